// The OFF and STL readers (io/off_format.h, io/stl_format.h) on hand-written files whose
// contents are known by construction, on malformed ones (each refused with a FormatError
// naming the file, the line -- binary STL: the triangle -- and the reason), and on every
// truncation of valid files (FormatError or a valid mesh, never a crash). The independent
// reading oracle is meshio: surface_meshio_test.py.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <vector>

#include "certimesh/io/format_error.h"
#include "certimesh/io/off_format.h"
#include "certimesh/io/stl_format.h"

namespace certimesh::io {
namespace {

// Expects `parse` to throw a FormatError at `line` whose reason contains `why`.
template <class Parse>
void expect_refused(Parse parse, std::size_t line, const std::string& why) {
  try {
    parse();
    FAIL() << "accepted; expected: " << why;
  } catch (const FormatError& e) {
    EXPECT_EQ(e.line(), line) << e.what();
    EXPECT_NE(e.why().find(why), std::string::npos) << e.what();
  }
}

TEST(surface_Off, TrianglesCommentsAndHeaderCounts) {
  const MeshData m = parse_off_format("t.off",
                                     "OFF 4 4 6  # counts on the header line\n"
                                     "# a tetrahedron\n"
                                     "0 0 0\n1 0 0\n0 1 0\n0 0 0x1p-3\n"
                                     "3 0 2 1\n3 0 1 3\n3 0 3 2 255 0 0\n3 1 2 3\n");
  EXPECT_EQ(m.dimension, 3);
  EXPECT_EQ(m.coordinates, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 0.125}));
  EXPECT_EQ(m.triangles, (std::vector<Index>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
  EXPECT_TRUE(m.facets.empty());
}

TEST(surface_Off, PolygonsBecomeOnePolygonFacets) {
  const MeshData m = parse_off_format("q.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n4 0 1 2 3\n3 0 1 4\n");
  EXPECT_TRUE(m.triangles.empty());
  EXPECT_EQ(m.facets.corners, (std::vector<Index>{0, 1, 2, 3, 0, 1, 4}));
  EXPECT_EQ(m.facets.polygon_end, (std::vector<std::uint64_t>{4, 7}));
  EXPECT_EQ(m.facets.facet_end, (std::vector<std::uint64_t>{1, 2}));
}

TEST(surface_Off, MalformedFilesNameTheLine) {
  auto off = [](std::string text) { return [text] { parse_off_format("m.off", text); }; };
  expect_refused(off(""), 1, "empty file");
  expect_refused(off("COFF\n1 0 0\n0 0 0 1 1 1 1\n"), 1, "COFF variant is not supported");
  expect_refused(off("OFF\n1 1 0\n0 0 nan\n3 0 0 0\n"), 3, "not finite");
  expect_refused(off("OFF\n1 1 0\n0 0 inf\n3 0 0 0\n"), 3, "not finite");
  expect_refused(off("OFF\n2 1 0\n0 0\n0 0 1\n3 0 1 0\n"), 3, "line ends before coordinate");
  expect_refused(off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"), 6, "vertex index 3 does not exist");
  expect_refused(off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n"), 6, "vertex 1 twice in one face");
  expect_refused(off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n"), 6, "a face of 2 corners");
  expect_refused(off("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), 2, "3 vertices and 2 faces cannot fit");
  expect_refused(off("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n     \n"), 8, "unexpected end of file");
  expect_refused(off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n7\n"), 7, "unexpected data after the 1 faces");
  expect_refused(off("OFF\n999999999 1 0\n0 0 0\n"), 2, "cannot fit");
}

// A binary STL of the given triangles (9 floats each), with an 80-byte header text.
std::string binary_stl(const std::string& header, const std::vector<float>& corners) {
  std::string out = header;
  out.resize(80, ' ');
  const auto n = static_cast<std::uint32_t>(corners.size() / 9);
  char count[4];
  std::memcpy(count, &n, 4);
  out.append(count, 4);
  for (std::uint32_t t = 0; t < n; ++t) {
    out.append(12, '\0');  // the normal, ignored
    for (int k = 0; k < 9; ++k) {
      const float f = corners[9 * t + std::size_t(k)];
      char bytes[4];
      std::memcpy(bytes, &f, 4);
      out.append(bytes, 4);
    }
    out.append(2, '\0');
  }
  return out;
}

const std::vector<float> kTetCorners = {0, 0, 0, 0, 1, 0, 1, 0, 0,  0, 0, 0, 1, 0, 0, 0, 0, 1,
                                        -0.0f, 0, 0, 0, 0, 1, 0, 1, 0,  1, 0, 0, 0, 1, 0, 0, 0, 0.1f};

TEST(surface_Stl, BinaryStartingWithSolidIsReadAsBinaryAndWelded) {
  const MeshData m = parse_stl_format("b.stl", binary_stl("solid but binary", kTetCorners));
  // Corners welded in order of first appearance; -0 is 0; 0.1f's float value kept exactly, and
  // (0 0 0.1f) differs from (0 0 1): five distinct points.
  EXPECT_EQ(m.point_count(), 5u);
  EXPECT_EQ(m.triangles, (std::vector<Index>{0, 1, 2, 0, 2, 3, 0, 3, 1, 2, 1, 4}));
  EXPECT_EQ(m.coordinates[14], static_cast<double>(0.1f));
  EXPECT_TRUE(m.triangle_labels.empty());
}

TEST(surface_Stl, AsciiSeveralSolidsAndCase) {
  const std::string text =
      "solid first part\n facet normal 0 0 -1\n  outer loop\n   vertex 0 0 0\n   vertex 0 1 0\n   vertex 1 0 0\n  endloop\n endfacet\n"
      "endsolid first part\n"
      "SOLID second\nFACET NORMAL 0 0 0\nOUTER LOOP\nVERTEX 1 0 0\nVERTEX 0 1 0\nVERTEX 0 0 1e-300\nENDLOOP\nENDFACET\nENDSOLID\n";
  const MeshData m = parse_stl_format("a.stl", text);
  EXPECT_EQ(m.coordinates, (std::vector<double>{0, 0, 0, 0, 1, 0, 1, 0, 0, 0, 0, 1e-300}));  // doubles, not floats
  EXPECT_EQ(m.triangles, (std::vector<Index>{0, 1, 2, 2, 1, 3}));
  EXPECT_EQ(m.triangle_labels, (std::vector<Label>{1, 2}));
}

TEST(surface_Stl, MalformedFiles) {
  auto stl = [](std::string text) { return [text] { parse_stl_format("m.stl", text); }; };
  const std::string head = "solid x\nfacet normal 0 0 1\nouter loop\n";
  expect_refused(stl(""), 0, "not an STL file");
  expect_refused(stl("hello"), 0, "not an STL file");
  expect_refused(stl(head + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 nan 0\nendloop\nendfacet\nendsolid\n"), 6, "not finite");
  expect_refused(stl(head + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\nendloop\n"), 7, "more than 3 vertices");
  expect_refused(stl(head + "vertex 0 0 0\nvertex 1 0 0\n"), 6, "unexpected end of file, expected 'vertex'");
  expect_refused(stl(head + "vertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\n"), 9, "expected 'facet' or 'endsolid'");
  expect_refused(stl("solid x\nfacet normal 0 0 1\ninner loop\n"), 3, "expected 'outer'");
  std::string truncated = binary_stl("", kTetCorners);
  truncated.pop_back();
  expect_refused(stl(truncated), 0, "announces 4 triangles (84 + 50*4 = 284 bytes) but the file has 283 bytes");
  std::vector<float> bad = kTetCorners;
  bad[9 * 2 + 4] = std::numeric_limits<float>::quiet_NaN();
  expect_refused(stl(binary_stl("", bad)), 0, "triangle 2 (0-based), corner 1: coordinate is not finite (nan)");
  bad[9 * 2 + 4] = std::numeric_limits<float>::infinity();
  expect_refused(stl(binary_stl("", bad)), 0, "triangle 2 (0-based), corner 1: coordinate is not finite (inf)");
}

TEST(surface_Readers, EveryTruncationIsRefusedOrValid) {
  const std::string off = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";
  const std::string ascii = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n";
  const std::string binary = binary_stl("solid", kTetCorners);
  for (std::size_t n = 0; n < off.size(); ++n) {
    try {
      const MeshData m = parse_off_format("t.off", off.substr(0, n));
      for (const Index i : m.triangles) EXPECT_LT(i, m.point_count());
    } catch (const FormatError&) {
    }
  }
  for (const std::string* file : {&ascii, &binary}) {
    for (std::size_t n = 0; n < file->size(); ++n) {
      try {
        const MeshData m = parse_stl_format("t.stl", file->substr(0, n));
        for (const Index i : m.triangles) EXPECT_LT(i, m.point_count());
        EXPECT_EQ(m.triangles.size() % 3, 0u);
      } catch (const FormatError&) {
      }
    }
  }
  // A cut binary file is never taken for text (it holds NUL bytes): the size error names it.
  EXPECT_THROW(parse_stl_format("t.stl", binary.substr(0, 200)), FormatError);
}

}  // namespace
}  // namespace certimesh::io
