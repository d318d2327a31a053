// ConstrainedDelaunay2 against CGAL (the independent oracle): the same triangles as
// Delaunay_triangulation_2 on generic random points (the Delaunay triangulation is unique
// there), the same triangles as Constrained_Delaunay_triangulation_2 with random polygon
// constraints, and the same hull edges on degenerate input (grid, points on a circle).
#include <gtest/gtest.h>

#include "cgal_reference.h"
#include "dt_triangulation_checks.h"

namespace certimesh::testing {
namespace {

std::vector<cgal_reference::Point2> reference_points(const std::vector<Point2>& points) {
  std::vector<cgal_reference::Point2> out;
  for (const Point2& p : points) out.push_back({p.x, p.y});
  return out;
}

// CGAL's finite triangles, by input index.
std::set<Triangle> cgal_triangles(const cgal_reference::Triangulation2& t) {
  std::set<Triangle> out;
  for (const auto& f : t.triangles) out.insert(canonical({t.input[f[0]], t.input[f[1]], t.input[f[2]]}));
  return out;
}

// The edges between consecutive vertices around CGAL's infinite vertex, by input index.
std::set<Edge> cgal_hull_edges(const cgal_reference::Triangulation2& t) {
  std::set<Edge> out;
  for (std::size_t i = 0; i < t.hull.size(); ++i) {
    const auto a = t.input[t.hull[i]], b = t.input[t.hull[(i + 1) % t.hull.size()]];
    out.insert({std::min(a, b), std::max(a, b)});
  }
  return out;
}

std::set<Edge> hull_edges(const std::vector<Triangle>& tris) {
  std::map<Edge, int> count;
  for (const Triangle& t : tris)
    for (int i = 0; i < 3; ++i) {
      const auto a = t[(i + 1) % 3], b = t[(i + 2) % 3];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::set<Edge> out;
  for (const auto& [e, n] : count)
    if (n == 1) out.insert(e);
  return out;
}

TEST(dt_cgal, SameTrianglesAsCgalOnRandomPoints) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto points = uniform_points(20000 / std::size_t(sanitizer_slowdown), seed);
    const auto cgal = cgal_reference::delaunay_2(reference_points(points));
    EXPECT_EQ(canonical_set(ConstrainedDelaunay2(points).triangles()), cgal_triangles(cgal)) << "seed " << seed;
  }
}

TEST(dt_cgal, SameTrianglesAsCgalConstrainedDelaunay) {
  std::mt19937_64 rng(4);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<Point2> points = star_polygon(80, {0, 0}, 0.5, 1.0, rng);
    const auto inner = star_polygon(30, {0.05, 0}, 0.1, 0.3, rng);
    points.insert(points.end(), inner.begin(), inner.end());
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 400; ++i) points.push_back({u(rng), u(rng)});
    std::vector<Edge> constraints;
    for (std::uint32_t i = 0; i < 80; ++i) constraints.push_back({i, (i + 1) % 80});
    for (std::uint32_t i = 0; i < 30; ++i) constraints.push_back({80 + i, 80 + (i + 1) % 30});

    ConstrainedDelaunay2 mine(points);
    for (const Edge& e : constraints) mine.insert_constraint(e[0], e[1]);
    std::set<Triangle> cgal;
    for (const auto& t : cgal_reference::constrained_delaunay_2(reference_points(points), constraints))
      cgal.insert(canonical(t));
    EXPECT_EQ(canonical_set(mine.triangles()), cgal) << "trial " << trial;
  }
}

TEST(dt_cgal, SameHullAsCgalOnGridAndCircle) {
  std::vector<std::vector<Point2>> inputs{grid_points(sanitizer_slowdown > 1 ? 40 : 120)};
  std::vector<Point2> circle;
  const std::size_t n = 100000 / std::size_t(sanitizer_slowdown);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * double(i) / double(n);
    circle.push_back({std::cos(a), std::sin(a)});
  }
  inputs.push_back(circle);
  for (const auto& points : inputs) {
    const auto cgal = cgal_reference::delaunay_2(reference_points(points));
    const auto mine = ConstrainedDelaunay2(points).triangles();
    EXPECT_EQ(hull_edges(mine), cgal_hull_edges(cgal));
    EXPECT_EQ(mine.size(), cgal.triangles.size());
  }
}

}  // namespace
}  // namespace certimesh::testing
