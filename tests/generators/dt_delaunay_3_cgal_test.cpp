// Delaunay3 against CGAL (the independent oracle): the same tetrahedra as
// Delaunay_triangulation_3 (Epick) on random points in general position, where the Delaunay
// tetrahedralization is unique; and on uniform points, points rounded from a sphere and
// integer points exactly on a sphere, the exact volume of the tetrahedra equals the exact
// volume of CGAL's convex hull (convex_hull_3), together with the exact checks of
// dt_delaunay_3_checks.h.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "certimesh/generators/delaunay/delaunay_3.h"
#include "cgal_reference.h"
#include "dt_delaunay_3_checks.h"

namespace certimesh::testing {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr std::size_t count = 2000;
constexpr long sphere_k = 4;
#else
constexpr std::size_t count = 30000;
constexpr long sphere_k = 34;
#endif

std::vector<Tet> certimesh_tetrahedra(const std::vector<P3>& p) {
  const generators::Delaunay3 dt(p);
  std::vector<Tet> out;
  for (const auto& t : dt.tetrahedra()) out.push_back(t);
  return out;
}

std::vector<cgal_reference::Point3> reference_points(const std::vector<P3>& p) {
  std::vector<cgal_reference::Point3> out;
  for (const P3& q : p) out.push_back({q.x, q.y, q.z});
  return out;
}

// CGAL's finite cells, by input index.
std::vector<Tet> cgal_tetrahedra(const std::vector<P3>& p) {
  const auto dt = cgal_reference::delaunay_3(reference_points(p));
  std::vector<Tet> out;
  for (const auto& c : dt.tetrahedra) out.push_back({dt.input[c[0]], dt.input[c[1]], dt.input[c[2]], dt.input[c[3]]});
  return out;
}

// 6 times the exact volume CGAL's convex hull encloses: its triangles coned from one vertex.
mpq_class cgal_hull_six_volume(const std::vector<P3>& p) {
  const auto hull = cgal_reference::convex_hull_3(reference_points(p));
  const auto& apex = hull.vertices.front();
  std::vector<P3> corners{{apex[0], apex[1], apex[2]}};
  std::vector<Tet> cone;
  for (const auto& f : hull.faces) {
    Tet t{0, 0, 0, 0};
    int k = 1;
    for (const auto v : f) {
      const auto& q = hull.vertices[v];
      corners.push_back({q[0], q[1], q[2]});
      if (k < 4) t[k] = static_cast<std::uint32_t>(corners.size() - 1);
      ++k;
    }
    EXPECT_EQ(k, 4) << "a hull face that is not a triangle";
    cone.push_back(t);
  }
  // (apex, a, b, c), for a face (a, b, c) counterclockwise seen from outside, has volume >= 0.
  return six_volume(corners, cone);
}

std::vector<P3> uniform(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<P3> p(n);
  for (auto& q : p) q = {u(rng), u(rng), u(rng)};
  return p;
}

TEST(Delaunay3Cgal, SameTetrahedraOnRandomPoints) {
  for (std::uint64_t seed : {11u, 12u}) {
    const auto p = uniform(count, seed);
    const auto ours = certimesh_tetrahedra(p);
    EXPECT_EQ(canonical_set(ours), canonical_set(cgal_tetrahedra(p))) << "seed " << seed;
    EXPECT_EQ(six_volume(p, ours), cgal_hull_six_volume(p));
  }
}

TEST(Delaunay3Cgal, HullVolumeOnPointsRoundedFromASphere) {
  std::mt19937_64 rng(13);
  std::normal_distribution<double> g;
  std::vector<P3> p(count / 3);
  for (auto& q : p) {
    const double x = g(rng), y = g(rng), z = g(rng), r = std::sqrt(x * x + y * y + z * z);
    q = {3 * x / r, 3 * y / r, 3 * z / r};
  }
  const auto tets = certimesh_tetrahedra(p);
  check_delaunay_3(p, tets);
  EXPECT_EQ(six_volume(p, tets), cgal_hull_six_volume(p));
}

TEST(Delaunay3Cgal, HullVolumeOnIntegerPointsOnASphere) {
  std::vector<P3> p;
  const long r2 = 625 * sphere_k, r = static_cast<long>(std::sqrt(double(r2)));
  for (long x = -r; x <= r; ++x)
    for (long y = -r; y <= r; ++y)
      for (long z = -r; z <= r; ++z)
        if (x * x + y * y + z * z == r2) p.push_back({double(x), double(y), double(z)});
  const auto tets = certimesh_tetrahedra(p);
  check_delaunay_3(p, tets);
  EXPECT_EQ(six_volume(p, tets), cgal_hull_six_volume(p));
}

}  // namespace
}  // namespace certimesh::testing
