#include "certimesh/fuzz/campaign/delaunay2d_target.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "certimesh/fuzz/campaign/case_seed.h"
#include "certimesh/fuzz/campaign/named_target.h"
#include "certimesh/fuzz/recipes.h"
#include "certimesh/generators/delaunay/delaunay_error.h"
#include "certimesh/generators/delaunay/point_set_2.h"
#include "payload_text.h"

namespace certimesh::fuzz::campaign {

namespace {

__extension__ typedef __int128 Int128;

struct IPoint {
  std::int64_t x = 0, y = 0;
  friend bool operator==(const IPoint&, const IPoint&) = default;
  friend auto operator<=>(const IPoint&, const IPoint&) = default;
};

constexpr std::int64_t kMaxCoordinate = std::int64_t{1} << 16;
constexpr std::size_t kMaxPoints = 24;

// ---- The oracle: exact signs on the integers (|coordinates| <= 2^16, so every product fits).

Int128 orient(const IPoint& a, const IPoint& b, const IPoint& c) {
  return Int128{b.x - a.x} * (c.y - a.y) - Int128{b.y - a.y} * (c.x - a.x);
}

// > 0 when d is strictly inside the circle through the counterclockwise a, b, c.
Int128 incircle(const IPoint& a, const IPoint& b, const IPoint& c, const IPoint& d) {
  const Int128 adx = a.x - d.x, ady = a.y - d.y, bdx = b.x - d.x, bdy = b.y - d.y, cdx = c.x - d.x, cdy = c.y - d.y;
  const Int128 al = adx * adx + ady * ady, bl = bdx * bdx + bdy * bdy, cl = cdx * cdx + cdy * cdy;
  return al * (bdx * cdy - bdy * cdx) - bl * (adx * cdy - ady * cdx) + cl * (adx * bdy - ady * bdx);
}

// Twice the convex hull's area (Andrew's monotone chain).
Int128 twice_hull_area(std::vector<IPoint> p) {
  std::sort(p.begin(), p.end());
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return 0;
  std::vector<IPoint> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && orient(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && orient(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  Int128 area = 0;
  for (std::size_t i = 0; i + 1 < k; ++i) area += Int128{h[i].x} * h[i + 1].y - Int128{h[i + 1].x} * h[i].y;
  return area;
}

// ---- Point sets.

std::vector<IPoint> lattice_circle(std::int64_t r) {
  std::vector<IPoint> out;
  for (std::int64_t x = -r; x <= r; ++x)
    for (std::int64_t y = -r; y <= r; ++y)
      if (x * x + y * y == r * r) out.push_back({x, y});
  return out;
}

void keep_some(SplitMixSource& s, std::vector<IPoint>& p) {
  for (std::size_t i = p.size(); i > 1; --i) std::swap(p[i - 1], p[s.below(i)]);
  const std::size_t lo = std::min<std::size_t>(3, p.size());
  p.resize(std::min(kMaxPoints, lo + static_cast<std::size_t>(s.below(p.size() - lo + 1))));
}

std::vector<IPoint> draw_points(SplitMixSource& s) {
  std::vector<IPoint> p;
  switch (s.below(8)) {
    case 0: case 1: {  // a grid, or a sheared one: collinear and cocircular everywhere
      const std::int64_t a = 2 + static_cast<std::int64_t>(s.below(5)), b = 2 + static_cast<std::int64_t>(s.below(5));
      const std::int64_t shear = s.below(2) ? draw_int(s, -2, 2) : 0, step = 1 + static_cast<std::int64_t>(s.below(3));
      for (std::int64_t i = 0; i < a; ++i)
        for (std::int64_t j = 0; j < b; ++j) p.push_back({step * i + shear * j, step * j});
      keep_some(s, p);
      break;
    }
    case 2: {
      static constexpr std::int64_t radii[] = {5, 25, 65};
      p = lattice_circle(radii[s.below(3)]);
      keep_some(s, p);
      if (s.below(2)) p.push_back({0, 0});
      break;
    }
    case 3: case 4: {
      static constexpr std::int64_t ranges[] = {2, 10, 1000, kMaxCoordinate};
      const std::int64_t r = ranges[s.below(4)];
      std::set<IPoint> seen;
      for (std::size_t n = 3 + s.below(kMaxPoints - 2); p.size() < n && seen.size() < 200;) {
        const IPoint q{draw_int(s, -r, r), draw_int(s, -r, r)};
        if (seen.insert(q).second) p.push_back(q);
      }
      break;
    }
    case 5: {  // all on one line: refused
      const IPoint d{draw_int(s, -3, 3), draw_int(s, -3, 3)};
      for (std::int64_t t = 0, n = 2 + static_cast<std::int64_t>(s.below(6)); t < n; ++t) p.push_back({d.x * t, d.y * t});
      break;
    }
    case 6: {  // a repeated point: refused
      for (std::size_t n = 3 + s.below(6); p.size() < n;) p.push_back({draw_int(s, -4, 4), draw_int(s, -4, 4)});
      p.push_back(p[s.below(p.size())]);
      break;
    }
    default:  // fewer than three points
      for (std::size_t n = s.below(3); p.size() < n;) p.push_back({draw_int(s, -4, 4), draw_int(s, -4, 4)});
      break;
  }
  return p;
}

int draw_exponent(SplitMixSource& s) {
  switch (s.below(4)) {
    case 0: return 0;
    case 1: return static_cast<int>(draw_int(s, -8, 8));
    case 2: return static_cast<int>(draw_int(s, 990, 1006));  // near overflow
    default: return static_cast<int>(draw_int(s, -1074, -1040));  // subnormal
  }
}

io::MeshData as_mesh_data(const std::vector<IPoint>& p, int k) {
  io::MeshData m;
  m.dimension = 2;
  for (const IPoint& q : p) {
    m.coordinates.push_back(std::ldexp(static_cast<double>(q.x), k));
    m.coordinates.push_back(std::ldexp(static_cast<double>(q.y), k));
  }
  return m;
}

// ---- The check.

// The triangles as a set, each starting at its least vertex: the order of the list and where
// a triangle starts are not the triangulation (and they do change with the scale: the three
// points (-5,7) (-1,1) (-2,7) give "2 0 1" unscaled and "0 1 2" times 2^-1041).
std::set<std::array<io::Index, 3>> triangle_set(const io::MeshData& m) {
  std::set<std::array<io::Index, 3>> out;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    std::array<io::Index, 3> v{m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]};
    std::rotate(v.begin(), std::min_element(v.begin(), v.end()), v.end());
    out.insert(v);
  }
  return out;
}

std::optional<Finding> check(const DelaunayKernel& kernel, const std::vector<IPoint>& p, int k) {
  std::string payload = std::to_string(k);
  for (const IPoint& q : p) {
    payload.push_back(' ');
    payload += std::to_string(q.x);
    payload.push_back(' ');
    payload += std::to_string(q.y);
  }
  const auto found = [&](const std::string& what) { return Finding{"delaunay2d: " + what, payload}; };
  const std::size_t n = p.size();
  bool repeated = false, flat = true;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < i; ++j) {
      repeated = repeated || p[i] == p[j];
      for (std::size_t l = 0; l < j; ++l) flat = flat && orient(p[l], p[j], p[i]) == 0;
    }
  const bool refusal = repeated || n < 3 || flat;
  const io::MeshData in = as_mesh_data(p, k);
  io::MeshData out;
  try {
    out = kernel.triangulate(in);
  } catch (const generators::DelaunayError& e) {
    if (refusal) return std::nullopt;
    return found(std::string("refused a valid point set: ") + e.what());
  } catch (const std::exception& e) {
    return found(std::string("an exception other than DelaunayError: ") + e.what());
  }
  if (refusal) return found(repeated ? "accepted a repeated point" : "accepted fewer than 3 points or points on one line");
  if (out.dimension != 2 || out.coordinates.size() != in.coordinates.size() ||
      !std::equal(in.coordinates.begin(), in.coordinates.end(), out.coordinates.begin(),
                  [](double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }))
    return found("the output's points are not the input's, bit for bit");
  if (out.triangles.size() % 3 != 0 || !out.tetrahedra.empty()) return found("the output is not a list of triangles");
  std::set<std::pair<std::size_t, std::size_t>> directed;
  std::vector<bool> used(n, false);
  Int128 area = 0;
  for (std::size_t t = 0; t < out.triangle_count(); ++t) {
    const std::size_t v[3] = {out.triangles[3 * t], out.triangles[3 * t + 1], out.triangles[3 * t + 2]};
    for (std::size_t i = 0; i < 3; ++i)
      if (v[i] >= n) return found("triangle " + std::to_string(t) + " names a vertex that does not exist");
    const Int128 o = orient(p[v[0]], p[v[1]], p[v[2]]);
    if (o <= 0) return found("triangle " + std::to_string(t) + (o == 0 ? " is flat" : " is clockwise"));
    area += o;
    for (std::size_t i = 0; i < 3; ++i) {
      used[v[i]] = true;
      if (!directed.emplace(v[i], v[(i + 1) % 3]).second) return found("a directed edge is used twice (an overlap)");
    }
    for (std::size_t q = 0; q < n; ++q)
      if (q != v[0] && q != v[1] && q != v[2] && incircle(p[v[0]], p[v[1]], p[v[2]], p[q]) > 0)
        return found("point " + std::to_string(q) + " is strictly inside triangle " + std::to_string(t) + "'s circumcircle");
  }
  if (std::find(used.begin(), used.end(), false) != used.end()) return found("a point is no triangle's vertex");
  for (const auto& [a, b] : directed)
    if (!directed.contains({b, a}))
      for (std::size_t q = 0; q < n; ++q)
        if (orient(p[a], p[b], p[q]) < 0) return found("an edge without a twin is not on the convex hull");
  if (area != twice_hull_area(p)) return found("the triangles' areas do not sum to the convex hull's");
  if (k != 0) {
    const io::MeshData unscaled = kernel.triangulate(as_mesh_data(p, 0));
    if (triangle_set(unscaled) != triangle_set(out)) return found("scaling the points by 2^k changes the triangles");
  }
  return std::nullopt;
}

class Delaunay2dTarget final : public KernelTarget<DelaunayKernel> {
 public:
  using KernelTarget::KernelTarget;
  std::optional<Finding> run_case(std::uint64_t seed) const override {
    SplitMixSource s(seed);
    const std::vector<IPoint> p = draw_points(s);
    return check(kernel_, p, draw_exponent(s));
  }
  std::optional<Finding> replay(std::string_view payload) const override {
    PayloadReader in(payload);
    const auto integer = [&](std::int64_t lo, std::int64_t hi) {
      const double v = in.next_double();
      if (!(v >= static_cast<double>(lo) && v <= static_cast<double>(hi)) || v != std::floor(v))
        throw MalformedPayload("expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
      return static_cast<std::int64_t>(v);
    };
    const int k = static_cast<int>(integer(-1074, 1006));
    std::vector<IPoint> p;
    while (!in.at_end()) {
      const std::int64_t x = integer(-kMaxCoordinate, kMaxCoordinate);
      p.push_back({x, integer(-kMaxCoordinate, kMaxCoordinate)});
    }
    return check(kernel_, p, k);
  }

};

}  // namespace

DelaunayKernel certimesh_delaunay_kernel() { return {generators::delaunay_of_points}; }

std::unique_ptr<Target> make_delaunay2d_target(const DelaunayKernel& kernel, std::string name, std::string description) {
  return std::make_unique<Delaunay2dTarget>(kernel, std::move(name), std::move(description));
}

std::unique_ptr<Target> make_delaunay2d_target() {
  return make_delaunay2d_target(certimesh_delaunay_kernel(), "delaunay2d",
                                "delaunay_of_points on grids, lattice circles and random integers scaled by 2^-1074..2^1006: "
                                "empty circles, exact hull cover and refusals against a brute-force integer oracle");
}

}  // namespace certimesh::fuzz::campaign
