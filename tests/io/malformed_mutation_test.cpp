// Generated malformed files: take a valid file written for a generated mesh, break one record
// line in one way, and the reader must refuse it naming exactly that line.
//   - Medit and Triangle/TetGen: one field replaced by a token that is no valid field of any
//     kind (NaN, Inf, out of range, garbage, a doubled sign);
//   - Triangle/TetGen (one record per line): one field deleted, or one field added.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "certimesh/io/format_error.h"
#include "certimesh/io/medit_format.h"
#include "certimesh/io/triangle_format.h"
#include "text_format_support.h"

namespace certimesh::io {
namespace {

namespace fs = std::filesystem;

std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

std::vector<std::string> split_fields(const std::string& line) {
  std::vector<std::string> fields;
  std::istringstream in(line);
  for (std::string field; in >> field;) fields.push_back(field);
  return fields;
}

std::string join(const std::vector<std::string>& lines, const char* separator) {
  std::string out;
  for (std::size_t i = 0; i < lines.size(); ++i) out += (i ? separator : "") + lines[i];
  return out;
}

rc::Gen<std::string> invalid_field() {
  return rc::gen::element<std::string>("nan", "inf", "-inf", "NaN", "1e400", "-1e999", "abc",
                                       "--1", "+-3", "0x", "1.5.2", "@", "\x01\x02");
}

// The line (0-based) of a record: the generated texts put each record on its own line, with
// three or more fields; headers, keywords and counts have fewer (Medit) or are line 0 (Triangle).
std::size_t pick_record_line(const std::vector<std::string>& lines, std::size_t first) {
  std::vector<std::size_t> records;
  for (std::size_t i = first; i < lines.size(); ++i) {
    if (split_fields(lines[i]).size() >= 3) records.push_back(i);
  }
  RC_PRE(!records.empty());
  return *rc::gen::elementOf(records);
}

std::size_t line_of_error(const std::function<void()>& parse) {
  try {
    parse();
  } catch (const FormatError& e) {
    return e.line();
  }
  return 0;  // accepted: never a valid line number
}

RC_GTEST_PROP(MalformedMutation, MeditFieldReplacedIsReportedOnItsLine, ()) {
  const MeshData mesh = *testing::mesh_of(*rc::gen::element(2, 3));
  std::vector<std::string> lines = split_lines(format_medit(mesh));
  const std::size_t target = pick_record_line(lines, 0);
  std::vector<std::string> fields = split_fields(lines[target]);
  fields[*rc::gen::inRange<std::size_t>(0, fields.size())] = *invalid_field();
  lines[target] = join(fields, " ");
  const std::string text = join(lines, "\n");
  RC_ASSERT(line_of_error([&] { parse_medit_format("m.mesh", text); }) == target + 1);
}

// The texts of X.node and X.ele (2D) as the writer produces them.
std::pair<std::string, std::string> node_and_ele(const MeshData& mesh) {
  static const testing::ScratchFolder folder("mutation");
  write_triangle_format(mesh, folder.path() / "m.node");
  auto slurp = [](const fs::path& p) {
    std::ifstream in(p);
    std::ostringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  };
  return {slurp(folder.path() / "m.node"), slurp(folder.path() / "m.ele")};
}

std::string mutate_line(const std::string& line) {
  std::vector<std::string> fields = split_fields(line);
  const std::size_t at = *rc::gen::inRange<std::size_t>(0, fields.size());
  switch (*rc::gen::inRange(0, 3)) {
    case 0: fields[at] = *invalid_field(); break;
    case 1: fields.erase(fields.begin() + static_cast<std::ptrdiff_t>(at)); break;
    default: fields.push_back("7"); break;
  }
  return join(fields, " ");
}

RC_GTEST_PROP(MalformedMutation, TriangleRecordBrokenIsReportedOnItsLine, ()) {
  MeshData mesh = *testing::mesh_of(2);
  RC_PRE(!mesh.triangles.empty());
  mesh.segments.clear();  // only X.node and X.ele: the parse below supplies no X.edge
  mesh.segment_labels.clear();
  auto [node, ele] = node_and_ele(mesh);
  const bool break_node = *rc::gen::arbitrary<bool>();
  std::vector<std::string> lines = split_lines(break_node ? node : ele);
  const std::size_t target = pick_record_line(lines, 1);
  lines[target] = mutate_line(lines[target]);
  const std::string broken = join(lines, "\n") + "\n";
  const std::string& main = break_node ? ele : broken;
  const std::string& companion = break_node ? broken : node;
  const std::size_t line = line_of_error([&] {
    parse_triangle_format("m.ele", main, [&](const fs::path& p) -> std::optional<std::string> {
      if (p.extension() == ".node") return companion;
      return std::nullopt;
    });
  });
  RC_ASSERT(line == target + 1);
}

}  // namespace
}  // namespace certimesh::io
