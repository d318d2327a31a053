// `certimesh check-surface`: the counts of valid surfaces in each format, `error: FILE: ...`
// naming the triangles and exit 1 for invalid ones, exit 2 for unreadable files and misuse.
// The expected counts are those of the hand-written files (docs/surface_input.md's rules).
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

class CheckSurfaceCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("certimesh_surface_cli_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(dir_ / name, std::ios::binary) << text;
    return dir_ / name;
  }
  static std::string slurp(const fs::path& p) {
    std::ifstream in(p);
    return std::string(std::istreambuf_iterator<char>(in), {});
  }
  int run(const std::string& args) {
    const std::string command = std::string("'") + CERTIMESH_CLI + "' " + args + " > '" + (dir_ / "out").string() + "' 2> '" + (dir_ / "err").string() + "'";
    const int status = std::system(command.c_str());
    out_ = slurp(dir_ / "out");
    err_ = slurp(dir_ / "err");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  fs::path dir_;
  std::string out_, err_;
};

// The unit cube's corners, then its faces as outward quads (0-based).
const std::string kCubePoints = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
const std::string kCubeQuads = "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 3 7 6 2\n4 0 4 7 3\n4 1 2 6 5\n";

std::string stl_facet(const std::string& a, const std::string& b, const std::string& c) {
  return "facet normal 0 0 0\nouter loop\nvertex " + a + "\nvertex " + b + "\nvertex " + c + "\nendloop\nendfacet\n";
}

TEST_F(CheckSurfaceCommand, OffCubeOfQuads) {
  const fs::path f = write("cube.off", "OFF\n8 6 0\n" + kCubePoints + kCubeQuads);
  ASSERT_EQ(run("check-surface '" + f.string() + "'"), 0) << err_;
  EXPECT_EQ(out_, f.string() + ": valid closed surface: 8 vertices, 12 triangles, 1 shells (1 solids, 0 cavities, 0 interfaces)\n");
}

TEST_F(CheckSurfaceCommand, PolyNestedBoxesAreAnInterfaceWhateverTheirFacetOrder) {
  // TetGen reads facets without orientation: both boxes are turned outward, the inner one is
  // an interface (the hole point inside it is the mesher's to apply, and is counted). Some
  // quads listed the other way round.
  std::string points, facets;
  for (int box = 0; box < 2; ++box)
    for (int i = 0; i < 8; ++i) {
      const double s = box == 0 ? 4 : 1, o = box == 0 ? 0 : 1;
      points += std::to_string(8 * box + i) + " " + std::to_string(o + s * ((i == 1 || i == 2 || i == 5 || i == 6) ? 1 : 0)) + " " +
                std::to_string(o + s * ((i == 2 || i == 3 || i == 6 || i == 7) ? 1 : 0)) + " " + std::to_string(o + s * (i >= 4 ? 1 : 0)) + "\n";
    }
  const int quads[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {3, 7, 6, 2}, {0, 4, 7, 3}, {1, 2, 6, 5}};
  for (int box = 0; box < 2; ++box)
    for (int q = 0; q < 6; ++q) {
      facets += "1\n4";
      for (int k = 0; k < 4; ++k) facets += " " + std::to_string(8 * box + quads[q][(q % 2 == 0) ? k : 3 - k]);
      facets += "\n";
    }
  const fs::path f = write("nested.poly", "16 3 0 0\n" + points + "12 0\n" + facets + "1\n1 1.5 1.5 1.5\n0\n");
  ASSERT_EQ(run("check-surface '" + f.string() + "'"), 0) << err_;
  EXPECT_NE(out_.find("16 vertices, 24 triangles, 2 shells (1 solids, 0 cavities, 1 interfaces), 1 hole points\n"), std::string::npos) << out_;
}

TEST_F(CheckSurfaceCommand, FlippedStlTriangleIsNamed) {
  const std::string o = "0 0 0", x = "1 0 0", y = "0 1 0", z = "0 0 1";
  const fs::path f = write("tet.stl", "solid t\n" + stl_facet(o, y, x) + stl_facet(o, x, z) + stl_facet(o, z, y) + stl_facet(x, z, y) + "endsolid t\n");
  ASSERT_EQ(run("check-surface '" + f.string() + "'"), 1);
  EXPECT_TRUE(out_.empty());
  EXPECT_EQ(err_.rfind("error: " + f.string() + ": triangle ", 0), 0u) << err_;
  EXPECT_NE(err_.find("triangle 3 (1 0 0)-(0 0 1)-(0 1 0)"), std::string::npos) << err_;
  EXPECT_NE(err_.find("in the same direction"), std::string::npos) << err_;
}

TEST_F(CheckSurfaceCommand, TouchingShellsAreAnIntersection) {
  // A small tetrahedron whose corner (0.25 0.25 0) lies on the big one's bottom face.
  const std::string o = "0 0 0", x = "4 0 0", y = "0 4 0", z = "0 0 4";
  const std::string p = "0.25 0.25 0", q = "1 0.5 1", r = "0.5 1 1", s = "1 1 0.5";
  std::string text = "solid t\n" + stl_facet(o, y, x) + stl_facet(o, x, z) + stl_facet(o, z, y) + stl_facet(x, y, z);
  text += stl_facet(p, r, q) + stl_facet(p, q, s) + stl_facet(p, s, r) + stl_facet(q, r, s) + "endsolid t\n";
  const fs::path f = write("touch.stl", text);
  ASSERT_EQ(run("check-surface '" + f.string() + "'"), 1) << out_;
  EXPECT_NE(err_.find("triangle 0 (0 0 0)-(0 4 0)-(4 0 0) and triangle 4 (0.25 0.25 0)"), std::string::npos) << err_;
  EXPECT_NE(err_.find("intersect"), std::string::npos) << err_;
}

TEST_F(CheckSurfaceCommand, UnreadableAndMisuse) {
  EXPECT_EQ(run("check-surface '" + (dir_ / "missing.stl").string() + "'"), 2);
  EXPECT_EQ(err_.rfind("error: ", 0), 0u) << err_;
  EXPECT_EQ(run("check-surface"), 2);
  EXPECT_EQ(run("check-surface --help"), 0);
  EXPECT_NE(out_.find("usage: certimesh check-surface SURFACE"), std::string::npos);
  const fs::path open = write("open.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
  EXPECT_EQ(run("check-surface '" + open.string() + "'"), 1);
  EXPECT_NE(err_.find("is open"), std::string::npos) << err_;
}

}  // namespace
