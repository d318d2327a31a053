// `certimesh convert` between Medit and Triangle/TetGen, through the real executable: the
// converted file reads back (through the readers) as the input, and a malformed input exits 2
// with "error: FILE:LINE:" on stderr and leaves no output file.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "certimesh/io/mesh_file.h"
#include "text_format_support.h"

namespace certimesh::io {
namespace {

namespace fs = std::filesystem;
using testing::identical;

const fs::path kSource = fs::path(CERTIMESH_TEST_DATA_DIR);

const fs::path& folder() {
  static const testing::ScratchFolder scratch("cli");
  return scratch.path();
}

struct CliResult {
  int exit_code = -1;
  std::string stderr_text;
};

CliResult convert(const fs::path& in, const fs::path& out) {
  const fs::path err = folder() / "stderr.txt";
  const std::string command = std::string("'") + CERTIMESH_CLI + "' convert '" + in.string() +
                              "' '" + out.string() + "' >/dev/null 2>'" + err.string() + "'";
  const int status = std::system(command.c_str());
  CliResult run;
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream text(err);
  std::ostringstream buffer;
  buffer << text.rdbuf();
  run.stderr_text = buffer.str();
  return run;
}

TEST(TriangleMeditCli, TetrahedronMeshToNodeEleFaceAndBack) {
  const fs::path input = kSource / "data" / "medit" / "tet.mesh";
  ASSERT_EQ(convert(input, folder() / "tet.node").exit_code, 0);
  EXPECT_TRUE(fs::exists(folder() / "tet.ele"));
  EXPECT_TRUE(fs::exists(folder() / "tet.face"));
  EXPECT_TRUE(identical(read_mesh(folder() / "tet.node"), read_mesh(input)));
  ASSERT_EQ(convert(folder() / "tet.ele", folder() / "back.mesh").exit_code, 0);
  EXPECT_TRUE(identical(read_mesh(folder() / "back.mesh"), read_mesh(input)));
}

TEST(TriangleMeditCli, TriangleFilesToMeditAndBack) {
  const fs::path input = kSource / "data" / "triangle" / "square0.ele";
  ASSERT_EQ(convert(input, folder() / "square.mesh").exit_code, 0);
  EXPECT_TRUE(identical(read_mesh(folder() / "square.mesh"), read_mesh(input)));
  ASSERT_EQ(convert(folder() / "square.mesh", folder() / "square.ele").exit_code, 0);
  EXPECT_TRUE(identical(read_mesh(folder() / "square.node"), read_mesh(input)));
}

TEST(TriangleMeditCli, MalformedMeditInputExits2AndWritesNothing) {
  const fs::path input = kSource / "malformed" / "nan.mesh";
  const CliResult run = convert(input, folder() / "out.node");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.stderr_text.find("error: " + input.string() + ":6: "), std::string::npos)
      << run.stderr_text;
  EXPECT_FALSE(fs::exists(folder() / "out.node"));
  EXPECT_FALSE(fs::exists(folder() / "out.ele"));
}

TEST(TriangleMeditCli, MalformedTriangleInputExits2AndWritesNothing) {
  const fs::path input = kSource / "malformed" / "zero_index.ele";
  const CliResult run = convert(input, folder() / "out.mesh");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.stderr_text.find("error: " + input.string() + ":2: "), std::string::npos)
      << run.stderr_text;
  EXPECT_FALSE(fs::exists(folder() / "out.mesh"));
}

}  // namespace
}  // namespace certimesh::io
