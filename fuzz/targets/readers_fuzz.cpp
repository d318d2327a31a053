// libFuzzer target for the readers (Medit .mesh; Triangle/TetGen .node .ele .face .edge .poly
// .smesh; OFF; STL, ASCII and binary). Input layout: the first byte picks the reader; the rest is the file, optionally
// followed by "\n====\n" and the contents of its companion X.node. For every input:
//   - the reader either throws FormatError or returns a MeshData whose indices name existing
//     points, whose label lists are empty or one per item, and whose numbers are finite;
//   - any other exception, crash, leak or sanitizer report is a finding (libFuzzer stops);
//   - an accepted mesh without holes/regions survives Medit: format_medit then
//     parse_medit_format gives the same MeshData bit for bit (a differential check between the
//     two readers and the writer);
//   - a refusal names a line that exists in the file it names, in a message of < 512 bytes.
//
// Build and run (clang; -DCERTIMESH_SANITIZE=ON puts ASan/UBSan in the readers as well):
//   cmake -S . -B build-fuzz -DCMAKE_CXX_COMPILER=clang++ -DCERTIMESH_BUILD_FUZZERS=ON \
//         -DCERTIMESH_SANITIZE=ON -DCERTIMESH_BUILD_BENCHMARKS=OFF -DCMAKE_BUILD_TYPE=RelWithDebInfo
//   cmake --build build-fuzz --target readers_fuzz
//   build-fuzz/bin/readers_fuzz -dict=fuzz/targets/readers_fuzz.dict -max_total_time=300 CORPUS
// Seed CORPUS with the files of tests/io/data and tests/io/malformed, each prefixed by its
// reader byte (0 .mesh, 1 .node, 2 .ele, 3 .face, 4 .edge, 5 .poly, 6 .smesh, 7 .off, 8 .stl).
// Measured (clang 14, ASan+UBSan in target and readers, one job on the shared 2-core VM, 69
// seeds): 300 s runs executed 1,713,836 inputs (5,700/s) and, with the error-line check,
// 1,406,159 inputs (4,700/s, 977 edges covered); no finding. With TetGen's polygonal facets and
// .smesh (33 seeds: tests/io/data/triangle, the .poly/.smesh of tests/io/malformed, the domains
// of tests/certificate/tetgen_domains_test.py), a 180 s run executed 650,402 inputs (3,593/s,
// 957 edges covered); no finding. With OFF and STL (9 seeds: OFF and ASCII/binary STL written by
// meshio and by tests/io/surface_meshio_test.py, the Medit files of tests/io/data), a 120 s run
// executed 852,836 inputs (7,048/s, 1,079 edges covered); no finding.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

#include "certimesh/io/format_error.h"
#include "certimesh/io/medit_format.h"
#include "certimesh/io/off_format.h"
#include "certimesh/io/stl_format.h"
#include "certimesh/io/triangle_format.h"
#include "mesh_data_invariants.h"

namespace {

namespace io = certimesh::io;

[[noreturn]] void fail(const char* what) {
  std::fprintf(stderr, "\n*** readers_fuzz: %s\n", what);
  std::abort();
}

void check_well_formed(const io::MeshData& m) {
  if (const auto defect = certimesh::testing::mesh_data_defect(m)) fail(defect->c_str());
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (std::bit_cast<std::uint64_t>(a[i]) != std::bit_cast<std::uint64_t>(b[i])) return false;
  }
  return true;
}

void check_medit_round_trip(const io::MeshData& m) {
  if (!m.holes.empty() || !m.region_points.empty() || !m.facets.empty()) return;  // .mesh cannot hold them
  const io::MeshData back = io::parse_medit_format("round-trip.mesh", io::format_medit(m));
  if (!(back == m) || !same_bits(back.coordinates, m.coordinates)) {
    fail("format_medit -> parse_medit_format changed the mesh");
  }
}

std::size_t line_count(std::string_view text) {
  return static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
}

constexpr const char* kNames[] = {"f.mesh", "f.node", "f.ele", "f.face", "f.edge", "f.poly", "f.smesh", "f.off", "f.stl"};

// The error names a line that exists in the file it names (the main file, or the X.node
// companion), and its message is short whatever the input (quoted tokens are cut).
void check_error(const io::FormatError& e, std::size_t reader, std::string_view main,
                 const std::optional<std::string>& node) {
  std::size_t lines = 0;
  if (e.file() == kNames[reader]) {
    lines = line_count(main);
  } else if (e.file() == "f.node" && node.has_value()) {
    lines = line_count(*node);
  }
  if (e.line() > lines) fail("error names a line past the end of the file it names");
  if (std::string_view(e.what()).size() > 512) fail("error message longer than 512 characters");
}

io::MeshData parse(std::size_t reader, std::string main, std::optional<std::string> node) {
  if (reader == 0) return io::parse_medit_format(kNames[0], std::move(main));
  if (reader == 7) return io::parse_off_format(kNames[7], std::move(main));
  if (reader == 8) return io::parse_stl_format(kNames[8], std::move(main));
  return io::parse_triangle_format(kNames[reader], std::move(main),
                                   [&](const std::filesystem::path& p) -> std::optional<std::string> {
                                     if (p.extension() == ".node") return node;
                                     return std::nullopt;
                                   });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::size_t reader = data[0] % 9;
  const std::string_view rest(reinterpret_cast<const char*>(data + 1), size - 1);
  constexpr std::string_view kSeparator = "\n====\n";
  const std::size_t split = rest.find(kSeparator);
  std::string main(rest.substr(0, split));
  std::optional<std::string> node;
  if (split != std::string_view::npos) node = std::string(rest.substr(split + kSeparator.size()));
  io::MeshData mesh;
  try {
    mesh = parse(reader, main, node);  // copies: the error check below reads them
  } catch (const io::FormatError& e) {
    // Refusing is a correct answer, if the error points into the file and stays short.
    check_error(e, reader, rest.substr(0, split), node);
    return 0;
  }
  check_well_formed(mesh);
  check_medit_round_trip(mesh);
  return 0;
}
