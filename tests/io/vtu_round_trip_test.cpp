// VTK .vtu: lossless round trips, and reading files other writers made (data/vtu, written by
// meshio 5.0.0 and in VTK's binary layout by make_meshio_files.py), checked against the literal
// mesh that script describes.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "certimesh/io/format_error.h"
#include "certimesh/io/mesh_file.h"
#include "certimesh/io/vtu_format.h"
#include "gmsh_vtu_test_meshes.h"

namespace certimesh::testing {
namespace {

const std::filesystem::path kData = std::filesystem::path(CERTIMESH_TEST_DATA_DIR) / "data" / "vtu";

RC_GTEST_PROP(VtuRoundTrip, WriteThenReadIsLossless, ()) {
  const io::MeshData mesh = *arbitrary_mesh();
  const io::MeshData back = io::parse_vtu_format("generated.vtu", io::format_vtu(mesh));
  const io::MeshData expected = with_zero_labels_dropped(mesh);  // dimension kept: certimesh_dimension
  RC_ASSERT(back == expected);
  RC_ASSERT(same_bits(back.coordinates, expected.coordinates));
}

TEST(VtuRoundTrip, ThroughAFileBothDimensions) {
  io::MeshData planar;  // a planar surface mesh in 3D keeps dimension 3 (unlike .msh)
  planar.dimension = 3;
  planar.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, -0.0, 5e-324, 0};
  planar.triangles = {0, 1, 2, 1, 3, 2};
  planar.triangle_labels = {4, -4};
  planar.segments = {0, 1};
  io::MeshData flat = planar;
  flat.dimension = 2;
  flat.coordinates = {0, 0, 1, 0, 0, 1, -0.0, 5e-324};
  flat.point_labels = {0, 0, 1, 0};
  for (const io::MeshData& mesh : {planar, flat}) {
    const auto path = std::filesystem::path(::testing::TempDir()) / "certimesh_vtu_round_trip.vtu";
    io::write_mesh(mesh, path);
    const io::MeshData back = io::read_mesh(path);
    EXPECT_EQ(back, mesh);
    EXPECT_TRUE(same_bits(back.coordinates, mesh.coordinates));
    std::filesystem::remove(path);
  }
}

// The mesh of make_meshio_files.py.
io::MeshData script_mesh() {
  io::MeshData m;
  m.dimension = 3;
  m.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0.1, 0.2, 1e-300};
  m.point_labels = {1, 2, 3, 4};
  m.triangles = {0, 1, 2};
  m.triangle_labels = {-3};
  m.tetrahedra = {0, 1, 2, 3};
  m.tetrahedron_labels = {7};
  return m;
}

TEST(VtuReadsOthers, MeshioBinaryUncompressed) {
  const io::MeshData m = io::read_mesh(kData / "meshio_binary.vtu");
  EXPECT_EQ(m, script_mesh());
  EXPECT_TRUE(same_bits(m.coordinates, script_mesh().coordinates));
}

TEST(VtuReadsOthers, VtkStyleBinaryWithSeparateUInt64Header) {
  const io::MeshData m = io::read_mesh(kData / "vtk_style_binary_uint64.vtu");
  EXPECT_EQ(m, script_mesh());
  EXPECT_TRUE(same_bits(m.coordinates, script_mesh().coordinates));
}

TEST(VtuReadsOthers, MeshioAscii) {
  // meshio's ASCII keeps 12 significant digits: 0.1, 0.2 and 1e-300 survive (they are the
  // doubles nearest their 12-digit decimals).
  const io::MeshData m = io::read_mesh(kData / "meshio_ascii.vtu");
  EXPECT_EQ(m, script_mesh());
}

TEST(VtuReadsOthers, MeshioDefaultZlibCompressed) {
  const io::MeshData m = io::read_mesh(kData / "meshio_binary_zlib.vtu");
  EXPECT_EQ(m, script_mesh());
  EXPECT_TRUE(same_bits(m.coordinates, script_mesh().coordinates));
}

TEST(VtuReadsOthers, OtherCompressorsAreRefusedWithTheReason) {
  try {
    (void)io::read_mesh(kData / "meshio_binary_lzma.vtu");
    ADD_FAILURE() << "accepted an LZMA-compressed file";
  } catch (const io::FormatError& e) {
    EXPECT_EQ(e.line(), 7u) << e.what();  // the first DataArray
    EXPECT_NE(e.why().find("compressor 'vtkLZMADataCompressor' is not supported"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace certimesh::testing
