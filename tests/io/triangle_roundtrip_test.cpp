// Triangle/TetGen files: MeshData -> write -> read gives the same MeshData bit for bit
// (generated meshes and domains, 2D and 3D, labels kept), and hand-made files read as the
// MeshData written out by hand below (the independent oracle for the reader).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include "certimesh/io/format_error.h"
#include "certimesh/io/mesh_file.h"
#include "certimesh/io/triangle_format.h"
#include "text_format_support.h"

namespace certimesh::io {
namespace {

namespace fs = std::filesystem;
using testing::identical;

const fs::path kData = fs::path(CERTIMESH_TEST_DATA_DIR) / "data" / "triangle";

const fs::path& folder() {
  static const testing::ScratchFolder scratch("triangle");
  return scratch.path();
}

RC_GTEST_PROP(TriangleRoundTrip, MeshThroughNodeAndEle2D, ()) {
  const MeshData mesh = *testing::mesh_of(2);
  const fs::path path = folder() / "m2.node";
  fs::remove(folder() / "m2.edge");
  write_triangle_format(mesh, path);
  RC_ASSERT(identical(read_triangle_format(path), mesh));
  RC_ASSERT(identical(read_mesh(folder() / "m2.ele"), mesh));
}

RC_GTEST_PROP(TriangleRoundTrip, MeshThroughNodeEleFaceEdge3D, ()) {
  const MeshData mesh = *testing::mesh_of(3);
  const fs::path path = folder() / "m3.ele";
  fs::remove(folder() / "m3.edge");
  fs::remove(folder() / "m3.face");
  write_triangle_format(mesh, path);
  RC_ASSERT(identical(read_triangle_format(path), mesh));
  RC_ASSERT(identical(read_mesh(folder() / "m3.node"), mesh));
}

RC_GTEST_PROP(TriangleRoundTrip, DomainThroughPoly, ()) {
  const int dimension = *rc::gen::element(2, 3);
  const MeshData domain = *testing::domain_of(dimension);
  const fs::path path = folder() / "d.poly";
  write_mesh(domain, path);
  RC_ASSERT(identical(read_mesh(path), domain));
}

TEST(TriangleRoundTrip, StaleCompanionIsOverwritten) {
  // Writing X.node for a mesh without segments over an X.edge left by an earlier mesh: X
  // must read back as the mesh just written, not pick up the old segments.
  MeshData with_segments;
  with_segments.coordinates = {0, 0, 1, 0, 0, 1};
  with_segments.triangles = {0, 1, 2};
  with_segments.segments = {0, 1};
  MeshData without = with_segments;
  without.segments.clear();
  const fs::path path = folder() / "stale.node";
  write_triangle_format(with_segments, path);
  write_triangle_format(without, path);
  EXPECT_EQ(read_triangle_format(path), without);
}

TEST(TriangleRoundTrip, SignedZeroAndExtremesKeepTheirBits) {
  MeshData mesh;
  mesh.coordinates = {-0.0, 0.0, 5e-324, -1.7976931348623157e308, 1e-300, -1e300};
  const fs::path path = folder() / "zero.node";
  write_triangle_format(mesh, path);
  const MeshData back = read_triangle_format(path);
  EXPECT_TRUE(std::signbit(back.coordinates[0]));
  EXPECT_FALSE(std::signbit(back.coordinates[1]));
  EXPECT_TRUE(identical(back, mesh));
}

TEST(TriangleRoundTrip, RealElementAttributesAndRegionAreas) {
  // Triangle's regional attributes are reals: a 2D .ele keeps them beside empty labels, and
  // writes them back; a .poly region's maximum area survives the round trip.
  MeshData mesh;
  mesh.coordinates = {0, 0, 1, 0, 1, 1, 0, 1};
  mesh.triangles = {0, 1, 2, 0, 2, 3};
  mesh.triangle_attributes = {0.05, 2.5};
  mesh.triangle_labels = {1, 2};  // each distinct attribute's rank, for the integer-only formats
  const fs::path path = folder() / "real.ele";
  write_triangle_format(mesh, path);
  std::ifstream ele(path);
  const std::string text((std::istreambuf_iterator<char>(ele)), std::istreambuf_iterator<char>());
  EXPECT_EQ(text, "2 3 1\n1 1 2 3 0.05\n2 1 3 4 2.5\n");  // Triangle's layout, by hand
  EXPECT_TRUE(identical(read_triangle_format(path), mesh));
  mesh.triangle_attributes = {3.0, -2.0};  // integers: labels, as before
  mesh.triangle_labels.clear();
  write_triangle_format(mesh, path);
  MeshData labelled = mesh;
  labelled.triangle_attributes.clear();
  labelled.triangle_labels = {3, -2};
  EXPECT_EQ(read_triangle_format(path), labelled);
  MeshData domain;
  domain.coordinates = {0, 0, 1, 0, 0, 1};
  domain.segments = {0, 1, 1, 2, 2, 0};
  domain.region_points = {0.25, 0.25, 0.5, 0.125};
  domain.region_attributes = {0.05, 7};
  domain.region_max_measures = {0.01, -1};
  const fs::path poly = folder() / "areas.poly";
  write_mesh(domain, poly);
  EXPECT_EQ(read_mesh(poly), domain);
}

TEST(TriangleRead, ZeroBasedSquareWithAttributesMarkersAndEdges) {
  MeshData expected;
  expected.dimension = 2;
  expected.coordinates = {0, 0, 1, 0, 1, 1, 0.5, 1};
  expected.point_labels = {1, 1, 0, 2};
  expected.triangles = {0, 1, 2, 0, 2, 3};
  expected.triangle_labels = {3, -4};
  expected.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  expected.segment_labels = {5, 5, 0, 6};
  EXPECT_EQ(read_mesh(kData / "square0.ele"), expected);
  EXPECT_EQ(read_mesh(kData / "square0.node"), expected);
}

TEST(TriangleRead, TetGenTetrahedronWithFaces) {
  MeshData expected;
  expected.dimension = 3;
  expected.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  expected.tetrahedra = {0, 1, 2, 3};
  expected.tetrahedron_labels = {7};
  expected.triangles = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  expected.triangle_labels = {1, 2, 3, 4};
  EXPECT_EQ(read_mesh(kData / "tet.ele"), expected);
  EXPECT_EQ(read_mesh(kData / "tet.face"), expected);
}

TEST(TriangleRead, PolyWithHoleAndRegion) {
  MeshData expected;
  expected.dimension = 2;
  expected.coordinates = {0, 0, 4, 0, 4, 4, 0, 4, 1, 1, 3, 1, 3, 3, 1, 3};
  expected.point_labels = {1, 1, 1, 1, 2, 2, 2, 2};
  expected.segments = {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4};
  expected.segment_labels = {1, 1, 1, 1, 2, 2, 2, 2};
  expected.holes = {2, 2};
  expected.region_points = {0.5, 0.5};
  expected.region_attributes = {10};
  expected.region_max_measures = {0.1};
  EXPECT_EQ(read_mesh(kData / "box.poly"), expected);
}

TEST(TriangleRead, TetGenPolyTakesItsPointsFromTheNodeFile) {
  MeshData expected;
  expected.dimension = 3;
  expected.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  expected.facets.corners = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  expected.facets.polygon_end = {3, 6, 9, 12};
  expected.facets.facet_end = {1, 2, 3, 4};
  expected.facets.hole_end = {0, 0, 0, 0};
  expected.facets.labels = {1, 2, 3, 0};
  EXPECT_EQ(read_mesh(kData / "tetp.poly"), expected);
}

// Hand-derived from the file (1-based corners minus one): polygons of 4 corners, a facet of two
// polygons with a facet hole, markers, comments at line ends, a region with a maximum volume.
TEST(TriangleRead, TetGenPolyWithPolygonsFacetHoleAndRegion) {
  const MeshData d = read_mesh(kData / "pocket.poly");
  EXPECT_EQ(d.dimension, 3);
  EXPECT_EQ(d.point_count(), 16u);
  EXPECT_EQ(d.facets.facet_count(), 11u);
  EXPECT_EQ(d.facets.polygon_count(), 12u);
  EXPECT_EQ(d.facets.facet_end, (std::vector<std::uint64_t>{1, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12}));
  EXPECT_EQ(d.facets.hole_end, (std::vector<std::uint64_t>{0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1}));
  EXPECT_EQ(d.facets.holes, (std::vector<double>{2, 2, 2}));
  EXPECT_EQ(d.facets.labels, (std::vector<Label>{1, 2, 3, 3, 3, 3, 4, 4, 4, 4, 4}));
  const std::vector<Index> first_three{0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
  EXPECT_TRUE(std::equal(first_three.begin(), first_three.end(), d.facets.corners.begin()));
  EXPECT_EQ(d.facets.corners.size(), 48u);
  EXPECT_EQ(d.facets.polygon_end.back(), 48u);
  EXPECT_EQ(d.region_points, (std::vector<double>{0.5, 0.5, 0.5}));
  EXPECT_EQ(d.region_attributes, (std::vector<double>{7}));
  EXPECT_EQ(d.region_max_measures, (std::vector<double>{0.5}));
  EXPECT_TRUE(d.triangles.empty());
}

// .smesh, 0-based: one polygon per facet, a corner list continued on the next line, the marker
// after the last corner.
TEST(TriangleRead, TetGenSmeshZeroBasedWithContinuedCornerList) {
  MeshData expected;
  expected.dimension = 3;
  expected.coordinates = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 1, 0, 1, 1};
  expected.facets.corners = {0, 2, 1, 3, 4, 5, 0, 1, 4, 3, 1, 2, 5, 4, 2, 0, 3, 5};
  expected.facets.polygon_end = {3, 6, 10, 14, 18};
  expected.facets.facet_end = {1, 2, 3, 4, 5};
  expected.facets.hole_end = {0, 0, 0, 0, 0};
  expected.facets.labels = {5, 6, 7, 8, 9};
  EXPECT_EQ(read_mesh(kData / "wedge.smesh"), expected);
}

TEST(TriangleWrite, FacetsRoundTripThroughSmeshAndAreRefusedElsewhere) {
  const MeshData wedge = read_mesh(kData / "wedge.smesh");
  write_mesh(wedge, folder() / "wedge.smesh");
  EXPECT_TRUE(identical(read_mesh(folder() / "wedge.smesh"), wedge));
  const MeshData pocket = read_mesh(kData / "pocket.poly");
  EXPECT_THROW(write_mesh(pocket, folder() / "pocket.smesh"), FormatError);  // a facet with a hole
  EXPECT_THROW(write_mesh(pocket, folder() / "pocket.mesh"), FormatError);   // quads: not triangles
  const MeshData tet = read_mesh(kData / "tetp.poly");                        // four triangles: they convert
  write_mesh(tet, folder() / "tetp.mesh");
  const MeshData back = read_mesh(folder() / "tetp.mesh");
  EXPECT_EQ(back.triangles, tet.facets.corners);
  EXPECT_EQ(back.triangle_labels, tet.facets.labels);
  write_mesh(pocket, folder() / "pocket.poly");
  EXPECT_TRUE(identical(read_mesh(folder() / "pocket.poly"), pocket));
}

TEST(TriangleRead, AllZeroMarkersReadAsNoMarkers) {
  const MeshData mesh = parse_triangle_format(
      "z.node", "3 2 0 1\n1 0 0 0\n2 1 0 0\n3 0 1 0\n", [](const fs::path&) { return std::nullopt; });
  EXPECT_TRUE(mesh.point_labels.empty());
  EXPECT_EQ(mesh.point_count(), 3u);
}

TEST(TriangleWrite, RefusesWhatTheFileCannotHold) {
  MeshData mesh;
  mesh.coordinates = {0, 0, 1, 0, 0, 1};
  mesh.triangles = {0, 1, 2};
  EXPECT_THROW(write_triangle_format(mesh, folder() / "elements.poly"), FormatError);
  MeshData domain;
  domain.coordinates = {0, 0};
  domain.holes = {0.5, 0.5};
  EXPECT_THROW(write_triangle_format(domain, folder() / "holes.node"), FormatError);
  MeshData bad_index = mesh;
  bad_index.triangles = {0, 1, 3};
  EXPECT_THROW(write_triangle_format(bad_index, folder() / "bad.node"), FormatError);
  EXPECT_FALSE(fs::exists(folder() / "bad.node"));
  MeshData not_finite = mesh;
  not_finite.coordinates[0] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(write_triangle_format(not_finite, folder() / "nan.node"), FormatError);
  EXPECT_FALSE(fs::exists(folder() / "nan.node"));
}

}  // namespace
}  // namespace certimesh::io
