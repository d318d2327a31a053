// Valid meshes shaped to attain the certificate's worst cases (design decision 9, issue 12):
// boundary facets whose bounding boxes all overlap, a vertex or an edge in tens of thousands
// of elements, many hole points, deeply nested boundary components. Built from integer or
// exactly rounded coordinates; the tests confirm every element's sign with the rational
// oracle before use, and the benchmark (bench_certificate_worst) times them at 1e5..1e6.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "certimesh/io/mesh_data.h"

namespace certimesh::fuzz {

namespace detail {
/// n points on the unit circle, at angles 2 pi i / n, appended to m (with z = 0 in 3D).
inline void append_circle(io::MeshData& m, int n) {
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i) {
    m.coordinates.push_back(std::cos(2 * pi * i / n));
    m.coordinates.push_back(std::sin(2 * pi * i / n));
    if (m.dimension == 3) m.coordinates.push_back(0);
  }
}
/// The double nearest to q, ties to even: a point "rounded from an exact point" (decision 2).
inline double nearest_double(const mpq_class& q) {
  const double toward_zero = q.get_d();
  const double away = std::nextafter(toward_zero, q > 0 ? INFINITY : -INFINITY);
  const mpq_class near_error = abs(q - toward_zero), far_error = abs(q - away);
  if (near_error != far_error) return near_error < far_error ? toward_zero : away;
  return (std::bit_cast<std::uint64_t>(toward_zero) & 1) == 0 ? toward_zero : away;
}
}  // namespace detail

/// A star of k spikes (notches at radius 1/2, tips at radius 1) whose 2k segments each carry
/// n - 1 Steiner points, each the double nearest to the exact point at j/n along its segment:
/// almost every boundary vertex is off its segment's line by a fraction of an ulp, so each one
/// needs the exact rounding-box test, and the long thin spikes' boxes overlap widely. Each spike
/// is a ladder of 2n - 1 triangles, the core a fan from the origin: 2nk triangles. `domain` gets
/// the star polygon (counterclockwise); mesh vertex 0 is the origin, 1..2k the star's corners.
inline io::MeshData spiked_star_2d(int k, int n, io::MeshData& domain) {
  const double pi = std::acos(-1.0);
  domain = io::MeshData{};
  domain.dimension = 2;
  for (int i = 0; i < 2 * k; ++i) {  // notch i at 2i, tip i at 2i + 1
    const double r = i % 2 == 0 ? 0.5 : 1.0, a = pi * i / k;
    domain.coordinates.push_back(r * std::cos(a));
    domain.coordinates.push_back(r * std::sin(a));
    domain.segments.push_back(static_cast<io::Index>(i));
    domain.segments.push_back(static_cast<io::Index>((i + 1) % (2 * k)));
  }
  io::MeshData m;
  m.dimension = 2;
  m.coordinates = {0.0, 0.0};
  m.coordinates.insert(m.coordinates.end(), domain.coordinates.begin(), domain.coordinates.end());
  auto corner = [&](int i) { return static_cast<io::Index>(1 + (i % (2 * k))); };
  auto steiner = [&](io::Index from, io::Index to, int j) {  // nearest to from + (to - from) j / n
    for (int c = 0; c < 2; ++c) {
      const mpq_class a = m.coordinates[2 * from + c], b = m.coordinates[2 * to + c];
      mpq_class t(j, n);
      t.canonicalize();
      m.coordinates.push_back(detail::nearest_double(a + (b - a) * t));
    }
    return static_cast<io::Index>(m.coordinates.size() / 2 - 1);
  };
  auto triangle = [&](io::Index a, io::Index b, io::Index c) { m.triangles.insert(m.triangles.end(), {a, b, c}); };
  for (int i = 0; i < k; ++i) {
    const io::Index notch = corner(2 * i), tip = corner(2 * i + 1), next = corner(2 * i + 2);
    triangle(0, notch, next);
    std::vector<io::Index> left{notch}, right{next};  // rung j: left[j] on notch-tip, right[j] on next-tip
    for (int j = 1; j < n; ++j) left.push_back(steiner(notch, tip, j)), right.push_back(steiner(next, tip, j));
    for (int j = 0; j + 1 < n; ++j) triangle(left[j], left[j + 1], right[j + 1]), triangle(left[j], right[j + 1], right[j]);
    triangle(left[n - 1], tip, right[n - 1]);
  }
  return m;
}

