// ConstrainedDelaunay2::split_constraint, the step --min-angle splits segments with: a
// constrained edge split at a point that is only near it (the rounding of a point of it, here
// computed in plain double, a few ulps off) leaves a valid constrained Delaunay triangulation
// whose constraints are the two halves, or changes nothing and says so. Every check is the
// brute-force GMP oracle of dt_triangulation_checks.h: orientation, each directed edge once,
// the empty circle on every unconstrained interior edge, the constraints present, the exact
// area equal to the convex hull's.
#include <gtest/gtest.h>

#include <random>

#include "dt_triangulation_checks.h"

namespace certimesh::testing {
namespace {

struct Splitting {
  std::vector<Point2> points;
  std::vector<Edge> constraints;
};

// Splits random constraints `rounds` times at a + f (b - a), f in (0.2, 0.8), in double.
void split_randomly(ConstrainedDelaunay2& cdt, Splitting& s, int rounds, std::mt19937_64& rng, int& refused) {
  std::uniform_real_distribution<double> fraction(0.2, 0.8);
  for (int r = 0; r < rounds; ++r) {
    const std::size_t i = rng() % s.constraints.size();
    const auto [a, b] = s.constraints[i];
    const Point2 pa = s.points[a], pb = s.points[b];
    // As the refinement does, another fraction when the point does not fit (a chain of points
    // within ulps of a line has sliver triangles beside it, half the roundings miss them).
    auto v = ConstrainedDelaunay2::none;
    Point2 p;
    for (int attempt = 0; attempt < 16 && v == ConstrainedDelaunay2::none; ++attempt) {
      const double f = fraction(rng);
      p = {pa.x + f * (pb.x - pa.x), pa.y + f * (pb.y - pa.y)};
      const std::size_t before = cdt.vertex_count();
      v = cdt.split_constraint(a, b, p);
      if (v == ConstrainedDelaunay2::none) {
        ASSERT_EQ(cdt.vertex_count(), before);  // nothing changed
      }
    }
    if (v == ConstrainedDelaunay2::none) {
      ++refused;
      continue;
    }
    ASSERT_EQ(v, s.points.size());
    s.points.push_back(p);
    s.constraints[i] = {a, v};
    s.constraints.push_back({v, b});
  }
}

void expect_valid(const ConstrainedDelaunay2& cdt, const Splitting& s) {
  const TriangulationFindings f = check_triangulation(s.points, cdt.triangles(), s.constraints);
  EXPECT_EQ(f.non_positive, 0u);
  EXPECT_EQ(f.repeated_edges, 0u);
  EXPECT_EQ(f.non_delaunay_edges, 0u);
  EXPECT_EQ(f.missing_constraints, 0u);
  EXPECT_EQ(f.twice_area, twice_hull_area(s.points));
  for (const auto& [a, b] : s.constraints) {  // and they are the constrained ones
    const auto t = cdt.triangle_left_of(a, b) != ConstrainedDelaunay2::none ? cdt.triangle_left_of(a, b)
                                                                            : cdt.triangle_left_of(b, a);
    ASSERT_NE(t, ConstrainedDelaunay2::none);
    const auto v = cdt.vertices(t);
    int local = 0;
    while (v[static_cast<std::size_t>(local)] == a || v[static_cast<std::size_t>(local)] == b) ++local;
    EXPECT_TRUE(cdt.is_constrained(t, local));
  }
}

TEST(dt_split_constraint, RandomStarPolygonsWithInteriorPoints) {
  std::mt19937_64 rng(20261201);
  int refused = 0, splits = 0;
  for (int trial = 0; trial < 20 / sanitizer_slowdown + 2; ++trial) {
    Splitting s;
    s.points = star_polygon(12, {0.5, 0.5}, 0.2, 0.5, rng);
    const std::uint32_t n = static_cast<std::uint32_t>(s.points.size());
    for (std::uint32_t i = 0; i < n; ++i) s.constraints.push_back({i, (i + 1) % n});
    for (const Point2& q : uniform_points(30, rng())) s.points.push_back(q);
    ConstrainedDelaunay2 cdt(s.points);
    for (const auto& [a, b] : s.constraints) cdt.insert_constraint(a, b);
    split_randomly(cdt, s, 120, rng, refused);
    splits += 120;
    expect_valid(cdt, s);
  }
  EXPECT_LT(refused, splits / 20);  // a point within ulps of the edge nearly always fits
}

TEST(dt_split_constraint, HullEdgesExactlyOnTheLineAndJustOutside) {
  // The unit square's sides: exact points (the collinear hull); a sloped triangle's sides:
  // points a few ulps off the line, half of them outside the hull (the ghost side).
  for (const std::vector<Point2>& corners : {std::vector<Point2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}},
                                             std::vector<Point2>{{0, 0}, {1, 0.3}, {0.1, 0.9}}}) {
    std::mt19937_64 rng(7);
    Splitting s{corners, {}};
    const std::uint32_t n = static_cast<std::uint32_t>(corners.size());
    for (std::uint32_t i = 0; i < n; ++i) s.constraints.push_back({i, (i + 1) % n});
    ConstrainedDelaunay2 cdt(s.points);
    for (const auto& [a, b] : s.constraints) cdt.insert_constraint(a, b);
    int refused = 0;
    split_randomly(cdt, s, 200, rng, refused);
    expect_valid(cdt, s);
    EXPECT_LT(refused, 10);
  }
}

TEST(dt_split_constraint, RefusesWhatDoesNotFit) {
  Splitting s{{{0, 0}, {1, 0}, {0.5, 1}, {0.5, 1e-3}}, {{0, 1}, {1, 2}, {2, 0}}};
  ConstrainedDelaunay2 cdt(s.points);
  for (const auto& [a, b] : s.constraints) cdt.insert_constraint(a, b);
  EXPECT_EQ(cdt.split_constraint(0, 3, {0.25, 5e-4}), ConstrainedDelaunay2::none);   // not a constraint
  EXPECT_EQ(cdt.split_constraint(0, 1, {0.5, 2e-3}), ConstrainedDelaunay2::none);    // beyond vertex 3
  EXPECT_EQ(cdt.split_constraint(0, 1, {1.5, 0}), ConstrainedDelaunay2::none);       // on the line, not between
  EXPECT_EQ(cdt.split_constraint(0, 1, {1, 0}), ConstrainedDelaunay2::none);         // an end point
  EXPECT_EQ(cdt.vertex_count(), 4u);
  EXPECT_NE(cdt.split_constraint(0, 1, {0.5, 0}), ConstrainedDelaunay2::none);
}

}  // namespace
}  // namespace certimesh::testing
