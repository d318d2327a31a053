// Conversion between io::MeshData and the mesh model: a file read by io/ becomes a mesh with
// its labels, round trips keep everything, boundary facets come out outward, and what the
// model cannot hold (a third element on a facet, an index out of range, a labelled facet that
// is no facet of the mesh, the wrong dimension) is an error value naming the item.
#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <set>
#include <string>

#include <unistd.h>

#include "certimesh/io/mesh_file.h"
#include "certimesh/topology/mesh_counts.h"
#include "certimesh/topology/mesh_data_conversion.h"
#include "fixtures.h"

namespace certimesh::topology {
namespace {

const std::filesystem::path data_dir = std::filesystem::path(CERTIMESH_TEST_DATA_DIR) / "data";

TEST(MeshDataConversion, ReadsFigure25FromAMeditFileWithLabels) {
  const io::MeshData data = io::read_mesh(data_dir / "square_with_hole.mesh");
  const auto result = from_mesh_data<TriangleMesh2>(data);
  ASSERT_TRUE(result.ok()) << result.error->message;
  const TriangleMesh2& mesh = *result.mesh;
  const MeshCounts c = count_mesh(mesh);
  EXPECT_EQ(c.vertices, 8u);
  EXPECT_EQ(c.edges, 16u);
  EXPECT_EQ(c.holes, 1u);
  // Labels as written in the file (1-based there, 0-based here).
  EXPECT_EQ(mesh.label(ElementId{0}), 10);
  EXPECT_EQ(mesh.label(ElementId{7}), 20);
  EXPECT_EQ(mesh.facet_label({VertexId{0}, VertexId{1}}), 1);
  EXPECT_EQ(mesh.facet_label({VertexId{5}, VertexId{4}}), 2);
  // Triangle 0 is (0, 1, 5): across (1, 5) lies triangle 3 = (1, 6, 5), across (5, 0)
  // triangle 1 = (0, 5, 4), and (0, 1) is on the outer square.
  EXPECT_EQ(mesh.neighbour(ElementId{0}, 0), ElementId{3});
  EXPECT_EQ(mesh.neighbour(ElementId{0}, 1), ElementId{1});
  EXPECT_EQ(mesh.neighbour(ElementId{0}, 2), no_element) << "facet (0, 1) lies on the outer square";
}

// Twice the signed area enclosed by the segments (shoelace sum): equals twice the mesh area
// exactly when every boundary segment has the domain on its left (outward orientation).
double twice_area_enclosed(const io::MeshData& d) {
  double sum = 0.0;
  for (std::size_t s = 0; s < d.segment_count(); ++s) {
    const std::size_t a = d.segments[2 * s], b = d.segments[2 * s + 1];
    sum += d.coordinates[2 * a] * d.coordinates[2 * b + 1] - d.coordinates[2 * b] * d.coordinates[2 * a + 1];
  }
  return sum;
}

TEST(MeshDataConversion, RoundTripKeepsEverythingAndWritesBoundaryOutward) {
  TriangleMesh2 grid = testing::grid2(5, 4, {testing::Cell2{2, 1}});
  grid.set_label(ElementId{3}, 42);
  grid.set_facet_label(grid.facet(ElementId{0}, 2), 7);  // on y = 0, the outer boundary
  grid.set_facet_label(grid.facet(ElementId{0}, 1), 9);  // the interior diagonal of cell (0, 0)
  const io::MeshData data = to_mesh_data(grid);
  EXPECT_EQ(data.triangle_count(), grid.element_count());
  EXPECT_EQ(data.segment_count(), 18u + 4 + 1) << "18 outer + 4 hole boundary edges + 1 labelled interior";
  // The boundary segments alone enclose the 5 x 4 grid minus its 1 x 1 hole; the labelled
  // interior segment is taken out first.
  io::MeshData boundary = data;
  for (std::size_t s = 0; s < boundary.segment_count(); ++s)
    if (boundary.segment_labels[s] == 9) {
      boundary.segments.erase(boundary.segments.begin() + static_cast<std::ptrdiff_t>(2 * s),
                              boundary.segments.begin() + static_cast<std::ptrdiff_t>(2 * s + 2));
      break;
    }
  EXPECT_EQ(twice_area_enclosed(boundary), 2.0 * (20 - 1));

  const auto back = from_mesh_data<TriangleMesh2>(data);
  ASSERT_TRUE(back.ok()) << back.error->message;
  EXPECT_EQ(to_mesh_data(*back.mesh), data) << "a second round trip changes nothing";
  EXPECT_EQ(back.mesh->label(ElementId{3}), 42);
  EXPECT_EQ(back.mesh->facet_label(back.mesh->facet(ElementId{0}, 1)), 9);
}

TEST(MeshDataConversion, TetrahedralRoundTripCompactsFreedSlots) {
  TetrahedralMesh3 mesh = testing::kuhn_grid3(2, 2, 2);
  mesh.remove_element(ElementId{5});
  const io::MeshData data = to_mesh_data(mesh);
  EXPECT_EQ(data.tetrahedron_count(), 47u);
  const auto back = from_mesh_data<TetrahedralMesh3>(data);
  ASSERT_TRUE(back.ok()) << back.error->message;
  const MeshCounts before = count_mesh(mesh), after = count_mesh(*back.mesh);
  EXPECT_EQ(after.boundary_faces, before.boundary_faces);
  EXPECT_EQ(after.edges, before.edges);
  EXPECT_EQ(data.triangle_count(), before.boundary_faces);
}

// What a tetrahedral mesh says, independent of how a file orders or numbers things: each
// element as its vertices' coordinates in order (orientation kept) with its label, each
// boundary facet as its sorted vertex coordinates with its label, and the counts.
struct TetrahedralContent {
  std::multiset<std::pair<std::vector<double>, Label>> elements;
  std::multiset<std::pair<std::vector<double>, Label>> boundary;
  std::size_t interior_faces = 0;
  bool operator==(const TetrahedralContent&) const = default;
};

TetrahedralContent content_of(const TetrahedralMesh3& mesh) {
  TetrahedralContent c;
  for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e) {
    if (!mesh.is_live(ElementId{e})) continue;
    std::vector<double> xyz;
    for (const VertexId v : mesh.vertices(ElementId{e}))
      for (const double x : mesh.point(v)) xyz.push_back(x);
    c.elements.emplace(xyz, mesh.label(ElementId{e}));
  }
  for (const FacetRecord& f : extract_facets(mesh)) {
    if (!f.boundary()) {
      ++c.interior_faces;
      continue;
    }
    const auto facet = mesh.facet(f.element, f.local);
    std::vector<std::array<double, 3>> points;
    for (const VertexId v : facet) points.push_back(mesh.point(v));
    std::sort(points.begin(), points.end());
    std::vector<double> xyz;
    for (const auto& p : points) xyz.insert(xyz.end(), p.begin(), p.end());
    c.boundary.emplace(xyz, mesh.facet_label(facet));
  }
  return c;
}

// Through the file formats: a labelled tetrahedral mesh written by io/ (Medit, Gmsh) and read
// back is the same mesh (Gmsh files group elements by label, so order may change).
TEST(MeshDataConversion, TetrahedralMeshSurvivesMeditAndGmshFiles) {
  TetrahedralMesh3 mesh = testing::kuhn_grid3(2, 2, 2);
  for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e) mesh.set_label(ElementId{e}, Label(1 + e % 3));
  for (const FacetRecord& f : extract_facets(mesh))
    if (f.boundary()) mesh.set_facet_label(mesh.facet(f.element, f.local), Label(10 + f.element.value % 5));
  const TetrahedralContent expected = content_of(mesh);
  const io::MeshData data = to_mesh_data(mesh);
  // Per process: two build trees may run the suite at once.
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("certimesh_topology_test_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  for (const char* name : {"grid.mesh", "grid.msh"}) {
    SCOPED_TRACE(name);
    io::write_mesh(data, dir / name);
    const auto back = from_mesh_data<TetrahedralMesh3>(io::read_mesh(dir / name));
    ASSERT_TRUE(back.ok()) << back.error->message;
    EXPECT_TRUE(content_of(*back.mesh) == expected);
  }
  std::filesystem::remove_all(dir);
}

