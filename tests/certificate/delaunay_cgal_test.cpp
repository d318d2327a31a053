// CGAL's Delaunay triangulations as independently built valid meshes: the finite cells of
// a Delaunay triangulation of random points tile their convex hull exactly once, so the
// certificate must accept them, and its counts must match CGAL's.
#include <gtest/gtest.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <cstdint>
#include <random>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "mesh_oracle.h"

namespace certimesh::testing {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb2 = CGAL::Triangulation_vertex_base_with_info_2<io::Index, Kernel>;
using Dt2 = CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vb2>>;
using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<io::Index, Kernel>;
using Dt3 = CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<Vb3>>;

// Coordinates: either dyadic values in [-1024, 1024) (generic position), or small integers
// (a 9^d lattice: many collinear, cocircular and cospherical points, duplicates merged).
double draw_coordinate(std::mt19937_64& rng, bool lattice) {
  if (lattice) return static_cast<double>(std::uniform_int_distribution<int>(-4, 4)(rng));
  return std::uniform_int_distribution<int>(-(1 << 20), (1 << 20) - 1)(rng) / 1024.0;
}

struct Case {
  std::uint64_t seed;
  int points;
  bool lattice;
};

const Case kCases[] = {{1, 2000, false}, {2, 5000, false}, {3, 300, true}, {4, 600, true}};

io::MeshData mesh_of(const Dt2& dt) {
  io::MeshData m;
  m.dimension = 2;
  io::Index next = 0;
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    v->info() = next++;
    m.coordinates.insert(m.coordinates.end(), {v->point().x(), v->point().y()});
  }
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    for (int i = 0; i < 3; ++i) m.triangles.push_back(f->vertex(i)->info());
  m.triangle_labels.assign(m.triangle_count(), 0);
  return m;
}

io::MeshData mesh_of(const Dt3& dt) {
  io::MeshData m;
  m.dimension = 3;
  io::Index next = 0;
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    v->info() = next++;
    m.coordinates.insert(m.coordinates.end(), {v->point().x(), v->point().y(), v->point().z()});
  }
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    for (int i = 0; i < 4; ++i) m.tetrahedra.push_back(c->vertex(i)->info());
  m.tetrahedron_labels.assign(m.tetrahedron_count(), 0);
  return m;
}

TEST(DelaunayCgal, Triangulation2dAccepted) {
  for (const Case& c : kCases) {
    SCOPED_TRACE("seed " + std::to_string(c.seed));
    std::mt19937_64 rng(c.seed);
    std::vector<Kernel::Point_2> points;
    for (int i = 0; i < c.points; ++i) {
      const double x = draw_coordinate(rng, c.lattice);
      points.emplace_back(x, draw_coordinate(rng, c.lattice));
    }
    Dt2 dt(points.begin(), points.end());
    ASSERT_EQ(dt.dimension(), 2);
    const io::MeshData mesh = mesh_of(dt);
    ASSERT_TRUE(all_elements_positive(mesh));  // CGAL's faces are counterclockwise
    const certificate::Report r = certificate::check_mesh(mesh);
    EXPECT_TRUE(r.valid) << certificate::defect_name(r.finding.defect) << ": " << r.finding.message;
    EXPECT_EQ(r.statistics.elements, dt.number_of_faces());
    EXPECT_EQ(r.statistics.vertices, dt.number_of_vertices());
    // Hull edges are the edges of the infinite vertex's star.
    EXPECT_EQ(r.statistics.boundary_facets, dt.degree(dt.infinite_vertex()));
    EXPECT_EQ(r.statistics.boundary_components, 1u);
  }
}

TEST(DelaunayCgal, Triangulation3dAccepted) {
  for (const Case& c : kCases) {
    SCOPED_TRACE("seed " + std::to_string(c.seed));
    std::mt19937_64 rng(c.seed);
    std::vector<Kernel::Point_3> points;
    for (int i = 0; i < c.points; ++i) {
      const double x = draw_coordinate(rng, c.lattice);
      const double y = draw_coordinate(rng, c.lattice);
      points.emplace_back(x, y, draw_coordinate(rng, c.lattice));
    }
    Dt3 dt(points.begin(), points.end());
    ASSERT_EQ(dt.dimension(), 3);
    const io::MeshData mesh = mesh_of(dt);
    ASSERT_TRUE(all_elements_positive(mesh));  // CGAL's cells: det[b-a, c-a, d-a] > 0
    const certificate::Report r = certificate::check_mesh(mesh);
    EXPECT_TRUE(r.valid) << certificate::defect_name(r.finding.defect) << ": " << r.finding.message;
    EXPECT_EQ(r.statistics.elements, dt.number_of_finite_cells());
    EXPECT_EQ(r.statistics.vertices, dt.number_of_vertices());
    // Hull triangles are the finite facets of the infinite cells.
    EXPECT_EQ(r.statistics.boundary_facets, dt.number_of_cells() - dt.number_of_finite_cells());
    EXPECT_EQ(r.statistics.boundary_components, 1u);
  }
}

}  // namespace
}  // namespace certimesh::testing
