// CGAL as the oracle: Delaunay triangulations of seeded random points (generic dyadic
// coordinates, and small-lattice points full of degeneracies) become meshes of the model
// through from_mesh_data; the model's adjacency must equal CGAL's neighbour relation (CGAL's
// neighbor(i) is also the cell across the facet opposite vertex i), its counts CGAL's counts,
// and the Euler relations of §2.2 must hold.
#include <gtest/gtest.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "certimesh/topology/mesh_counts.h"
#include "certimesh/topology/mesh_data_conversion.h"

namespace certimesh::topology {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
constexpr std::uint32_t infinite = 0xFFFFFFFFu;
using Vb2 = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using Fb2 = CGAL::Triangulation_face_base_with_info_2<std::uint32_t, Kernel>;
using Dt2 = CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vb2, Fb2>>;
using Vb3 = CGAL::Triangulation_vertex_base_with_info_3<std::uint32_t, Kernel>;
using Cb3 = CGAL::Triangulation_cell_base_with_info_3<std::uint32_t, Kernel>;
using Dt3 = CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<Vb3, Cb3>>;

struct Case {
  std::uint64_t seed;
  int points;
  bool lattice;  // coordinates in -4..4: collinear, cocircular, cospherical points, duplicates
};
const Case cases[] = {{11, 3000, false}, {12, 400, true}};

double draw_coordinate(std::mt19937_64& rng, bool lattice) {
  if (lattice) return static_cast<double>(std::uniform_int_distribution<int>(-4, 4)(rng));
  return std::uniform_int_distribution<int>(-(1 << 20), (1 << 20) - 1)(rng) / 1024.0;
}

// Numbers CGAL's finite vertices and cells in iteration order and writes them as MeshData.
io::MeshData number_and_export(Dt2& dt) {
  io::MeshData m;
  m.dimension = 2;
  std::uint32_t next = 0;
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    v->info() = next++;
    m.coordinates.insert(m.coordinates.end(), {v->point().x(), v->point().y()});
  }
  next = 0;
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) f->info() = infinite;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    f->info() = next++;
    for (int i = 0; i < 3; ++i) m.triangles.push_back(f->vertex(i)->info());
  }
  return m;
}

io::MeshData number_and_export(Dt3& dt) {
  io::MeshData m;
  m.dimension = 3;
  std::uint32_t next = 0;
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    v->info() = next++;
    m.coordinates.insert(m.coordinates.end(), {v->point().x(), v->point().y(), v->point().z()});
  }
  next = 0;
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) c->info() = infinite;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    c->info() = next++;
    for (int i = 0; i < 4; ++i) m.tetrahedra.push_back(c->vertex(i)->info());
  }
  return m;
}

template <class Mesh, class Cell>
void expect_same_neighbours(const Mesh& mesh, Cell cell, int vertices) {
  const ElementId e{cell->info()};
  for (int i = 0; i < vertices; ++i) {
    const std::uint32_t expected = cell->neighbor(i)->info();
    EXPECT_EQ(mesh.neighbour(e, i).value, expected) << "element " << e.value << " facet " << i;
  }
}

TEST(DelaunayCgal, TriangleMeshMatchesCgal) {
  for (const Case& c : cases) {
    SCOPED_TRACE("seed " + std::to_string(c.seed));
    std::mt19937_64 rng(c.seed);
    std::vector<Kernel::Point_2> points;
    for (int i = 0; i < c.points; ++i) {
      const double x = draw_coordinate(rng, c.lattice);
      points.emplace_back(x, draw_coordinate(rng, c.lattice));
    }
    Dt2 dt(points.begin(), points.end());
    const auto result = from_mesh_data<TriangleMesh2>(number_and_export(dt));
    ASSERT_TRUE(result.ok()) << result.error->message;
    const TriangleMesh2& mesh = *result.mesh;
    for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) expect_same_neighbours(mesh, f, 3);

    const MeshCounts counts = count_mesh(mesh);
    std::size_t hull_edges = 0;
    for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) hull_edges += dt.is_infinite(f) ? 1 : 0;
    std::size_t finite_edges = 0;
    for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) ++finite_edges;
    EXPECT_EQ(counts.vertices, dt.number_of_vertices());
    EXPECT_EQ(counts.triangles, dt.number_of_faces());
    EXPECT_EQ(counts.edges, finite_edges);
    EXPECT_EQ(counts.boundary_edges, hull_edges);
    EXPECT_EQ(counts.boundary_vertices, std::size_t(dt.infinite_vertex()->degree()));
    EXPECT_EQ(counts.holes, 0u);
    // (2.2.2) and (2.2.4) with Nh = 0 on CGAL's own counts.
    const auto nv = std::int64_t(dt.number_of_vertices()), nf = std::int64_t(dt.number_of_faces());
    EXPECT_EQ(nf, std::int64_t(finite_edges) - nv + 1);
    EXPECT_EQ(nf, 2 * nv - std::int64_t(hull_edges) - 2);
  }
}

TEST(DelaunayCgal, TetrahedralMeshMatchesCgal) {
  for (const Case& c : cases) {
    SCOPED_TRACE("seed " + std::to_string(c.seed));
    std::mt19937_64 rng(c.seed);
    std::vector<Kernel::Point_3> points;
    for (int i = 0; i < c.points / 2; ++i) {
      const double x = draw_coordinate(rng, c.lattice);
      const double y = draw_coordinate(rng, c.lattice);
      points.emplace_back(x, y, draw_coordinate(rng, c.lattice));
    }
    Dt3 dt(points.begin(), points.end());
    const auto result = from_mesh_data<TetrahedralMesh3>(number_and_export(dt));
    ASSERT_TRUE(result.ok()) << result.error->message;
    const TetrahedralMesh3& mesh = *result.mesh;
    for (auto cell = dt.finite_cells_begin(); cell != dt.finite_cells_end(); ++cell)
      expect_same_neighbours(mesh, cell, 4);

    const MeshCounts counts = count_mesh(mesh);
    const std::size_t hull_facets = dt.number_of_cells() - dt.number_of_finite_cells();
    EXPECT_EQ(counts.vertices, dt.number_of_vertices());
    EXPECT_EQ(counts.tetrahedra, dt.number_of_finite_cells());
    EXPECT_EQ(counts.triangles, dt.number_of_finite_facets());
    EXPECT_EQ(counts.edges, dt.number_of_finite_edges());
    EXPECT_EQ(counts.boundary_faces, hull_facets);
    EXPECT_EQ(counts.boundary_vertices, dt.degree(dt.infinite_vertex()));
    // The tetrahedral relations on CGAL's counts: the convex hull is a ball.
    const auto nv = std::int64_t(dt.number_of_vertices()), ne = std::int64_t(dt.number_of_finite_edges());
    const auto nt = std::int64_t(dt.number_of_finite_cells()), nfb = std::int64_t(hull_facets);
    const auto nvb = std::int64_t(dt.degree(dt.infinite_vertex()));
    EXPECT_EQ(4 * ne, 4 * nt + 4 * nv + 3 * nfb - 2 * nvb);
    EXPECT_EQ(4 * nt, 2 * (std::int64_t(dt.number_of_finite_facets()) - nfb) + nfb);
    EXPECT_EQ(counts.euler_characteristic(), 1);
  }
}

}  // namespace
}  // namespace certimesh::topology
