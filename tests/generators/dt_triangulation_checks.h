// Brute-force, independent checks of a (constrained) Delaunay triangulation for the dt_*
// tests: every sign from the GMP rational oracle (fuzz/oracles), areas summed in exact
// rationals, the convex hull by a monotone chain of its own.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "certimesh/generators/delaunay/constrained_delaunay_2.h"
#include "rational_oracle.h"

namespace certimesh::testing {

using generators::ConstrainedDelaunay2;
using predicates::Point2;
using Triangle = std::array<std::uint32_t, 3>;
using Edge = std::array<std::uint32_t, 2>;

inline int oracle_orient(const Point2& a, const Point2& b, const Point2& c) {
  return oracle_orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

/// Positive when d is inside the circle through the counterclockwise a, b, c.
inline int oracle_incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  return oracle_sign<2, 4>({{{a.x, a.y}, {b.x, b.y}, {c.x, c.y}, {d.x, d.y}}}, true);
}

/// Rotated so the smallest id comes first (orientation kept): a canonical form for sets.
inline Triangle canonical(Triangle t) {
  while (t[0] > t[1] || t[0] > t[2]) t = {t[1], t[2], t[0]};
  return t;
}

inline std::set<Triangle> canonical_set(const std::vector<Triangle>& tris) {
  std::set<Triangle> out;
  for (const auto& t : tris) out.insert(canonical(t));
  return out;
}

/// Twice the signed area of the convex hull, exactly (hull by Andrew's monotone chain with
/// oracle signs).
inline mpq_class twice_hull_area(std::vector<Point2> p) {
  std::sort(p.begin(), p.end(), [](const Point2& a, const Point2& b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  std::vector<Point2> hull;
  for (int pass = 0; pass < 2; ++pass) {
    const std::size_t base = hull.size();
    for (const Point2& q : p) {
      while (hull.size() >= base + 2 && oracle_orient(hull[hull.size() - 2], hull.back(), q) <= 0) hull.pop_back();
      hull.push_back(q);
    }
    hull.pop_back();
    std::reverse(p.begin(), p.end());
  }
  mpq_class area = 0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const Point2 &a = hull[i], &b = hull[(i + 1) % hull.size()];
    area += mpq_class(a.x) * mpq_class(b.y) - mpq_class(a.y) * mpq_class(b.x);
  }
  return area;
}

inline mpq_class twice_area(const Point2& a, const Point2& b, const Point2& c) {
  return (mpq_class(b.x) - mpq_class(a.x)) * (mpq_class(c.y) - mpq_class(a.y)) -
         (mpq_class(b.y) - mpq_class(a.y)) * (mpq_class(c.x) - mpq_class(a.x));
}

struct TriangulationFindings {
  std::size_t non_positive = 0;        // triangles not strictly counterclockwise
  std::size_t repeated_edges = 0;      // a directed edge in two triangles
  std::size_t non_delaunay_edges = 0;  // unconstrained interior edges failing the empty circle
  std::size_t missing_constraints = 0;
  mpq_class twice_area = 0;            // of all triangles
};

/// Checks `tris` over `points` with the oracle. An interior edge not in `constraints`
/// (undirected) must be locally Delaunay: the opposite apex not strictly inside the circle.
inline TriangulationFindings check_triangulation(const std::vector<Point2>& points, const std::vector<Triangle>& tris,
                                                 const std::vector<Edge>& constraints = {}) {
  TriangulationFindings f;
  std::map<Edge, std::uint32_t> apex_of;  // directed edge -> apex
  for (const Triangle& t : tris) {
    if (oracle_orient(points[t[0]], points[t[1]], points[t[2]]) <= 0) ++f.non_positive;
    f.twice_area += twice_area(points[t[0]], points[t[1]], points[t[2]]);
    for (int i = 0; i < 3; ++i)
      if (!apex_of.emplace(Edge{t[(i + 1) % 3], t[(i + 2) % 3]}, t[i]).second) ++f.repeated_edges;
  }
  std::set<Edge> constrained;
  for (const Edge& e : constraints) {
    constrained.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
    if (!apex_of.count(e) && !apex_of.count(Edge{e[1], e[0]})) ++f.missing_constraints;
  }
  for (const auto& [e, apex] : apex_of) {
    const auto twin = apex_of.find(Edge{e[1], e[0]});
    if (twin == apex_of.end() || e[0] > e[1]) continue;
    if (constrained.count({std::min(e[0], e[1]), std::max(e[0], e[1])})) continue;
    if (oracle_incircle(points[apex], points[e[0]], points[e[1]], points[twin->second]) > 0) ++f.non_delaunay_edges;
  }
  return f;
}

/// The triangles of a triangulation built from `points` shuffled by `seed`, in the original ids.
inline std::vector<Triangle> triangles_of_shuffled(const std::vector<Point2>& points, std::uint64_t seed) {
  std::vector<std::uint32_t> perm(points.size());
  for (std::uint32_t i = 0; i < perm.size(); ++i) perm[i] = i;
  std::mt19937_64 rng(seed);
  std::shuffle(perm.begin(), perm.end(), rng);
  std::vector<Point2> shuffled(points.size());
  for (std::size_t i = 0; i < perm.size(); ++i) shuffled[i] = points[perm[i]];
  std::vector<Triangle> out;
  for (Triangle t : ConstrainedDelaunay2(shuffled).triangles()) out.push_back({perm[t[0]], perm[t[1]], perm[t[2]]});
  return out;
}

inline std::vector<Point2> uniform_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point2> p(n);
  for (auto& q : p) q.x = u(rng), q.y = u(rng);
  return p;
}

inline std::vector<Point2> grid_points(int side) {
  std::vector<Point2> p;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) p.push_back({double(i), double(j)});
  return p;
}

/// A random star-shaped simple polygon around c: `n` vertices at increasing angles.
inline std::vector<Point2> star_polygon(std::size_t n, Point2 c, double r0, double r1, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<double> angle(n);
  for (auto& a : angle) a = 6.283185307179586 * u(rng);
  std::sort(angle.begin(), angle.end());
  std::vector<Point2> p;
  for (double a : angle) {
    const double r = r0 + (r1 - r0) * u(rng);
    p.push_back({c.x + r * std::cos(a), c.y + r * std::sin(a)});
  }
  return p;
}

#if defined(__SANITIZE_ADDRESS__)
inline constexpr int sanitizer_slowdown = 8;
#else
inline constexpr int sanitizer_slowdown = 1;
#endif

}  // namespace certimesh::testing