/// A star polygon of 2k sides around the origin (tips at radius 1, notches at radius 1/64),
/// fan-triangulated from the centre: 2k triangles, 2k boundary edges, most of whose boxes
/// overlap near the centre. Vertex 0 is the centre; the polygon runs counterclockwise.
inline io::MeshData star_fan_2d(int k) {
  io::MeshData m;
  m.dimension = 2;
  m.coordinates = {0.0, 0.0};
  const double pi = std::acos(-1.0);
  for (int i = 0; i < 2 * k; ++i) {
    const double r = i % 2 == 0 ? 1.0 : 1.0 / 64, a = pi * i / k;
    m.coordinates.push_back(r * std::cos(a));
    m.coordinates.push_back(r * std::sin(a));
  }
  for (int i = 0; i < 2 * k; ++i) {
    m.triangles.push_back(0);
    m.triangles.push_back(static_cast<io::Index>(1 + i));
    m.triangles.push_back(static_cast<io::Index>(1 + (i + 1) % (2 * k)));
  }
  return m;
}

/// k tetrahedra around the edge from S = (0,0,-1) to N = (0,0,1), their other vertices on the
/// unit circle of z = 0: the edge is in k tetrahedra, N and S in k boundary triangles each,
/// and every boundary box overlaps the others near the axis.
inline io::MeshData book_3d(int k) {
  io::MeshData m;
  m.dimension = 3;
  m.coordinates = {0, 0, -1, 0, 0, 1};
  detail::append_circle(m, k);
  for (int i = 0; i < k; ++i) {  // (S, N, r_i, r_i+1): positive for counterclockwise r
    const auto a = static_cast<io::Index>(2 + i), b = static_cast<io::Index>(2 + (i + 1) % k);
    for (io::Index v : {io::Index{0}, a, b, io::Index{1}}) m.tetrahedra.push_back(v);
  }
  return m;
}

/// An n x n grid (n odd) of unit squares (two triangles each) with every other square of every other
/// row and column left out: about n^2/4 square holes, each with its hole point in the domain
/// returned in `domain` (the outer square and every hole's four segments).
inline io::MeshData holey_grid_2d(int n, io::MeshData& domain) {
  io::MeshData m;
  m.dimension = 2;
  auto id = [n](int i, int j) { return static_cast<io::Index>(j * (n + 1) + i); };
  auto hole = [](int i, int j) { return i % 2 == 1 && j % 2 == 1; };
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.coordinates.insert(m.coordinates.end(), {double(i), double(j)});
  domain = io::MeshData{};
  domain.dimension = 2;
  domain.coordinates = m.coordinates;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const io::Index a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (!hole(i, j)) {
        m.triangles.insert(m.triangles.end(), {a, b, c, a, c, d});
        continue;
      }
      domain.segments.insert(domain.segments.end(), {a, b, b, c, c, d, d, a});
      domain.holes.insert(domain.holes.end(), {i + 0.5, j + 0.5});
    }
  for (int i = 0; i < n; ++i)
    domain.segments.insert(domain.segments.end(), {id(i, 0), id(i + 1, 0), id(n, i), id(n, i + 1),
                                                   id(i + 1, n), id(i, n), id(0, i + 1), id(0, i)});
  return m;  // the domain's unused grid points are fine: a domain vertex need not be on a segment
}

/// k nested square rings (ring r between the squares of half-width 2r+1 and 2r+2 around the
/// origin, 8 triangles each), separate components: every ring's boundary lies inside the boxes
/// of all the rings around it, the worst case of the winding-number pass.
inline io::MeshData nested_rings_2d(int k) {
  io::MeshData m;
  m.dimension = 2;
  const double corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int r = 0; r < k; ++r) {
    const auto first = static_cast<io::Index>(m.point_count());
    for (double s : {2.0 * r + 1, 2.0 * r + 2})
      for (const auto& c : corners) m.coordinates.insert(m.coordinates.end(), {s * c[0], s * c[1]});
    for (io::Index i = 0; i < 4; ++i) {  // inner i, i+1; outer i, i+1
      const io::Index a = first + i, b = first + (i + 1) % 4, c = first + 4 + i, d = first + 4 + (i + 1) % 4;
      m.triangles.insert(m.triangles.end(), {a, c, d, a, d, b});
    }
  }
  return m;
}

/// k triangles around the origin in every other wedge of angle pi/k (tips on the unit circle):
/// k parts pinched at one vertex (design decision 8), which is in 2k boundary edges; pairing
/// them must cost k log k (an angular sort), not k^2.
inline io::MeshData pinwheel_2d(int k) {
  io::MeshData m;
  m.dimension = 2;
  m.coordinates = {0.0, 0.0};
  detail::append_circle(m, 2 * k);
  for (int i = 0; i < k; ++i)
    m.triangles.insert(m.triangles.end(), {io::Index{0}, static_cast<io::Index>(1 + 2 * i), static_cast<io::Index>(2 + 2 * i)});
  return m;
}

