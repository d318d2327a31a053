// Unit tests of the certificate's conditions 1-5 on small hand-built meshes: each mesh is
// valid or broken in exactly one way, and the report must name that defect and where.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "certimesh/certificate/check_mesh.h"
#include "unit_meshes.h"

namespace certimesh::certificate::test {
namespace {

Report expect_defect(const MeshData& m, Defect defect) {
  const Report r = check_mesh(m);
  EXPECT_EQ(defect_name(r.finding.defect), defect_name(defect)) << r.finding.message;
  EXPECT_EQ(r.valid, defect == Defect::none);
  return r;
}

TEST(CertificateUnit, ValidGrids) {
  const Report r2 = expect_defect(square_grid(4), Defect::none);
  EXPECT_EQ(r2.statistics.elements, 32u);
  EXPECT_EQ(r2.statistics.boundary_facets, 16u);
  EXPECT_EQ(r2.statistics.interior_facets, (3u * 32u - 16u) / 2u);
  EXPECT_EQ(r2.statistics.boundary_components, 1u);
  const Report r3 = expect_defect(kuhn_grid(3), Defect::none);
  EXPECT_EQ(r3.statistics.elements, 162u);
  EXPECT_EQ(r3.statistics.boundary_facets, 6u * 9u * 2u);
  EXPECT_EQ(r3.statistics.interior_facets, (4u * 162u - 108u) / 2u);
}

TEST(CertificateUnit, ValidWithCavity) {  // the winding check must accept a hole
  const Report r2 = expect_defect(square_grid(3, [](int i, int j) { return i == 1 && j == 1; }), Defect::none);
  EXPECT_EQ(r2.statistics.boundary_components, 2u);
  const Report r3 = expect_defect(kuhn_grid(3, [](int i, int j, int k) { return i == 1 && j == 1 && k == 1; }),
                                  Defect::none);
  EXPECT_EQ(r3.statistics.boundary_components, 2u);
}

TEST(CertificateUnit, ValidIslandInCavity) {  // a meshed island inside a hole: W stays 0 or 1
  MeshData m = square_grid(5, [](int i, int j) { return i >= 1 && i <= 3 && j >= 1 && j <= 3 && !(i == 2 && j == 2); });
  const Report r = expect_defect(m, Defect::none);
  EXPECT_EQ(r.statistics.boundary_components, 3u);
}

TEST(CertificateUnit, QualityOfRightTriangles) {  // 12√3·(1/2)/(2+√2)² by hand
  const Report r = expect_defect(square_grid(2), Defect::none);
  EXPECT_NEAR(r.statistics.worst_quality, 6.0 * std::sqrt(3.0) / ((2 + std::sqrt(2.0)) * (2 + std::sqrt(2.0))), 1e-12);
}

TEST(CertificateUnit, InputDefects) {
  expect_defect(MeshData{}, Defect::no_elements);
  MeshData m = square_grid(2);
  m.triangles[4] = 99;
  EXPECT_EQ(expect_defect(m, Defect::index_out_of_range).finding.element, 1);
  m = square_grid(2);
  m.coordinates[7] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(expect_defect(m, Defect::non_finite_coordinate).finding.vertex, 3);
  m = square_grid(2);
  append(m.coordinates, {1.0, 2.0});  // same point as vertex 7
  const Report dup = expect_defect(m, Defect::duplicate_vertex);
  EXPECT_EQ(dup.finding.vertex, 9);
  EXPECT_EQ(dup.finding.other, 7);
  m = square_grid(2);
  append(m.coordinates, {5.0, 5.0});
  EXPECT_EQ(expect_defect(m, Defect::unused_vertex).finding.vertex, 9);
  m = square_grid(2);
  m.triangles[2] = m.triangles[1];
  EXPECT_EQ(expect_defect(m, Defect::repeated_vertex).finding.element, 0);
  m = square_grid(2);
  append(m.triangles, {m.triangles[3], m.triangles[4], m.triangles[5]});
  const Report same = expect_defect(m, Defect::duplicate_element);
  EXPECT_EQ(same.finding.element, 8);
  EXPECT_EQ(same.finding.other, 1);
}

TEST(CertificateUnit, CombinatorialDefects2D) {
  MeshData m = square_grid(1);
  append(m.coordinates, {3.0, -1.0});  // third triangle on the diagonal 0-3
  append(m.triangles, {0, 4, 3});
  EXPECT_EQ(expect_defect(m, Defect::non_manifold_facet).finding.element, 2);
  m = square_grid(2);
  std::swap(m.triangles[0], m.triangles[1]);  // triangle 0 listed clockwise
  const Report r = expect_defect(m, Defect::inconsistent_orientation);
  EXPECT_TRUE(r.finding.element == 0 || r.finding.other == 0);
}

TEST(CertificateUnit, CombinatorialDefects3D) {
  MeshData m = kuhn_grid(1);
  std::swap(m.tetrahedra[4 * 3 + 2], m.tetrahedra[4 * 3 + 3]);
  const Report r = expect_defect(m, Defect::inconsistent_orientation);
  EXPECT_TRUE(r.finding.element == 3 || r.finding.other == 3);
  m = kuhn_grid(1);  // a seventh tetrahedron on the interior face (0, 7, 1), apex outside
  append(m.coordinates, {3.0, -2.0, 0.5});
  append(m.tetrahedra, {0, 1, 7, 8});
  expect_defect(m, Defect::non_manifold_facet);
}

TEST(CertificateUnit, OrientationDefects) {
  EXPECT_EQ(expect_defect(simplices(2, {{0, 0, 1, 0, 2, 0}}), Defect::flat_element).finding.element, 0);
  EXPECT_EQ(expect_defect(simplices(2, {{0, 0, 1, 0, 0, 1}, {5, 0, 5, 1, 6, 0}}), Defect::inverted_element).finding.element, 1);
  expect_defect(simplices(3, {{0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}}), Defect::flat_element);
  expect_defect(simplices(3, {{0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1}}), Defect::inverted_element);
}

// Parts sharing only a vertex are a valid pinch (design decision 8); a part nested inside
// another at the shared vertex (2D) or edge (3D) is not: the boundary facets around it do not
// alternate between the two orientations.
TEST(CertificateUnit, PinchedBoundary) {
  MeshData bowtie = simplices(2, {{0, 0, 1, 0, 1, 1}, {-1, 0, -1, -1, 0.5, 0.5}});
  bowtie.coordinates.resize(10);  // element 1 reuses vertex 0 instead of its own (0.5, 0.5)
  bowtie.triangles[5] = 0;
  EXPECT_TRUE(check_mesh(bowtie).valid);
  MeshData tets;  // two tetrahedra sharing only vertex 0
  tets.dimension = 3;
  tets.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, 0, -1, 0, -1, 0};
  tets.tetrahedra = {0, 1, 2, 3, 0, 4, 5, 6};
  EXPECT_EQ(det3(tets, &tets.tetrahedra[4]), 1.0);
  EXPECT_TRUE(check_mesh(tets).valid);
  MeshData nested;  // a triangle inside another, sharing vertex 0
  nested.dimension = 2;
  nested.coordinates = {0, 0, 4, 0, 0, 4, 2, 1, 1, 2};
  nested.triangles = {0, 1, 2, 0, 3, 4};
  ASSERT_GT(det2(nested, &nested.triangles[3]), 0);
  EXPECT_EQ(expect_defect(nested, Defect::non_manifold_boundary).finding.vertex, 0);
  MeshData book = simplices(3, {{0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4}});  // and one inside it on edge 0-1
  append(book.coordinates, {1, 1, 0.5, 1, 0.5, 1});
  append(book.tetrahedra, {0, 1, 4, 5});
  ASSERT_GT(det3(book, &book.tetrahedra[4]), 0);
  EXPECT_EQ(expect_defect(book, Defect::non_manifold_boundary).finding.vertex, 0);
}

TEST(CertificateUnit, TJunctionAndCrossing) {
  const Report t2 = expect_defect(simplices(2, {{0, 0, 2, 0, 1, 1}, {1, 0, 0, -1, 2, -1}}), Defect::t_junction);
  EXPECT_EQ(t2.finding.vertex, 3);
  EXPECT_EQ(t2.finding.element, 0);
  expect_defect(simplices(2, {{0, 0, 2, 0, 0, 2}, {0.5, 0.5, 2.5, 0.5, 0.5, 2.5}}), Defect::boundary_intersection);
  const Report t3 = expect_defect(
      simplices(3, {{0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4}, {1, 1, 0, 1, 2, -1, 2, 1, -1, 1, 1, -2}}), Defect::t_junction);
  EXPECT_EQ(t3.finding.vertex, 4);
  expect_defect(simplices(3, {{0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4}, {1, 1, 1, 5, 1, 1, 1, 5, 1, 1, 1, 5}}),
                Defect::boundary_intersection);
}

TEST(CertificateUnit, NestedCopiesAreMultipleCovers) {
  const Report r2 = expect_defect(simplices(2, {{0, 0, 10, 0, 0, 10}, {1, 1, 2, 1, 1, 2}}), Defect::multiple_cover);
  EXPECT_EQ(r2.finding.vertex, 3);
  expect_defect(simplices(3, {{0, 0, 0, 10, 0, 0, 0, 10, 0, 0, 0, 10}, {1, 1, 1, 2, 1, 1, 1, 2, 1, 1, 1, 2}}),
                Defect::multiple_cover);
  // A meshed square inside the cavity of a meshed annulus is fine (ValidIslandInCavity);
  // inside the annulus' material it is a double cover.
  MeshData m = square_grid(5);
  const MeshData island = simplices(2, {{1.25, 1.25, 1.75, 1.25, 1.5, 1.75}});
  for (double x : island.coordinates) m.coordinates.push_back(x);
  append(m.triangles, {36, 37, 38});
  expect_defect(m, Defect::multiple_cover);
}

TEST(CertificateUnit, SameMeshSameJson) {
  const MeshData m = kuhn_grid(2);
  const std::string a = certificate_json(check_mesh(m), "test"), b = certificate_json(check_mesh(m), "test");
  EXPECT_EQ(a, b);
  EXPECT_NE(a.find("\"valid\": true"), std::string::npos);
  MeshData moved = m;
  moved.coordinates[0] = -0.0;  // same geometry, different bytes: the hash must see it
  EXPECT_NE(check_mesh(moved).mesh_sha256, check_mesh(m).mesh_sha256);
  EXPECT_EQ(check_mesh(m).mesh_sha256.size(), 64u);
}

// The canonical form documented in proofs/mesh_certificate.md, hashed independently with
// Python's struct + hashlib: the expected value is not produced by the code under test.
TEST(CertificateUnit, HashOfTheDocumentedExample) {
  MeshData m;
  m.dimension = 3;
  m.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 1, 1};
  m.tetrahedra = {0, 1, 2, 3, 1, 4, 2, 3};
  m.tetrahedron_labels = {1, 1};
  EXPECT_EQ(check_mesh(m).mesh_sha256, "fd1fc435cd464869e34e80fd9e1ccd474aaff7d8500074cb993a3ae852a26722");
}

}  // namespace
}  // namespace certimesh::certificate::test
