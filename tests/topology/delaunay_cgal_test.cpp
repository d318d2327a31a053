// CGAL as the oracle: Delaunay triangulations of seeded random points (generic dyadic
// coordinates, and small-lattice points full of degeneracies) become meshes of the model
// through from_mesh_data; the model's adjacency must equal CGAL's neighbour relation (CGAL's
// neighbor(i) is also the cell across the facet opposite vertex i), its counts CGAL's counts,
// and the Euler relations of §2.2 must hold.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "certimesh/topology/mesh_counts.h"
#include "certimesh/topology/mesh_data_conversion.h"
#include "cgal_reference.h"

namespace certimesh::topology {
namespace {

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

// CGAL's finite vertices and cells, numbered in iteration order, as MeshData.
io::MeshData export_mesh(const cgal_reference::Triangulation2& dt) {
  io::MeshData m;
  m.dimension = 2;
  for (const auto& p : dt.vertices) m.coordinates.insert(m.coordinates.end(), {p[0], p[1]});
  for (const auto& f : dt.triangles) m.triangles.insert(m.triangles.end(), f.begin(), f.end());
  return m;
}

io::MeshData export_mesh(const cgal_reference::Triangulation3& dt) {
  io::MeshData m;
  m.dimension = 3;
  for (const auto& p : dt.vertices) m.coordinates.insert(m.coordinates.end(), {p[0], p[1], p[2]});
  for (const auto& c : dt.tetrahedra) m.tetrahedra.insert(m.tetrahedra.end(), c.begin(), c.end());
  return m;
}

// Element e's neighbour across from each vertex i is CGAL's neighbor(i) (kInfinite, the
// model's none, for an infinite cell).
template <class Mesh, std::size_t N>
void expect_same_neighbours(const Mesh& mesh, std::uint32_t element, const std::array<std::uint32_t, N>& expected) {
  const ElementId e{element};
  for (std::size_t i = 0; i < N; ++i)
    EXPECT_EQ(mesh.neighbour(e, int(i)).value, expected[i]) << "element " << e.value << " facet " << i;
}

TEST(DelaunayCgal, TriangleMeshMatchesCgal) {
  for (const Case& c : cases) {
    SCOPED_TRACE("seed " + std::to_string(c.seed));
    std::mt19937_64 rng(c.seed);
    std::vector<cgal_reference::Point2> points;
    for (int i = 0; i < c.points; ++i) {
      const double x = draw_coordinate(rng, c.lattice);
      points.push_back({x, draw_coordinate(rng, c.lattice)});
    }
    const auto dt = cgal_reference::delaunay_2(points);
    const auto result = from_mesh_data<TriangleMesh2>(export_mesh(dt));
    ASSERT_TRUE(result.ok()) << result.error->message;
    const TriangleMesh2& mesh = *result.mesh;
    for (std::uint32_t f = 0; f < dt.triangles.size(); ++f) expect_same_neighbours(mesh, f, dt.neighbours[f]);

    const MeshCounts counts = count_mesh(mesh);
    const std::size_t hull_edges = dt.infinite_faces, finite_edges = dt.finite_edges;
    EXPECT_EQ(counts.vertices, dt.vertices.size());
    EXPECT_EQ(counts.triangles, dt.triangles.size());
    EXPECT_EQ(counts.edges, finite_edges);
    EXPECT_EQ(counts.boundary_edges, hull_edges);
    EXPECT_EQ(counts.boundary_vertices, dt.infinite_vertex_degree);
    EXPECT_EQ(counts.holes, 0u);
    // (2.2.2) and (2.2.4) with Nh = 0 on CGAL's own counts.
    const auto nv = std::int64_t(dt.vertices.size()), nf = std::int64_t(dt.triangles.size());
    EXPECT_EQ(nf, std::int64_t(finite_edges) - nv + 1);
    EXPECT_EQ(nf, 2 * nv - std::int64_t(hull_edges) - 2);
  }
}

TEST(DelaunayCgal, TetrahedralMeshMatchesCgal) {
  for (const Case& c : cases) {
    SCOPED_TRACE("seed " + std::to_string(c.seed));
    std::mt19937_64 rng(c.seed);
    std::vector<cgal_reference::Point3> points;
    for (int i = 0; i < c.points / 2; ++i) {
      const double x = draw_coordinate(rng, c.lattice);
      const double y = draw_coordinate(rng, c.lattice);
      points.push_back({x, y, draw_coordinate(rng, c.lattice)});
    }
    const auto dt = cgal_reference::delaunay_3(points);
    const auto result = from_mesh_data<TetrahedralMesh3>(export_mesh(dt));
    ASSERT_TRUE(result.ok()) << result.error->message;
    const TetrahedralMesh3& mesh = *result.mesh;
    for (std::uint32_t cell = 0; cell < dt.tetrahedra.size(); ++cell) expect_same_neighbours(mesh, cell, dt.neighbours[cell]);

    const MeshCounts counts = count_mesh(mesh);
    const std::size_t hull_facets = dt.infinite_cells;
    EXPECT_EQ(counts.vertices, dt.vertices.size());
    EXPECT_EQ(counts.tetrahedra, dt.tetrahedra.size());
    EXPECT_EQ(counts.triangles, dt.finite_facets);
    EXPECT_EQ(counts.edges, dt.finite_edges);
    EXPECT_EQ(counts.boundary_faces, hull_facets);
    EXPECT_EQ(counts.boundary_vertices, dt.infinite_vertex_degree);
    // The tetrahedral relations on CGAL's counts: the convex hull is a ball.
    const auto nv = std::int64_t(dt.vertices.size()), ne = std::int64_t(dt.finite_edges);
    const auto nt = std::int64_t(dt.tetrahedra.size()), nfb = std::int64_t(hull_facets);
    const auto nvb = std::int64_t(dt.infinite_vertex_degree);
    EXPECT_EQ(4 * ne, 4 * nt + 4 * nv + 3 * nfb - 2 * nvb);
    EXPECT_EQ(4 * nt, 2 * (std::int64_t(dt.finite_facets) - nfb) + nfb);
    EXPECT_EQ(counts.euler_characteristic(), 1);
  }
}

}  // namespace
}  // namespace certimesh::topology
