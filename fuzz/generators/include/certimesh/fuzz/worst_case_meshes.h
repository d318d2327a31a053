// Valid meshes shaped to attain the certificate's worst cases (design decision 9, issue 12):
// boundary facets whose bounding boxes all overlap, a vertex or an edge in tens of thousands
// of elements, many hole points, deeply nested boundary components. Built from integer or
// exactly rounded coordinates; the tests confirm every element's sign with the rational
// oracle before use, and the benchmark (bench_certificate_worst) times them at 1e5..1e6.
#pragma once

#include <gmpxx.h>

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

}  // namespace certimesh::fuzz
