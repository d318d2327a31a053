// Medit .mesh: MeshData -> write -> read gives the same MeshData bit for bit (generated meshes,
// 2D and 3D, labels kept), and hand-made files read as the MeshData written out by hand below.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <filesystem>

#include "certimesh/io/format_error.h"
#include "certimesh/io/medit_format.h"
#include "certimesh/io/mesh_file.h"
#include "text_format_support.h"

namespace certimesh::io {
namespace {

namespace fs = std::filesystem;
using testing::identical;

const fs::path kData = fs::path(CERTIMESH_TEST_DATA_DIR) / "data" / "medit";

RC_GTEST_PROP(MeditRoundTrip, InMemory, ()) {
  const MeshData mesh = *testing::mesh_of(*rc::gen::element(2, 3));
  RC_ASSERT(identical(parse_medit_format("m.mesh", format_medit(mesh)), mesh));
}

RC_GTEST_PROP(MeditRoundTrip, ThroughAFile, ()) {
  const MeshData mesh = *testing::mesh_of(*rc::gen::element(2, 3));
  static const testing::ScratchFolder folder("medit");
  write_mesh(mesh, folder.path() / "m.mesh");
  RC_ASSERT(identical(read_mesh(folder.path() / "m.mesh"), mesh));
}

TEST(MeditRoundTrip, SignedZeroAndExtremesKeepTheirBits) {
  MeshData mesh;
  mesh.dimension = 3;
  mesh.coordinates = {-0.0, 0.0, 5e-324, -1.7976931348623157e308, 1e-300, -1e300};
  const MeshData back = parse_medit_format("z.mesh", format_medit(mesh));
  EXPECT_TRUE(std::signbit(back.coordinates[0]));
  EXPECT_FALSE(std::signbit(back.coordinates[1]));
  EXPECT_TRUE(identical(back, mesh));
}

TEST(MeditRead, SquareSkippingKeywordsItDoesNotHold) {
  MeshData expected;
  expected.dimension = 2;
  expected.coordinates = {0, 0, 1, 0, 1, 1, 0, 1};
  expected.point_labels = {1, 1, 0, 2};
  expected.segments = {0, 1, 2, 3};
  expected.segment_labels = {5, 0};
  expected.triangles = {0, 1, 2, 0, 2, 3};
  expected.triangle_labels = {3, -4};
  EXPECT_EQ(read_mesh(kData / "square.mesh"), expected);
}

TEST(MeditRead, TetrahedronWithBoundaryTriangles) {
  MeshData expected;
  expected.dimension = 3;
  expected.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  expected.point_labels = {0, 0, 0, 3};
  expected.triangles = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  expected.triangle_labels = {1, 2, 3, 4};
  expected.tetrahedra = {0, 1, 2, 3};
  expected.tetrahedron_labels = {7};
  EXPECT_EQ(read_mesh(kData / "tet.mesh"), expected);
}

TEST(MeditRead, AllZeroReferencesReadAsNoLabels) {
  const MeshData mesh = parse_medit_format(
      "z.mesh", "MeshVersionFormatted 2 Dimension 2 Vertices 3 0 0 0 1 0 0 0 1 0 "
                "Triangles 1 1 2 3 0 End");
  EXPECT_TRUE(mesh.point_labels.empty());
  EXPECT_TRUE(mesh.triangle_labels.empty());
  EXPECT_EQ(mesh.triangles, (std::vector<Index>{0, 1, 2}));
}

TEST(MeditWrite, RefusesHolesAndNonFiniteCoordinates) {
  MeshData domain;
  domain.coordinates = {0, 0};
  domain.holes = {0.5, 0.5};
  EXPECT_THROW(format_medit(domain), FormatError);
  MeshData nan;
  nan.coordinates = {0, std::numeric_limits<double>::infinity()};
  EXPECT_THROW(format_medit(nan), FormatError);
}

}  // namespace
}  // namespace certimesh::io
