// ConstrainedDelaunay2 against brute-force exact checks: every sign from the GMP rational
// oracle, the covered area compared exactly with the convex hull's.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dt_triangulation_checks.h"

namespace certimesh::testing {
namespace {

using generators::DelaunayError;

// A Delaunay triangulation of conv(points): positive triangles, no overlap, area = hull area,
// every vertex used, every edge locally Delaunay.
void expect_delaunay_of_hull(const std::vector<Point2>& points, const std::vector<Triangle>& tris) {
  const TriangulationFindings f = check_triangulation(points, tris);
  EXPECT_EQ(f.non_positive, 0u);
  EXPECT_EQ(f.repeated_edges, 0u);
  EXPECT_EQ(f.non_delaunay_edges, 0u);
  EXPECT_TRUE(f.twice_area == twice_hull_area(points)) << "area " << f.twice_area.get_d() << " hull "
                                                       << twice_hull_area(points).get_d();
  std::vector<bool> used(points.size(), false);
  for (const Triangle& t : tris)
    for (auto v : t) used[v] = true;
  EXPECT_EQ(std::count(used.begin(), used.end(), false), 0);
}

TEST(dt_delaunay, UniformRandomPointsAreDelaunayAndCoverTheHull) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto points = uniform_points(3000, seed);
    expect_delaunay_of_hull(points, ConstrainedDelaunay2(points).triangles());
  }
}

TEST(dt_delaunay, IntegerGridIsCorrectAndOrderIndependent) {
  const int side = sanitizer_slowdown > 1 ? 60 : 200;
  const auto points = grid_points(side);
  const auto tris = ConstrainedDelaunay2(points).triangles();
  EXPECT_EQ(tris.size(), std::size_t(2 * (side - 1) * (side - 1)));
  expect_delaunay_of_hull(points, tris);
  // SoS makes the triangulation of the cocircular grid unique: any input order gives it.
  EXPECT_EQ(canonical_set(tris), canonical_set(triangles_of_shuffled(points, 7)));
}

// Integer points exactly on x^2 + y^2 = R^2, R = 5^4 13^2 (180 of them), and the centre.
std::vector<Point2> exactly_cocircular_points() {
  const std::int64_t r = 625 * 169;
  std::vector<Point2> p;
  for (std::int64_t x = -r; x <= r; ++x) {
    const std::int64_t y2 = r * r - x * x;
    auto y = static_cast<std::int64_t>(std::sqrt(double(y2)));
    while (y * y > y2) --y;
    while ((y + 1) * (y + 1) <= y2) ++y;
    if (y * y != y2) continue;
    p.push_back({double(x), double(y)});
    if (y != 0) p.push_back({double(x), double(-y)});
  }
  return p;
}

TEST(dt_delaunay, ExactlyCocircularPoints) {
  auto points = exactly_cocircular_points();
  ASSERT_EQ(points.size(), 180u);
  for (int with_centre = 0; with_centre < 2; ++with_centre) {
    if (with_centre) points.push_back({0.0, 0.0});
    const auto tris = ConstrainedDelaunay2(points).triangles();
    EXPECT_EQ(tris.size(), with_centre ? 180u : 178u);
    expect_delaunay_of_hull(points, tris);
    EXPECT_EQ(canonical_set(tris), canonical_set(triangles_of_shuffled(points, 11)));
    EXPECT_EQ(canonical_set(tris), canonical_set(triangles_of_shuffled(points, 12)));
  }
}

TEST(dt_delaunay, RoundedCirclePoints) {
  const std::size_t n = sanitizer_slowdown > 1 ? 10000 : 100000;
  std::vector<Point2> points;
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * double(i) / double(n);
    points.push_back({std::cos(a), std::sin(a)});
  }
  expect_delaunay_of_hull(points, ConstrainedDelaunay2(points).triangles());
}

TEST(dt_delaunay, PermutationInvarianceOnRandomInput) {
  const auto points = uniform_points(2000, 5);
  const auto reference = canonical_set(ConstrainedDelaunay2(points).triangles());
  for (std::uint64_t seed = 20; seed < 23; ++seed)
    EXPECT_EQ(reference, canonical_set(triangles_of_shuffled(points, seed)));
}

TEST(dt_delaunay, CollinearAndTinyInputsHaveNoTriangle) {
  std::vector<Point2> line;
  for (int i = 0; i < 50; ++i) line.push_back({0.5 * i, 3.0 - 0.25 * i});
  EXPECT_TRUE(ConstrainedDelaunay2(line).triangles().empty());
  EXPECT_TRUE(ConstrainedDelaunay2(std::vector<Point2>{}).triangles().empty());
  EXPECT_TRUE(ConstrainedDelaunay2(std::vector<Point2>{{0, 0}, {1, 1}}).triangles().empty());
  const ConstrainedDelaunay2 one(std::vector<Point2>{{0, 0}, {1, 0}, {0, 1}});
  EXPECT_EQ(one.triangles().size(), 1u);
}

