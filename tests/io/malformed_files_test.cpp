// Malformed and hostile input for the Triangle/TetGen and Medit readers. Every case must end in
// a FormatError "FILE:LINE: why" naming the right file and line with a reason that names the
// problem -- never another exception, a crash or a hang (the sanitizer stage reruns this).
//   - tests/io/malformed/MANIFEST: hand-made files with their expected file, line and reason;
//   - generated: a multi-megabyte line, random binary junk, every truncation of valid files.
#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "certimesh/io/format_error.h"
#include "certimesh/io/medit_format.h"
#include "certimesh/io/mesh_file.h"
#include "certimesh/io/triangle_format.h"

namespace certimesh::io {
namespace {

namespace fs = std::filesystem;

const fs::path kMalformed = fs::path(CERTIMESH_TEST_DATA_DIR) / "malformed";
const fs::path kData = fs::path(CERTIMESH_TEST_DATA_DIR) / "data";

std::string slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

std::string trim(const std::string& s) {
  const auto begin = s.find_first_not_of(' ');
  const auto end = s.find_last_not_of(' ');
  return begin == std::string::npos ? std::string() : s.substr(begin, end - begin + 1);
}

struct Case {
  std::string read;        // file given to read_mesh
  std::string error_file;  // file the error must name
  std::size_t line = 0;
  std::string why;         // phrase the reason must contain
};

std::vector<Case> manifest() {
  std::vector<Case> cases;
  std::istringstream lines(slurp(kMalformed / "MANIFEST"));
  std::string line;
  while (std::getline(lines, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::vector<std::string> fields;
    std::size_t start = 0;
    for (std::size_t bar = line.find(" | "); bar != std::string::npos; bar = line.find(" | ", start)) {
      fields.push_back(trim(line.substr(start, bar - start)));
      start = bar + 3;
    }
    fields.push_back(trim(line.substr(start)));
    if (fields.size() != 4) throw std::runtime_error("MANIFEST: malformed line: " + line);
    cases.push_back({fields[0], fields[1], std::stoul(fields[2]), fields[3]});
  }
  return cases;
}

class MalformedFile : public ::testing::TestWithParam<Case> {};

TEST_P(MalformedFile, GivesFileLineAndReason) {
  const Case& c = GetParam();
  try {
    read_mesh(kMalformed / c.read);
    FAIL() << c.read << " was accepted";
  } catch (const FormatError& e) {
    EXPECT_EQ(fs::path(e.file()).filename().string(), c.error_file) << e.what();
    EXPECT_EQ(e.line(), c.line) << e.what();
    EXPECT_NE(e.why().find(c.why), std::string::npos) << "reason: " << e.why();
    const std::string prefix = e.file() + (c.line == 0 ? ": " : ":" + std::to_string(c.line) + ": ");
    EXPECT_EQ(std::string(e.what()).rfind(prefix, 0), 0u) << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(Manifest, MalformedFile, ::testing::ValuesIn(manifest()),
                         [](const ::testing::TestParamInfo<Case>& param_info) {
                           std::string name = param_info.param.read;
                           for (char& ch : name) {
                             if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
                           }
                           return name;
                         });

TEST(MalformedManifest, CoversEveryFileInTheFolder) {
  // A file added to the folder without a manifest line would silently test nothing.
  std::vector<std::string> named;
  for (const Case& c : manifest()) {
    named.push_back(c.read);
    named.push_back(c.error_file);
  }
  for (const auto& entry : fs::directory_iterator(kMalformed)) {
    const std::string name = entry.path().filename().string();
    if (name == "MANIFEST") continue;
    const fs::path stem = entry.path().stem();
    const bool mentioned = std::any_of(named.begin(), named.end(), [&](const std::string& n) {
      return n == name || fs::path(n).stem() == stem;
    });
    EXPECT_TRUE(mentioned) << name << " is not in MANIFEST";
  }
}

// ---- Generated cases --------------------------------------------------------------------------

// Parses `contents` as a file named `name`; the Triangle formats get `node` as X.node.
void parse(const std::string& name, const std::string& contents, const std::string& node = {}) {
  if (fs::path(name).extension() == ".mesh") {
    parse_medit_format(name, contents);
    return;
  }
  parse_triangle_format(name, contents, [&](const fs::path& p) -> std::optional<std::string> {
    if (p.extension() == ".node" && !node.empty()) return node;
    return std::nullopt;
  });
}

// Runs the parser and returns the FormatError; any other exception fails the test.
std::optional<FormatError> error_of(const std::string& name, const std::string& contents,
                                    const std::string& node = {}) {
  try {
    parse(name, contents, node);
  } catch (const FormatError& e) {
    return e;
  }
  return std::nullopt;
}

TEST(MalformedGenerated, MegabyteTokenGivesAShortMessageOnTheRightLine) {
  const std::string huge(4'000'000, '7');
  const std::string junk(4'000'000, 'x');
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"h.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n1\n" + huge + " 0 0\nEnd\n"},
      {"j.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n1\n0 0 0\n" + junk + "\nEnd\n"},
      {"h.node", "1 2 0 0\n1 " + huge + " 0\n"},
      {"j.node", "1 2 0 0\n1 0 " + junk + "\n"},
  };
  for (const auto& [name, contents] : cases) {
    const auto e = error_of(name, contents);
    ASSERT_TRUE(e.has_value()) << name;
    EXPECT_LT(std::string(e->what()).size(), 200u) << name;
    // j.mesh: a letter-led token where a keyword goes is an unknown keyword, whose count the
    // reader then expects on the next line.
    EXPECT_EQ(e->line(), name == "h.node" || name == "j.node" ? 2u : name == "h.mesh" ? 5u : 7u)
        << e->what();
  }
}

TEST(MalformedGenerated, CountsBeyondTheFileAreRefusedForEverySection) {
  const std::string node = "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"a.node", "4000000000 2 0 0\n1 0 0\n"},
      {"b.node", "1 2 1000000000 0\n1 0 0\n"},
      {"c.ele", "1 3 4000000000\n1 1 2 3\n"},
      {"d.edge", "9223372036854775807 1\n1 1 2 0\n"},
      {"e.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n999999999 0\n"},
      {"f.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n999999999\n"},
      {"g.mesh", "MeshVersionFormatted 2\nDimension 2\nVertices\n3\n0 0 0\n1 0 0\n0 1 0\n"
                 "Triangles\n4000000000\n1 2 3 0\nEnd\n"},
      {"h.mesh", "MeshVersionFormatted 2\nDimension 2\nCorners\n99999999999\n1\nEnd\n"},
  };
  for (const auto& [name, contents] : cases) {
    const auto e = error_of(name, contents, node);
    ASSERT_TRUE(e.has_value()) << name;
    EXPECT_NE(e->why().find("cannot fit"), std::string::npos) << e->what();
  }
}

TEST(MalformedGenerated, RandomBinaryJunkIsRefusedCleanly) {
  std::mt19937_64 rng(20261129);  // fixed seed: the same junk on every run
  const std::vector<std::string> names = {"r.mesh", "r.node", "r.ele", "r.poly", "r.face"};
  const std::vector<std::string> headers = {"MeshVersionFormatted 2\nDimension 3\n", "3 3 0 1\n",
                                            "2 4 1\n", "4 2 0 0\n", "2 1\n"};
  const std::string node = "4 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n4 0 0 1\n";
  std::size_t refused = 0;
  for (int round = 0; round < 2000; ++round) {
    const std::size_t which = static_cast<std::size_t>(round) % names.size();
    std::string junk = round % 2 == 0 ? headers[which] : std::string();
    const std::size_t length = rng() % 600;
    for (std::size_t i = 0; i < length; ++i) {
      // Mostly digits, separators and signs, so that the junk gets past the first field.
      const std::uint64_t r = rng();
      static constexpr char kAlphabet[] = "0123456789 \n-+.eE#\t";
      junk += r % 4 == 0 ? static_cast<char>(r >> 8) : kAlphabet[(r >> 8) % (sizeof kAlphabet - 1)];
    }
    if (error_of(names[which], junk, node)) ++refused;
  }
  EXPECT_GT(refused, 1900u);  // junk is almost never a valid file
}

// Every prefix of a valid file that cuts into its records is refused: every prefix shorter
// than `must_fail_before` bytes (default: the start of the file's last token; a file whose
// optional last section may be cut off cleanly says where that section begins).
void expect_every_truncation_refused(const std::string& name, const std::string& contents,
                                     const std::string& node = {},
                                     std::size_t must_fail_before = std::string::npos) {
  ASSERT_FALSE(error_of(name, contents, node).has_value()) << name << " itself must be valid";
  std::size_t last_token = contents.find_last_not_of(" \t\r\n");
  while (last_token > 0 && std::string(" \t\r\n").find(contents[last_token - 1]) == std::string::npos) {
    --last_token;
  }
  const std::size_t end = std::min(last_token, must_fail_before);
  for (std::size_t cut = 0; cut < end; ++cut) {
    EXPECT_TRUE(error_of(name, contents.substr(0, cut), node).has_value()) << name << " cut at byte " << cut;
  }
}

TEST(MalformedGenerated, EveryTruncationOfAValidFileIsRefused) {
  expect_every_truncation_refused("square.mesh", slurp(kData / "medit" / "square.mesh"));
  expect_every_truncation_refused("tet.mesh", slurp(kData / "medit" / "tet.mesh"));
  const std::string box = slurp(kData / "triangle" / "box.poly");
  // The region list is optional: box.poly cut just before it is a valid domain.
  expect_every_truncation_refused("box.poly", box, {}, box.rfind("\n1\n1 0.5 0.5 10 0.1"));
  expect_every_truncation_refused("tet.node", slurp(kData / "triangle" / "tet.node"));
  const std::string tet_node = slurp(kData / "triangle" / "tet.node");
  expect_every_truncation_refused("tet.ele", slurp(kData / "triangle" / "tet.ele"), tet_node);
  expect_every_truncation_refused("tet.face", slurp(kData / "triangle" / "tet.face"), tet_node);
  expect_every_truncation_refused("tetp.poly", slurp(kData / "triangle" / "tetp.poly"), tet_node);
}

}  // namespace
}  // namespace certimesh::io
