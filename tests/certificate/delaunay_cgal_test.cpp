// CGAL's Delaunay triangulations as independently built valid meshes: the finite cells of
// a Delaunay triangulation of random points tile their convex hull exactly once, so the
// certificate must accept them, and its counts must match CGAL's.
#include <gtest/gtest.h>

#include <cstdint>
#include <random>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "cgal_reference.h"
#include "mesh_oracle.h"

namespace certimesh::testing {
namespace {

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

// CGAL's finite vertices (iteration order) and finite faces or cells, as MeshData.
io::MeshData mesh_of(const cgal_reference::Triangulation2& dt) {
  io::MeshData m;
  m.dimension = 2;
  for (const auto& p : dt.vertices) m.coordinates.insert(m.coordinates.end(), {p[0], p[1]});
  for (const auto& f : dt.triangles) m.triangles.insert(m.triangles.end(), f.begin(), f.end());
  m.triangle_labels.assign(m.triangle_count(), 0);
  return m;
}

io::MeshData mesh_of(const cgal_reference::Triangulation3& dt) {
  io::MeshData m;
  m.dimension = 3;
  for (const auto& p : dt.vertices) m.coordinates.insert(m.coordinates.end(), {p[0], p[1], p[2]});
  for (const auto& c : dt.tetrahedra) m.tetrahedra.insert(m.tetrahedra.end(), c.begin(), c.end());
  m.tetrahedron_labels.assign(m.tetrahedron_count(), 0);
  return m;
}

TEST(DelaunayCgal, Triangulation2dAccepted) {
  for (const Case& c : kCases) {
    SCOPED_TRACE("seed " + std::to_string(c.seed));
    std::mt19937_64 rng(c.seed);
    std::vector<cgal_reference::Point2> points;
    for (int i = 0; i < c.points; ++i) {
      const double x = draw_coordinate(rng, c.lattice);
      points.push_back({x, draw_coordinate(rng, c.lattice)});
    }
    const auto dt = cgal_reference::delaunay_2(points);
    ASSERT_EQ(dt.dimension, 2);
    const io::MeshData mesh = mesh_of(dt);
    ASSERT_TRUE(all_elements_positive(mesh));  // CGAL's faces are counterclockwise
    const certificate::Report r = certificate::check_mesh(mesh);
    EXPECT_TRUE(r.valid) << certificate::defect_name(r.finding.defect) << ": " << r.finding.message;
    EXPECT_EQ(r.statistics.elements, dt.triangles.size());
    EXPECT_EQ(r.statistics.vertices, dt.vertices.size());
    // Hull edges are the edges of the infinite vertex's star.
    EXPECT_EQ(r.statistics.boundary_facets, dt.infinite_vertex_degree);
    EXPECT_EQ(r.statistics.boundary_components, 1u);
  }
}

TEST(DelaunayCgal, Triangulation3dAccepted) {
  for (const Case& c : kCases) {
    SCOPED_TRACE("seed " + std::to_string(c.seed));
    std::mt19937_64 rng(c.seed);
    std::vector<cgal_reference::Point3> points;
    for (int i = 0; i < c.points; ++i) {
      const double x = draw_coordinate(rng, c.lattice);
      const double y = draw_coordinate(rng, c.lattice);
      points.push_back({x, y, draw_coordinate(rng, c.lattice)});
    }
    const auto dt = cgal_reference::delaunay_3(points);
    ASSERT_EQ(dt.dimension, 3);
    const io::MeshData mesh = mesh_of(dt);
    ASSERT_TRUE(all_elements_positive(mesh));  // CGAL's cells: det[b-a, c-a, d-a] > 0
    const certificate::Report r = certificate::check_mesh(mesh);
    EXPECT_TRUE(r.valid) << certificate::defect_name(r.finding.defect) << ": " << r.finding.message;
    EXPECT_EQ(r.statistics.elements, dt.tetrahedra.size());
    EXPECT_EQ(r.statistics.vertices, dt.vertices.size());
    // Hull triangles are the finite facets of the infinite cells.
    EXPECT_EQ(r.statistics.boundary_facets, dt.infinite_cells);
    EXPECT_EQ(r.statistics.boundary_components, 1u);
  }
}

}  // namespace
}  // namespace certimesh::testing