TEST(dt_delaunay, CollinearPointsOnTheHullGiveNoFlatTriangle) {
  // A square with many points on its sides: SoS makes flat hull triangles, never reported.
  std::vector<Point2> p;
  for (int i = 0; i <= 20; ++i) p.push_back({double(i), 0}), p.push_back({double(i), 20}), p.push_back({0, double(i)}),
                                p.push_back({20, double(i)});
  std::sort(p.begin(), p.end(), [](auto a, auto b) { return a.x != b.x ? a.x < b.x : a.y < b.y; });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  p.push_back({7.5, 9.25});
  const ConstrainedDelaunay2 dt(p);
  expect_delaunay_of_hull(p, dt.triangles());
  for (std::uint32_t t = 0; t < dt.triangle_slot_count(); ++t)
    if (dt.is_live(t)) {
      const auto v = dt.vertices(t);
      EXPECT_GT(oracle_orient(p[v[0]], p[v[1]], p[v[2]]), 0);
    }
}

TEST(dt_delaunay, DuplicateAndNonFinitePointsAreRefusedByIndex) {
  std::vector<Point2> p = uniform_points(100, 3);
  p[61] = p[17];
  try {
    ConstrainedDelaunay2 dt(p);
    ADD_FAILURE() << "duplicate accepted";
  } catch (const DelaunayError& e) {
    EXPECT_NE(std::string(e.what()).find("points 17 and 61"), std::string::npos) << e.what();
  }
  std::vector<Point2> line{{0, 0}, {1, 1}, {2, 2}, {1, 1}};
  EXPECT_THROW(ConstrainedDelaunay2{line}, DelaunayError);
  p = uniform_points(10, 4);
  p[4].y = std::numeric_limits<double>::quiet_NaN();
  try {
    ConstrainedDelaunay2 dt(p);
    ADD_FAILURE() << "NaN accepted";
  } catch (const DelaunayError& e) {
    EXPECT_NE(std::string(e.what()).find("point 4 "), std::string::npos) << e.what();
  }
}

// Random star polygons (outer, and a hole inside): their edges as constraints.
struct PolygonDomain {
  std::vector<Point2> points;
  std::vector<Edge> constraints;
};

PolygonDomain polygons_with_points(std::uint64_t seed, std::size_t outer, std::size_t inner, std::size_t interior) {
  std::mt19937_64 rng(seed);
  PolygonDomain d;
  auto add_loop = [&](const std::vector<Point2>& loop) {
    const auto base = static_cast<std::uint32_t>(d.points.size());
    for (std::size_t i = 0; i < loop.size(); ++i) {
      d.points.push_back(loop[i]);
      d.constraints.push_back({base + std::uint32_t(i), base + std::uint32_t((i + 1) % loop.size())});
    }
  };
  add_loop(star_polygon(outer, {0, 0}, 0.6, 1.0, rng));
  add_loop(star_polygon(inner, {0, 0}, 0.1, 0.3, rng));
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (std::size_t i = 0; i < interior; ++i) d.points.push_back({u(rng), u(rng)});
  return d;
}

TEST(dt_constrained, PolygonEdgesAreRecoveredAndTheRestIsConstrainedDelaunay) {
  for (std::uint64_t seed = 1; seed <= 20; ++seed) {
    const PolygonDomain d = polygons_with_points(seed, 60, 25, 300);
    ConstrainedDelaunay2 cdt(d.points);
    for (const Edge& e : d.constraints) cdt.insert_constraint(e[0], e[1]);
    const auto tris = cdt.triangles();
    const TriangulationFindings f = check_triangulation(d.points, tris, d.constraints);
    EXPECT_EQ(f.non_positive, 0u);
    EXPECT_EQ(f.repeated_edges, 0u);
    EXPECT_EQ(f.missing_constraints, 0u);
    EXPECT_EQ(f.non_delaunay_edges, 0u);
    EXPECT_TRUE(f.twice_area == twice_hull_area(d.points));
    // The constrained flags are the constraints, seen from both sides.
    std::set<Edge> flagged;
    for (std::uint32_t t = 0; t < cdt.triangle_slot_count(); ++t) {
      if (!cdt.is_live(t)) continue;
      const auto v = cdt.vertices(t);
      for (int i = 0; i < 3; ++i)
        if (cdt.is_constrained(t, i)) flagged.insert({std::min(v[(i + 1) % 3], v[(i + 2) % 3]), std::max(v[(i + 1) % 3], v[(i + 2) % 3])});
    }
    std::set<Edge> expected;
    for (const Edge& e : d.constraints) expected.insert({std::min(e[0], e[1]), std::max(e[0], e[1])});
    EXPECT_EQ(flagged, expected) << "seed " << seed;
  }
}