io::MeshData three_triangles_on_one_edge() {
  io::MeshData d;
  d.dimension = 2;
  d.coordinates = {0, 0, 1, 0, 0, 1, 0, -1, 1, 1};
  d.triangles = {0, 1, 2, 1, 0, 3, 0, 1, 4};
  return d;
}

TEST(MeshDataConversion, ErrorsNameTheProblemAndTheItem) {
  const auto non_manifold = from_mesh_data<TriangleMesh2>(three_triangles_on_one_edge());
  ASSERT_FALSE(non_manifold.ok());
  EXPECT_EQ(non_manifold.error->kind, ConversionError::Kind::non_manifold_facet);
  EXPECT_EQ(non_manifold.error->item, 2u);
  EXPECT_NE(non_manifold.error->message.find("triangle 2"), std::string::npos) << non_manifold.error->message;

  io::MeshData out_of_range = three_triangles_on_one_edge();
  out_of_range.triangles[4] = 5;
  const auto range = from_mesh_data<TriangleMesh2>(out_of_range);
  ASSERT_FALSE(range.ok());
  EXPECT_EQ(range.error->kind, ConversionError::Kind::vertex_out_of_range);
  EXPECT_EQ(range.error->item, 1u);

  io::MeshData repeated = three_triangles_on_one_edge();
  repeated.triangles[2] = 0;
  EXPECT_EQ(from_mesh_data<TriangleMesh2>(repeated).error->kind, ConversionError::Kind::repeated_vertex);

  io::MeshData stray_segment = three_triangles_on_one_edge();
  stray_segment.triangles.resize(6);
  stray_segment.segments = {0, 1, 2, 3};  // (0,1) is an edge; (2,3) is not
  const auto stray = from_mesh_data<TriangleMesh2>(stray_segment);
  ASSERT_FALSE(stray.ok());
  EXPECT_EQ(stray.error->kind, ConversionError::Kind::labelled_facet_not_in_mesh);
  EXPECT_EQ(stray.error->item, 1u);

  EXPECT_EQ(from_mesh_data<TetrahedralMesh3>(three_triangles_on_one_edge()).error->kind,
            ConversionError::Kind::wrong_dimension);

  io::MeshData three_tets_on_one_face;
  three_tets_on_one_face.dimension = 3;
  three_tets_on_one_face.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, -1, 1, 1, 1};
  three_tets_on_one_face.tetrahedra = {0, 1, 2, 3, 0, 2, 1, 4, 0, 1, 2, 5};
  const auto tets = from_mesh_data<TetrahedralMesh3>(three_tets_on_one_face);
  ASSERT_FALSE(tets.ok());
  EXPECT_EQ(tets.error->kind, ConversionError::Kind::non_manifold_facet);
  EXPECT_EQ(tets.error->item, 2u);
  EXPECT_NE(tets.error->message.find("tetrahedron 2"), std::string::npos) << tets.error->message;
}

}  // namespace
}  // namespace certimesh::topology
