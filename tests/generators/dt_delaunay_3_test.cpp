// Delaunay3 against exact checks (dt_delaunay_3_checks.h), on the shapes that break inexact
// or unperturbed tetrahedralizers: uniform points, points rounded from a sphere, an integer
// grid (eight cospherical points in every cell, every hull face a plane full of points),
// integer points exactly on a sphere; the same points in another order give the same
// tetrahedra (the perturbed tetrahedralization is unique), and so does every scaling by
// 2^k; bad input is refused, naming the points.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "certimesh/generators/delaunay/delaunay_3.h"
#include "certimesh/generators/delaunay/perturbed_predicates_3.h"
#include "dt_delaunay_3_checks.h"

namespace certimesh::testing {
namespace {

using generators::Delaunay3;
using generators::DelaunayError;

#if defined(__SANITIZE_ADDRESS__)
constexpr std::size_t uniform_count = 3000, sphere_count = 2000, grid_side = 8, scaled_count = 150;
constexpr int quintuples = 8000;
constexpr long sphere_k = 4;
#else
constexpr std::size_t uniform_count = 100000, sphere_count = 10000, grid_side = 20, scaled_count = 800;
constexpr int quintuples = 60000;
constexpr long sphere_k = 34;
#endif

std::vector<Tet> tetrahedra_of(const std::vector<P3>& p) {
  const Delaunay3 dt(p);
  std::vector<Tet> out;
  for (const auto& t : dt.tetrahedra()) out.push_back(t);
  EXPECT_EQ(out.size(), dt.tetrahedron_count());
  return out;
}

std::vector<P3> uniform(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<P3> p(n);
  for (auto& q : p) q = {u(rng), u(rng), u(rng)};
  return p;
}

std::vector<P3> rounded_sphere(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  std::vector<P3> p(n);
  for (auto& q : p) {
    const double x = g(rng), y = g(rng), z = g(rng), r = std::sqrt(x * x + y * y + z * z);
    q = {x / r, y / r, z / r};
  }
  return p;
}

std::vector<P3> grid(std::size_t side) {
  std::vector<P3> p;
  for (std::size_t i = 0; i < side; ++i)
    for (std::size_t j = 0; j < side; ++j)
      for (std::size_t k = 0; k < side; ++k) p.push_back({double(i), double(j), double(k)});
  return p;
}

// Every integer point with x^2 + y^2 + z^2 = r2.
std::vector<P3> integer_sphere(long r2) {
  std::vector<P3> p;
  const long r = static_cast<long>(std::sqrt(double(r2)));
  for (long x = -r; x <= r; ++x)
    for (long y = -r; y <= r; ++y) {
      const long rest = r2 - x * x - y * y;
      if (rest < 0) continue;
      const long z = std::lround(std::sqrt(double(rest)));
      if (z * z != rest) continue;
      p.push_back({double(x), double(y), double(z)});
      if (z != 0) p.push_back({double(x), double(y), double(-z)});
    }
  return p;
}

// The same tetrahedra for the points in a shuffled order (mapped back to the original ids).
void expect_order_independent(const std::vector<P3>& p, const std::vector<Tet>& tets, std::uint64_t seed) {
  std::vector<std::uint32_t> perm(p.size());
  std::iota(perm.begin(), perm.end(), 0u);
  std::shuffle(perm.begin(), perm.end(), std::mt19937_64(seed));
  std::vector<P3> shuffled(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) shuffled[i] = p[perm[i]];
  std::vector<Tet> back = tetrahedra_of(shuffled);
  for (Tet& t : back)
    for (auto& v : t) v = perm[v];
  EXPECT_EQ(canonical_set(back), canonical_set(tets)) << "another input order gives other tetrahedra";
}

// The fast evaluation of the perturbed in-sphere sign against the kernel's generic one, on
// random quintuples of a 3 x 3 x 3 grid: cospherical (exact zero) ones with a tetrahedron of
// non-zero volume, the only ones Delaunay3 asks, and the rest.
TEST(Delaunay3, LiftedPerturbationIsInsphereSos) {
  const auto p = grid(3);
  std::mt19937_64 rng(8);
  std::uniform_int_distribution<std::size_t> pick(0, p.size() - 1);
  int degenerate = 0;
  for (int k = 0; k < quintuples; ++k) {
    const P3 &a = p[pick(rng)], &b = p[pick(rng)], &c = p[pick(rng)], &d = p[pick(rng)], &e = p[pick(rng)];
    if (a == b || a == c || a == d || a == e || b == c || b == d || b == e || c == d || c == e || d == e) continue;
    if (predicates::orient3d(a, b, c, d) == predicates::Sign::zero) continue;
    const int expected = predicates::to_int(predicates::insphere_sos(a, b, c, d, e));
    degenerate += predicates::insphere(a, b, c, d, e) == predicates::Sign::zero ? 1 : 0;
    ASSERT_EQ(generators::detail::insphere_perturbed(a, b, c, d, e), expected);
  }
  EXPECT_GT(degenerate, quintuples / 60);
  // Points of an integer sphere (all cospherical) and integers near 2^22 (the 128-bit path's
  // bound), against the kernel's exact insphere where that is not zero.
  const auto sphere = integer_sphere(625 * 34);
  std::uniform_int_distribution<std::size_t> on_sphere(0, sphere.size() - 1);
  std::uniform_int_distribution<long> large(-(1l << 22) + 1, (1l << 22) - 1), near(-3, 3);
  for (int k = 0; k < quintuples / 3; ++k) {
    std::array<P3, 5> q;
    if (k % 2 == 0) {
      for (auto& v : q) v = sphere[on_sphere(rng)];
    } else {
      const P3 base{double(large(rng) / 2), double(large(rng) / 2), double(large(rng) / 2)};
      for (auto& v : q) v = {base.x + double(near(rng)), base.y + double(near(rng)), base.z + double(near(rng))};
      if (k % 4 == 1) q[4] = {double(large(rng)), double(large(rng)), double(large(rng))};
    }
    bool distinct = true;
    for (int i = 0; i < 5; ++i)
      for (int j = i + 1; j < 5; ++j) distinct = distinct && !(q[i] == q[j]);
    if (!distinct || predicates::orient3d(q[0], q[1], q[2], q[3]) == predicates::Sign::zero) continue;
    ASSERT_EQ(generators::detail::insphere_perturbed(q[0], q[1], q[2], q[3], q[4]),
              predicates::to_int(predicates::insphere_sos(q[0], q[1], q[2], q[3], q[4])));
  }
}

TEST(Delaunay3, UniformPointsAreDelaunay) {
  const auto p = uniform(uniform_count, 1);
  const auto tets = tetrahedra_of(p);
  check_delaunay_3(p, tets);
  // About 6.75 tetrahedra per uniform point (Dwyer 1991: 6.77 asymptotically in a convex body).
  EXPECT_GT(tets.size(), 6 * p.size());
  EXPECT_LT(tets.size(), 7 * p.size());
}

TEST(Delaunay3, PointsRoundedFromASphere) {
  const auto p = rounded_sphere(sphere_count, 2);
  const auto tets = tetrahedra_of(p);
  check_delaunay_3(p, tets);
}

TEST(Delaunay3, IntegerGridFillsTheCube) {
  const auto p = grid(grid_side);
  const auto tets = tetrahedra_of(p);
  const std::size_t hull_faces = check_delaunay_3(p, tets);
  const double side = double(grid_side - 1);
  EXPECT_EQ(six_volume(p, tets), mpq_class(6 * side * side * side));  // the cube's volume, exactly
  // Each of the 6 (side)^2 unit squares of the hull is two hull triangles.
  EXPECT_EQ(hull_faces, 12 * std::size_t(side * side));
  // The grid's Delaunay subdivision is its unit cells (8 cospherical corners each), and the
  // perturbed tetrahedralization refines it: every tetrahedron lies in one cell, with corners
  // among the cell's, so its volume is 1/6 or 1/3.
  for (const Tet& t : tets) {
    for (int axis = 0; axis < 3; ++axis) {
      auto coordinate = [&](std::uint32_t v) { return axis == 0 ? p[v].x : (axis == 1 ? p[v].y : p[v].z); };
      double lo = coordinate(t[0]), hi = lo;
      for (auto v : t) lo = std::min(lo, coordinate(v)), hi = std::max(hi, coordinate(v));
      EXPECT_EQ(hi - lo, 1.0);
    }
    const mpq_class v = six_volume(p, {t});
    EXPECT_TRUE(v == 1 || v == 2) << v;
  }
  expect_order_independent(p, tets, 3);
}

TEST(Delaunay3, IntegerPointsExactlyOnASphere) {
  const auto p = integer_sphere(625 * sphere_k);
  ASSERT_GT(p.size(), 100u);
  const auto tets = tetrahedra_of(p);
  const std::size_t hull_faces = check_delaunay_3(p, tets);
  // Every point is on the hull (the sphere is strictly convex): Euler, 2 V - 4 hull faces.
  EXPECT_EQ(hull_faces, 2 * p.size() - 4);
  expect_order_independent(p, tets, 4);
}

TEST(Delaunay3, ScalingByPowersOfTwoKeepsTheTetrahedra) {
  const auto p = uniform(scaled_count, 5);
  const auto base = canonical_set(tetrahedra_of(p));
  for (int k : {-600, -30, 1, 40, 700}) {
    std::vector<P3> q = p;
    for (auto& v : q) v = {std::ldexp(v.x, k), std::ldexp(v.y, k), std::ldexp(v.z, k)};
    EXPECT_EQ(canonical_set(tetrahedra_of(q)), base) << "scaled by 2^" << k;
  }
}

// locate: a live tetrahedron whose closure holds the query (exact orientations), or a ghost
// whose hull face has the query strictly outside; neighbour: symmetric, and `none` exactly on
// the hull faces the exact checks count.
TEST(Delaunay3, LocateAndNeighbours) {
  const auto p = grid(6);
  const Delaunay3 dt(p);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> u(-1.0, 6.0);
  static constexpr int face[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};
  for (int k = 0; k < 2000; ++k) {
    // Half the queries on grid planes, where they fall on faces and edges.
    P3 q{u(rng), u(rng), u(rng)};
    if (k % 2) q.x = std::round(q.x), q.y = std::round(q.y);
    const auto t = dt.locate(q);
    ASSERT_NE(t, Delaunay3::none);
    const bool inside = q.x >= 0 && q.x <= 5 && q.y >= 0 && q.y <= 5 && q.z >= 0 && q.z <= 5;
    ASSERT_EQ(dt.is_ghost(t), !inside) << q.x << " " << q.y << " " << q.z;
    if (!inside) continue;
    const auto c = dt.vertices(t);
    for (const auto& f : face)
      EXPECT_NE(predicates::orient3d(p[c[f[0]]], p[c[f[1]]], p[c[f[2]]], q), predicates::Sign::positive);
  }
  std::size_t hull = 0;
  for (Delaunay3::TetrahedronId t = 0; t < dt.tetrahedron_slot_count(); ++t) {
    if (!dt.is_live(t)) continue;
    for (int i = 0; i < 4; ++i) {
      const auto n = dt.neighbour(t, i);
      if (n == Delaunay3::none) {
        ++hull;
        continue;
      }
      int back = 0;
      for (int j = 0; j < 4; ++j) back += dt.neighbour(n, j) == t ? 1 : 0;
      EXPECT_EQ(back, 1);
    }
  }
  EXPECT_EQ(hull, 12u * 25u);
  EXPECT_EQ(dt.locate({std::nan(""), 0, 0}), Delaunay3::none);
}

TEST(Delaunay3, SmallDegenerateSets) {
  // The cube's corners: 8 cospherical points, 5 or 6 tetrahedra filling it.
  std::vector<P3> cube;
  for (int i = 0; i < 8; ++i) cube.push_back({double(i & 1), double((i >> 1) & 1), double((i >> 2) & 1)});
  const auto tets = tetrahedra_of(cube);
  check_delaunay_3(cube, tets);
  EXPECT_EQ(six_volume(cube, tets), 6);
  // A regular octahedron: 6 cospherical points, 4 of them coplanar in three ways.
  const std::vector<P3> octahedron{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  const auto otets = tetrahedra_of(octahedron);
  check_delaunay_3(octahedron, otets);
  EXPECT_EQ(six_volume(octahedron, otets), 8);  // 6 * (4/3)
  EXPECT_EQ(otets.size(), 4u);
}

// Progress: stage "delaunay", non-decreasing, ending at done == total == the point count.
TEST(Delaunay3, ReportsProgress) {
  const auto p = uniform(70000, 10);
  std::vector<std::uint64_t> done;
  const Delaunay3 dt(p, [&](const generators::Progress& r) {
    EXPECT_EQ(r.stage, "delaunay");
    EXPECT_EQ(r.total, p.size());
    done.push_back(r.done);
  });
  ASSERT_GE(done.size(), 2u);
  EXPECT_TRUE(std::is_sorted(done.begin(), done.end()));
  EXPECT_EQ(done.back(), p.size());
}

std::string error_of(const std::vector<P3>& p) {
  try {
    const Delaunay3 dt(p);
  } catch (const DelaunayError& e) {
    return e.what();
  }
  return "";
}

TEST(Delaunay3, BadInputIsRefused) {
  auto p = uniform(500, 6);
  p[417] = p[31];
  const std::string duplicate = error_of(p);
  EXPECT_NE(duplicate.find("points 31 and 417"), std::string::npos) << duplicate;
  std::ostringstream where;
  where.precision(17);
  where << '(' << p[31].x << ' ' << p[31].y << ' ' << p[31].z << ')';
  EXPECT_NE(duplicate.find(where.str()), std::string::npos) << duplicate;

  std::vector<P3> plane;
  for (int i = 0; i < 50; ++i) plane.push_back({double(i % 7), double(i / 7), 3.0});
  EXPECT_NE(error_of(plane).find("in one plane"), std::string::npos) << error_of(plane);
  plane[20] = plane[3];
  EXPECT_NE(error_of(plane).find("points 3 and 20"), std::string::npos) << error_of(plane);
  std::vector<P3> line;
  for (int i = 0; i < 10; ++i) line.push_back({double(i), double(2 * i), double(-i)});
  EXPECT_NE(error_of(line).find("on one line"), std::string::npos) << error_of(line);
  EXPECT_NE(error_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}).find("at least four"), std::string::npos);
  auto nan = uniform(20, 7);
  nan[9].y = std::nan("");
  EXPECT_NE(error_of(nan).find("point 9"), std::string::npos) << error_of(nan);
  EXPECT_NE(error_of(nan).find("not finite"), std::string::npos) << error_of(nan);
}

}  // namespace
}  // namespace certimesh::testing