TEST(dt_constrained, ClassifyFindsTheAnnulusAndItsArea) {
  const PolygonDomain d = polygons_with_points(5, 40, 15, 0);
  ConstrainedDelaunay2 cdt(d.points);
  for (const Edge& e : d.constraints) cdt.insert_constraint(e[0], e[1]);
  const std::vector<Point2> holes{{0.0, 0.0}};
  const std::vector<generators::RegionSeed> regions{{{0.0, 0.45}, 7}};
  const auto labels = cdt.classify(holes, regions);
  mpq_class inside = 0;
  for (std::uint32_t t = 0; t < cdt.triangle_slot_count(); ++t) {
    if (!cdt.is_live(t)) {
      EXPECT_EQ(labels[t], -1);
      continue;
    }
    if (labels[t] < 0) continue;
    EXPECT_EQ(labels[t], 7);
    const auto v = cdt.vertices(t);
    inside += twice_area(d.points[v[0]], d.points[v[1]], d.points[v[2]]);
  }
  // The annulus: outer polygon minus inner polygon, exactly.
  auto polygon_area = [&](std::size_t first, std::size_t count) {
    mpq_class a = 0;
    for (std::size_t i = 0; i < count; ++i) {
      const Point2 &p = d.points[first + i], &q = d.points[first + (i + 1) % count];
      a += mpq_class(p.x) * mpq_class(q.y) - mpq_class(p.y) * mpq_class(q.x);
    }
    return a;
  };
  EXPECT_TRUE(inside == polygon_area(0, 40) - polygon_area(40, 15));
}

TEST(dt_constrained, CrossingConstraintAndVertexOnConstraintAreRefused) {
  const std::vector<Point2> p{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}, {1, 2.5}};
  ConstrainedDelaunay2 cdt(p);
  try {
    cdt.insert_constraint(0, 2);  // through vertex 4 (2 2)
    ADD_FAILURE() << "vertex on constraint accepted";
  } catch (const DelaunayError& e) {
    EXPECT_NE(std::string(e.what()).find("point 4"), std::string::npos) << e.what();
  }
  cdt.insert_constraint(1, 5);
  try {
    cdt.insert_constraint(4, 0);  // (2 2)-(0 0) meets (4 0)-(1 2.5) at x = y = 20/11
    ADD_FAILURE() << "crossing constraint accepted";
  } catch (const DelaunayError& e) {
    const std::string what = e.what();
    EXPECT_TRUE(what.find("crosses constraint 1-5") != std::string::npos ||
                what.find("crosses constraint 5-1") != std::string::npos) << what;
  }
}

TEST(dt_constrained, InsertPointKeepsTheConstrainedDelaunayProperty) {
  const PolygonDomain d = polygons_with_points(9, 50, 20, 50);
  ConstrainedDelaunay2 cdt(d.points);
  for (const Edge& e : d.constraints) cdt.insert_constraint(e[0], e[1]);
  std::vector<Point2> all = d.points;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::size_t inserted = 0;
  for (int i = 0; i < 500; ++i) {
    const Point2 q{u(rng), u(rng)};
    const auto v = cdt.insert_point(q);
    if (v == ConstrainedDelaunay2::none) continue;
    EXPECT_EQ(v, all.size());
    all.push_back(q);
    ++inserted;
  }
  EXPECT_GT(inserted, 100u);
  const TriangulationFindings f = check_triangulation(all, cdt.triangles(), d.constraints);
  EXPECT_EQ(f.non_positive, 0u);
  EXPECT_EQ(f.repeated_edges, 0u);
  EXPECT_EQ(f.missing_constraints, 0u);
  EXPECT_EQ(f.non_delaunay_edges, 0u);
  EXPECT_TRUE(f.twice_area == twice_hull_area(all));
  // Outside the hull and on a vertex: nothing inserted.
  EXPECT_EQ(cdt.insert_point({5.0, 5.0}), ConstrainedDelaunay2::none);
  EXPECT_EQ(cdt.insert_point(all[3]), ConstrainedDelaunay2::none);
}

}  // namespace
}  // namespace certimesh::testing
