// Malformed and hostile .vtu input: every case is a FormatError naming the file, the line of
// the offending element or value and the problem; never a crash, a hang or a huge allocation.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "certimesh/io/format_error.h"
#include "certimesh/io/vtu_format.h"
#include "text_mutation.h"

namespace certimesh::testing {
namespace {

// A valid file; the cases below change one fragment of it. Line numbers on the right.
const std::string kValid =
    "<?xml version=\"1.0\"?>\n"                                                            // 1
    "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\">\n"     // 2
    "<UnstructuredGrid>\n"                                                                  // 3
    "<Piece NumberOfPoints=\"3\" NumberOfCells=\"1\">\n"                                    // 4
    "<Points>\n"                                                                            // 5
    "<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n"              // 6
    "0 0 0\n"                                                                               // 7
    "1 0 0\n"                                                                               // 8
    "0 1 0\n"                                                                               // 9
    "</DataArray>\n"                                                                        // 10
    "</Points>\n"                                                                           // 11
    "<Cells>\n"                                                                             // 12
    "<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n"                   // 13
    "0 1 2\n"                                                                               // 14
    "</DataArray>\n"                                                                        // 15
    "<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n"                        // 16
    "3\n"                                                                                   // 17
    "</DataArray>\n"                                                                        // 18
    "<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n"                          // 19
    "5\n"                                                                                   // 20
    "</DataArray>\n"                                                                        // 21
    "</Cells>\n"                                                                            // 22
    "<CellData>\n"                                                                          // 23
    "<DataArray type=\"Int32\" Name=\"label\" format=\"ascii\">\n"                          // 24
    "2\n"                                                                                   // 25
    "</DataArray>\n"                                                                        // 26
    "</CellData>\n"                                                                         // 27
    "</Piece>\n"                                                                            // 28
    "</UnstructuredGrid>\n"                                                                 // 29
    "</VTKFile>\n";                                                                         // 30

std::string changed(const std::string& from, const std::string& to) {
  std::string text = kValid;
  const std::size_t at = text.find(from);
  if (at == std::string::npos) throw std::logic_error("fragment not in the valid file: " + from);
  return text.replace(at, from.size(), to);
}

struct MalformedCase {
  const char* title;
  std::string text;
  std::size_t line;
  const char* why;
};

const std::string kConnectivity = "Name=\"connectivity\" format=\"ascii\">\n0 1 2";

// The valid file with a zlib compressor and the connectivity as this base64 text.
std::string zlib_connectivity(const std::string& base64) {
  std::string text = changed(kConnectivity, "Name=\"connectivity\" format=\"binary\">\n" + base64);
  return text.replace(text.find("byte_order"), 0, "compressor=\"vtkZLibDataCompressor\" ");
}

std::vector<MalformedCase> cases() {
  return {
      {"empty file", "", 1, "no XML element"},
      {"garbage", "hello\n", 1, "expected an XML element"},
      {"truncated", kValid.substr(0, kValid.find("0 1 2") + 3), 14, "unexpected end of file inside <DataArray> of line 13"},
      {"PolyData", changed("\"UnstructuredGrid\"", "\"PolyData\""), 2, "type 'PolyData' is not supported"},
      {"version 2.2", changed("version=\"1.0\" byte", "version=\"2.2\" byte"), 2, "version '2.2' is not supported"},
      {"wrong root", changed("<VTKFile", "<VTKFil"), 30, "</VTKFile> closes <VTKFil>"},
      {"point count mismatch", changed("NumberOfPoints=\"3\"", "NumberOfPoints=\"4\""), 6, "NumberOfPoints 4 needs 12"},
      {"a billion cells", changed("NumberOfCells=\"1\"", "NumberOfCells=\"1000000000\""), 4, "cannot fit"},
      {"a billion points", changed("NumberOfPoints=\"3\"", "NumberOfPoints=\"1000000000\""), 4, "cannot fit"},
      {"negative count", changed("NumberOfCells=\"1\"", "NumberOfCells=\"-1\""), 4, "is not a count"},
      {"index out of range", changed("0 1 2", "0 1 3"), 13, "names point 3"},
      {"negative index", changed("0 1 2", "0 -1 2"), 13, "names point -1"},
      {"NaN coordinate", changed("1 0 0", "1 nan 0"), 8, "not finite"},
      {"Inf coordinate", changed("0 1 0\n<", "0 1 inf\n<"), 9, "not finite"},
      {"coordinate out of range", changed("1 0 0", "1e400 0 0"), 8, "out of range"},
      {"not a number", changed("1 0 0", "1 zero 0"), 8, "expected a number, got 'zero'"},
      {"quadrangle", changed(">\n5\n", ">\n9\n"), 19, "VTK type 9, not supported"},
      {"offset beyond connectivity", changed(">\n3\n", ">\n4\n"), 16, "beyond the connectivity"},
      {"offsets count", changed(">\n3\n", ">\n3 3\n"), 16, "offsets holds 2 values"},
      {"cell size vs type", changed(">\n5\n", ">\n10\n"), 19, "has 3 vertices"},
      {"mismatched close tag", changed("</Points>", "</Cells>"), 11, "</Cells> closes <Points> of line 5"},
      {"unsupported compressor", [] {
         std::string t = zlib_connectivity("AAAA");
         return t.replace(t.find("vtkZLibDataCompressor"), 21, "vtkLZ4DataCompressor");
       }(),
       13, "compressor 'vtkLZ4DataCompressor' is not supported"},
      {"zlib header truncated", zlib_connectivity("AAAA"), 14, "shorter than its header"},
      {"zlib block corrupt", zlib_connectivity("AQAAABgAAAAAAAAABAAAAGFiY2Q="), 14, "block 0 is corrupt"},
      {"zlib bomb declared", zlib_connectivity("AQAAAAAAAIAAAAAABAAAAGFiY2Q="), 14, "more data than the piece can use"},
      {"zlib block missing", zlib_connectivity("AQAAABgAAAAAAAAAEAAAAA=="), 14, "truncated in block 0"},
      {"appended data", changed("Name=\"connectivity\" format=\"ascii\"", "Name=\"connectivity\" format=\"appended\" offset=\"0\""),
       13, "appended"},
      {"bad base64", changed(kConnectivity, "Name=\"connectivity\" format=\"binary\">\n!!!!"), 14, "malformed base64"},
      {"base64 header beyond data", changed(kConnectivity, "Name=\"connectivity\" format=\"binary\">\nGAAAAA=="), 14,
       "declares 24 bytes, it holds 0"},
      {"float labels", changed("\"Int32\" Name=\"label\"", "\"Float64\" Name=\"label\""), 24, "must have an integer type"},
      {"label count", changed(">\n2\n", ">\n2 2\n"), 24, "label holds 2 values, expected 1"},
      {"label beyond int32", changed(">\n2\n", ">\n4294967296\n"), 24, "not a 32-bit integer"},
      {"2D with z", [] {
         std::string t = changed("<UnstructuredGrid>\n",
                                 "<UnstructuredGrid><FieldData><DataArray type=\"Int32\" Name=\"certimesh_dimension\" "
                                 "format=\"ascii\">2</DataArray></FieldData>\n");
         return t.replace(t.find("0 1 0\n<"), 5, "0 1 5");
       }(),
       4, "certimesh_dimension is 2 but point 2 has z != 0"},
      {"second piece", changed("</Piece>\n", "</Piece>\n<Piece NumberOfPoints=\"0\" NumberOfCells=\"0\"/>\n"), 29,
       "more than one <Piece>"},
      {"unknown Piece child", changed("<CellData>", "<Verts></Verts><CellData>"), 23, "unexpected <Verts>"},
      {"DOCTYPE", "<!DOCTYPE foo>\n" + kValid, 1, "DOCTYPE"},
      {"unquoted attribute", changed("NumberOfCells=\"1\"", "NumberOfCells=1"), 4, "quoted value"},
      {"duplicate attribute", changed("NumberOfCells=\"1\"", "NumberOfCells=\"1\" NumberOfCells=\"1\""), 4, "appears twice"},
      {"content after root", kValid + "<x/>\n", 31, "content after the root"},
      {"deep nesting", "<VTKFile type=\"UnstructuredGrid\">" + std::string(10000, '<') , 1, "expected an XML name"},
      {"deep nesting of elements", [] {
         std::string t = "<VTKFile type=\"UnstructuredGrid\">\n";
         for (int i = 0; i < 10000; ++i) t += "<a>";
         return t;
       }(), 2, "nested deeper"},
  };
}

TEST(VtuMalformed, EveryCaseNamesFileLineAndWhy) {
  for (const MalformedCase& c : cases()) {
    SCOPED_TRACE(c.title);
    try {
      (void)io::parse_vtu_format("bad.vtu", c.text);
      ADD_FAILURE() << "accepted";
    } catch (const io::FormatError& e) {
      EXPECT_EQ(e.file(), "bad.vtu");
      EXPECT_EQ(e.line(), c.line) << e.what();
      EXPECT_NE(e.why().find(c.why), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("bad.vtu:" + std::to_string(c.line) + ": ", 0), 0u) << e.what();
    }
  }
}

TEST(VtuMalformed, TheValidBaseIsValid) {
  const io::MeshData m = io::parse_vtu_format("good.vtu", kValid);
  EXPECT_EQ(m.dimension, 2);
  EXPECT_EQ(m.coordinates, (std::vector<double>{0, 0, 1, 0, 0, 1}));
  EXPECT_EQ(m.triangles, (std::vector<io::Index>{0, 1, 2}));
  EXPECT_EQ(m.triangle_labels, (std::vector<io::Label>{2}));
  EXPECT_EQ(io::parse_vtu_format("bom.vtu", "\xEF\xBB\xBF" + kValid), m);  // with a UTF-8 byte order mark
}

TEST(VtuMalformed, TheZlibBaseIsValid) {
  // Python: header struct.pack('<4I', 1, 24, 0, len(c)) + c = zlib.compress of Int64 0 1 2.
  const io::MeshData m = io::parse_vtu_format("good.vtu", zlib_connectivity("AQAAABgAAAAAAAAAEAAAAA==eJxjYIAARijNBKUBADgABA=="));
  EXPECT_EQ(m.triangles, (std::vector<io::Index>{0, 1, 2}));
}

TEST(VtuMalformed, EveryPrefixIsRefusedOrTheWholeMesh) {
  for (std::size_t cut = 0; cut < kValid.size(); ++cut) {
    try {
      const io::MeshData m = io::parse_vtu_format("cut.vtu", kValid.substr(0, cut));
      EXPECT_EQ(m.triangles, (std::vector<io::Index>{0, 1, 2})) << "cut " << cut;
    } catch (const io::FormatError& e) {
      EXPECT_GE(e.line(), 1u) << "cut " << cut;
    }
  }
}

TEST(VtuMalformed, MissingFileIsAFormatError) {
  EXPECT_THROW((void)io::read_vtu_format(std::filesystem::path(::testing::TempDir()) / "certimesh_no_such_file.vtu"),
               io::FormatError);
}

TEST(VtuMalformed, RandomByteMutationsOnlyEverThrowFormatError) {
  // Seeded (reproducible) corruption of a valid file: overwrite, insert or delete a few bytes,
  // biased towards characters that matter to the format. Anything but a FormatError or a
  // result fails; the sanitizer rerun of the suite catches memory errors on the way.
  const std::string zlib_valid = zlib_connectivity("AQAAABgAAAAAAAAAEAAAAA==eJxjYIAARijNBKUBADgABA==");
  std::mt19937_64 rng(20261129);
  std::size_t refused = 0;
  for (int round = 0; round < 20000; ++round) {
    const std::string text = mutate_text(round % 2 == 0 ? kValid : zlib_valid, rng);  // ASCII, and base64 of zlib data
    try {
      (void)io::parse_vtu_format("mutated.vtu", text);
    } catch (const io::FormatError& error) {
      ++refused;
      EXPECT_EQ(std::string(error.what()).rfind("mutated.vtu:", 0), 0u) << error.what();
    }
  }
  EXPECT_GT(refused, 5000u);  // the mutations do break the files
}

}  // namespace
}  // namespace certimesh::testing
