// The counting relations of the monograph's §2.2 (digest A §3, §6.2) on meshes whose counts
// are known in closed form: the relations are theorems and the grid counts are computed here
// from the grid sizes, so neither comes from the code under test.
#include <gtest/gtest.h>

#include <cstdint>

#include "certimesh/topology/mesh_counts.h"
#include "fixtures.h"

namespace certimesh::topology {
namespace {

using testing::Cell2;
using testing::Cell3;
using I = std::int64_t;

// The 2D relations (2.2.2)-(2.2.6) for a connected planar mesh with Nh holes.
void expect_planar_relations(const MeshCounts& c) {
  const I nv = I(c.vertices), ne = I(c.edges), nf = I(c.triangles), nh = I(c.holes);
  EXPECT_EQ(nf + nh, ne - nv + 1) << "(2.2.2)";
  EXPECT_EQ(2 * I(c.interior_edges) + I(c.boundary_edges), 3 * nf) << "(2.2.3)";
  EXPECT_EQ(nf, 2 * nv - I(c.boundary_edges) + 2 * nh - 2) << "(2.2.4)";
  EXPECT_LE(nf, 2 * nv - 5) << "(2.2.5)";
  EXPECT_LE(ne, 3 * nv - 6) << "(2.2.6)";
  EXPECT_EQ(c.boundary_vertices, c.boundary_edges) << "simple boundary loops: Nvb = Neb";
}

// The 3D relations for a tetrahedral mesh whose vertex stars are balls.
void expect_tetrahedral_relations(const MeshCounts& c, I euler_characteristic) {
  const I nv = I(c.vertices), ne = I(c.edges), nt = I(c.tetrahedra);
  const I nfb = I(c.boundary_faces), nvb = I(c.boundary_vertices);
  EXPECT_EQ(4 * ne, 4 * nt + 4 * nv + 3 * nfb - 2 * nvb) << "Ne = Nt + Nv + 3/4 Nfb - 1/2 Nvb";
  EXPECT_EQ(4 * nt, 2 * I(c.interior_faces) + nfb) << "4Nt = 2Nfi + Nfb";
  EXPECT_EQ(4 * c.euler_characteristic(), 2 * nvb - nfb) << "chi = 1/2 Nvb - 1/4 Nfb";
  EXPECT_EQ(c.euler_characteristic(), euler_characteristic);
}

TEST(EulerRelations, Figure25SquareWithSquareHole) {
  TriangleMesh2 mesh;
  const std::array<std::array<double, 2>, 8> points{
      {{0, 0}, {3, 0}, {3, 3}, {0, 3}, {1, 1}, {2, 1}, {2, 2}, {1, 2}}};
  std::vector<VertexId> v;
  for (const auto& p : points) v.push_back(mesh.add_vertex(p));
  const std::array<std::array<int, 3>, 8> triangles{
      {{0, 1, 5}, {0, 5, 4}, {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}}};
  for (const auto& t : triangles) mesh.add_element({v[t[0]], v[t[1]], v[t[2]]});
  const MeshCounts c = count_mesh(mesh);
  // (Nv, Ne, Nf, Nh, Nei, Neb) = (8, 16, 8, 1, 8, 8), as printed with Fig. 2.5.
  EXPECT_EQ(c.vertices, 8u);
  EXPECT_EQ(c.edges, 16u);
  EXPECT_EQ(c.triangles, 8u);
  EXPECT_EQ(c.holes, 1u);
  EXPECT_EQ(c.interior_edges, 8u);
  EXPECT_EQ(c.boundary_edges, 8u);
  EXPECT_EQ(c.boundary_components, 2u);
  const I nv = 8, ne = 16, nf = 8, nh = 1;
  EXPECT_EQ(nf + nh, ne - nv + 1);
  EXPECT_EQ(2 * 8 + 8, 3 * nf);
}

TEST(EulerRelations, StructuredGrids2D) {
  for (const auto& [nx, ny] : {std::pair{1, 1}, std::pair{3, 2}, std::pair{7, 5}, std::pair{20, 13}}) {
    const MeshCounts c = count_mesh(testing::grid2(nx, ny));
    EXPECT_EQ(c.vertices, std::size_t((nx + 1) * (ny + 1)));
    EXPECT_EQ(c.triangles, std::size_t(2 * nx * ny));
    EXPECT_EQ(c.edges, std::size_t(nx * (ny + 1) + ny * (nx + 1) + nx * ny));
    EXPECT_EQ(c.boundary_edges, std::size_t(2 * (nx + ny)));
    EXPECT_EQ(c.holes, 0u);
    EXPECT_EQ(c.components, 1u);
    expect_planar_relations(c);
  }
}

TEST(EulerRelations, GridsWithHoles2D) {
  // One interior cell removed: one hole, 2 triangles and 1 diagonal fewer, 4 more boundary edges.
  const MeshCounts one = count_mesh(testing::grid2(4, 4, {Cell2{1, 1}}));
  EXPECT_EQ(one.holes, 1u);
  EXPECT_EQ(one.triangles, 2u * 16 - 2);
  EXPECT_EQ(one.edges, std::size_t(4 * 5 * 2 + 16 - 1));
  EXPECT_EQ(one.boundary_edges, 16u + 4);
  expect_planar_relations(one);
  // Two separated holes, one of them 2 x 1 cells.
  const MeshCounts two = count_mesh(testing::grid2(6, 6, {Cell2{1, 1}, Cell2{3, 3}, Cell2{4, 3}}));
  EXPECT_EQ(two.holes, 2u);
  EXPECT_EQ(two.boundary_edges, 24u + 4 + 6);
  expect_planar_relations(two);
}

TEST(EulerRelations, SingleTetrahedronAndCubes) {
  const MeshCounts single = count_mesh(testing::kuhn_grid3(1, 1, 1));
  EXPECT_EQ(single.tetrahedra, 6u);
  EXPECT_EQ(single.edges, 19u) << "cube in 6 tetrahedra";
  EXPECT_EQ(single.vertices, 8u);
  EXPECT_EQ(single.boundary_faces, 12u);
  expect_tetrahedral_relations(single, 1);

  const MeshCounts five = count_mesh(testing::cube_in_five());
  EXPECT_EQ(five.tetrahedra, 5u);
  EXPECT_EQ(five.edges, 18u) << "cube in 5 tetrahedra";
  EXPECT_EQ(five.boundary_faces, 12u);
  EXPECT_EQ(five.interior_faces, 4u);
  expect_tetrahedral_relations(five, 1);

  TetrahedralMesh3 one;
  std::vector<VertexId> v;
  for (const auto& p : {std::array<double, 3>{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}})
    v.push_back(one.add_vertex(p));
  one.add_element({v[0], v[1], v[2], v[3]});
  const MeshCounts tet = count_mesh(one);
  EXPECT_EQ(tet.vertices, 4u);
  EXPECT_EQ(tet.edges, 6u);
  EXPECT_EQ(tet.triangles, 4u);
  EXPECT_EQ(tet.tetrahedra, 1u);
  expect_tetrahedral_relations(tet, 1);
}

TEST(EulerRelations, KuhnGrids3D) {
  for (const int n : {2, 3, 5}) {
    const MeshCounts c = count_mesh(testing::kuhn_grid3(n, n, n));
    const I nn = n;
    EXPECT_EQ(I(c.vertices), (nn + 1) * (nn + 1) * (nn + 1));
    EXPECT_EQ(I(c.tetrahedra), 6 * nn * nn * nn);
    // Axis edges, one diagonal per unit square face, one body diagonal per cube.
    EXPECT_EQ(I(c.edges), 3 * nn * (nn + 1) * (nn + 1) + 3 * nn * nn * (nn + 1) + nn * nn * nn);
    EXPECT_EQ(I(c.boundary_faces), 12 * nn * nn);
    EXPECT_EQ(I(c.boundary_vertices), (nn + 1) * (nn + 1) * (nn + 1) - (nn - 1) * (nn - 1) * (nn - 1));
    expect_tetrahedral_relations(c, 1);
  }
}

TEST(EulerRelations, CavityAndThroughHole3D) {
  // A cube with an inner cubic cavity: chi = 2 (the boundary is two spheres).
  const MeshCounts cavity = count_mesh(testing::kuhn_grid3(3, 3, 3, {Cell3{1, 1, 1}}));
  EXPECT_EQ(cavity.boundary_components, 2u);
  EXPECT_EQ(cavity.holes, 1u);
  EXPECT_EQ(cavity.boundary_faces, 12u * 9 + 12);
  expect_tetrahedral_relations(cavity, 2);
  // A cube with a square tunnel through it: a solid torus, chi = 0.
  const MeshCounts tunnel = count_mesh(testing::kuhn_grid3(3, 3, 3, {Cell3{1, 1, 0}, Cell3{1, 1, 1}, Cell3{1, 1, 2}}));
  EXPECT_EQ(tunnel.boundary_components, 1u);
  expect_tetrahedral_relations(tunnel, 0);
}

// Closed surfaces of genus g: Nf = 2Nv + 4g - 4, and every edge has two triangles.
void expect_closed_surface(const MeshCounts& c, I genus) {
  EXPECT_EQ(I(c.triangles), 2 * I(c.vertices) + 4 * genus - 4);
  EXPECT_EQ(2 * I(c.edges), 3 * I(c.triangles));
  EXPECT_EQ(c.boundary_edges, 0u);
  EXPECT_EQ(c.holes, 0u);
  EXPECT_EQ(c.components, 1u);
}

TEST(EulerRelations, ClosedSurfaces) {
  expect_closed_surface(count_mesh(testing::boundary_surface(testing::kuhn_grid3(2, 3, 4))), 0);
  expect_closed_surface(count_mesh(testing::torus(4, 5)), 1);
  expect_closed_surface(count_mesh(testing::boundary_surface(testing::kuhn_grid3(
                            3, 3, 3, {Cell3{1, 1, 0}, Cell3{1, 1, 1}, Cell3{1, 1, 2}}))),
                        1);
}

TEST(EulerRelations, OpenSurfaceHasItsBoundaryLoopsAsHoles) {
  // The boundary of a cube with one face's two triangles taken away: a disk, one loop.
  SurfaceMesh3 closed = testing::boundary_surface(testing::kuhn_grid3(1, 1, 1));
  int removed = 0;
  for (std::uint32_t e = 0; e < closed.element_slot_count() && removed < 2; ++e) {
    const auto v = closed.vertices(ElementId{e});
    bool bottom = true;
    for (const VertexId w : v) bottom = bottom && closed.point(w)[2] == 0.0;
    if (bottom) {
      closed.remove_element(ElementId{e});
      ++removed;
    }
  }
  ASSERT_EQ(removed, 2);
  const MeshCounts c = count_mesh(closed);
  EXPECT_EQ(c.holes, 1u);
  EXPECT_EQ(c.boundary_edges, 4u);
  EXPECT_EQ(c.euler_characteristic(), 1) << "a disk";
}

}  // namespace
}  // namespace certimesh::topology
