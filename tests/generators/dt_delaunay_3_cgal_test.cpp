// Delaunay3 against CGAL (the independent oracle): the same tetrahedra as
// Delaunay_triangulation_3 (Epick) on random points in general position, where the Delaunay
// tetrahedralization is unique; and on uniform points, points rounded from a sphere and
// integer points exactly on a sphere, the exact volume of the tetrahedra equals the exact
// volume of CGAL's convex hull (convex_hull_3), together with the exact checks of
// dt_delaunay_3_checks.h.
#include <gtest/gtest.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/convex_hull_3.h>

#include <cmath>
#include <random>

#include "certimesh/generators/delaunay/delaunay_3.h"
#include "dt_delaunay_3_checks.h"

namespace certimesh::testing {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using Tds = CGAL::Triangulation_data_structure_3<VertexBase>;
using CgalDelaunay = CGAL::Delaunay_triangulation_3<Kernel, Tds>;
using Mesh = CGAL::Surface_mesh<Kernel::Point_3>;

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

std::vector<Tet> cgal_tetrahedra(const std::vector<P3>& p) {
  std::vector<std::pair<Kernel::Point_3, std::uint32_t>> in;
  for (std::uint32_t i = 0; i < p.size(); ++i) in.emplace_back(Kernel::Point_3(p[i].x, p[i].y, p[i].z), i);
  const CgalDelaunay dt(in.begin(), in.end());
  std::vector<Tet> out;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    out.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
  return out;
}

// 6 times the exact volume CGAL's convex hull encloses: its triangles coned from one vertex.
mpq_class cgal_hull_six_volume(const std::vector<P3>& p) {
  std::vector<Kernel::Point_3> in;
  for (const auto& q : p) in.emplace_back(q.x, q.y, q.z);
  Mesh hull;
  CGAL::convex_hull_3(in.begin(), in.end(), hull);
  const auto apex = hull.point(*hull.vertices().begin());
  std::vector<P3> corners{{apex.x(), apex.y(), apex.z()}};
  std::vector<Tet> cone;
  for (auto f : hull.faces()) {
    Tet t{0, 0, 0, 0};
    int k = 1;
    for (auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) {
      const auto& q = hull.point(v);
      corners.push_back({q.x(), q.y(), q.z()});
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