/// book_3d with every other page left out: k tetrahedra around the edge S N in every other
/// wedge of 2k, so the edge is in 2k boundary triangles, paired by their order around it.
inline io::MeshData open_book_3d(int k) {
  io::MeshData m;
  m.dimension = 3;
  m.coordinates = {0, 0, -1, 0, 0, 1};
  detail::append_circle(m, 2 * k);
  for (int i = 0; i < k; ++i) {
    const auto a = static_cast<io::Index>(2 + 2 * i), b = static_cast<io::Index>(3 + 2 * i);
    for (io::Index v : {io::Index{0}, a, b, io::Index{1}}) m.tetrahedra.push_back(v);
  }
  return m;
}

/// A prism of height 1 over a star polygon of 2k corners (tips at radius 1, notches at 1/4)
/// with the domain as TetGen writes it: `domain` gets the 4k corners and 2k + 2 polygonal
/// facets (the bottom and top stars, one polygon of 2k corners each, and 2k side quads),
/// oriented outward. The mesh fans each star from its centre (mesh vertices 0 = (0,0,0) and
/// 1 = (0,0,1), inside the bottom and top facets, not domain vertices; then the bottom corners,
/// then the top ones) and splits each wedge prism into three tetrahedra, every shared quad
/// along the diagonal from its lower-numbered bottom vertex: 6k tetrahedra. The certificate
/// cuts each star facet into 2k - 2 triangles, most of them long, whose boxes overlap.
inline io::MeshData star_prism_3d(int k, io::MeshData& domain) {
  const double pi = std::acos(-1.0);
  const int n = 2 * k;
  io::MeshData m;
  m.dimension = 3;
  m.coordinates = {0, 0, 0, 0, 0, 1};
  for (int z = 0; z < 2; ++z)
    for (int i = 0; i < n; ++i) {
      const double r = i % 2 == 0 ? 1.0 : 0.25, a = pi * i / k;
      m.coordinates.insert(m.coordinates.end(), {r * std::cos(a), r * std::sin(a), double(z)});
    }
  domain = io::MeshData{};
  domain.dimension = 3;
  domain.coordinates.assign(m.coordinates.begin() + 6, m.coordinates.end());
  auto facet = [&](const std::vector<io::Index>& corners) {
    domain.facets.corners.insert(domain.facets.corners.end(), corners.begin(), corners.end());
    domain.facets.polygon_end.push_back(domain.facets.corners.size());
    domain.facets.facet_end.push_back(domain.facets.polygon_end.size());
    domain.facets.hole_end.push_back(0);
  };
  std::vector<io::Index> bottom, top;
  for (int i = 0; i < n; ++i) bottom.push_back(static_cast<io::Index>(n - 1 - i)), top.push_back(static_cast<io::Index>(n + i));
  facet(bottom);  // clockwise from above: outward is down
  facet(top);
  for (int i = 0; i < n; ++i) {
    const auto a = static_cast<io::Index>(i), b = static_cast<io::Index>((i + 1) % n);
    facet({a, b, static_cast<io::Index>(b + n), static_cast<io::Index>(a + n)});  // outward: right of a -> b
  }
  auto q = [&](io::Index v, int c) { return mpq_class(m.coordinates[3 * v + static_cast<std::size_t>(c)]); };
  auto tetrahedron = [&](io::Index a, io::Index b, io::Index c, io::Index d) {  // positive: swap c, d if not
    mpq_class e[3][3];
    for (int r = 0; r < 3; ++r) e[0][r] = q(b, r) - q(a, r), e[1][r] = q(c, r) - q(a, r), e[2][r] = q(d, r) - q(a, r);
    const mpq_class det = e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                          e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
    if (det < 0) std::swap(c, d);
    m.tetrahedra.insert(m.tetrahedra.end(), {a, b, c, d});
  };
  for (int i = 0; i < n; ++i) {
    // The wedge over (centre, corner i, corner i + 1); bottom ids 0, 2 + i, 2 + (i + 1) % n, each
    // with its top n further on (the centre's top is 1). Sorted bottom u < v < w, tops u' v' w':
    // (u v w w'), (u v v' w'), (u u' v' w'): each quad split from its lower bottom vertex.
    std::array<io::Index, 3> base{0, static_cast<io::Index>(2 + i), static_cast<io::Index>(2 + (i + 1) % n)};
    std::sort(base.begin(), base.end());
    auto up = [&](io::Index v) { return v == 0 ? io::Index{1} : static_cast<io::Index>(v + n); };
    const io::Index u = base[0], v = base[1], w = base[2];
    tetrahedron(u, v, w, up(w));
    tetrahedron(u, v, up(v), up(w));
    tetrahedron(u, up(u), up(v), up(w));
  }
  return m;
}

}  // namespace certimesh::fuzz
