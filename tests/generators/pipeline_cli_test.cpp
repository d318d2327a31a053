// `certimesh mesh` end to end through the real binary: every mesh it writes passes
// `certimesh check --domain` (a second, separate process: the certificate reads the files
// back), the certificate JSON and the SVG picture are written, and bad input gives `error:`,
// a non-zero exit status and no output file at all.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

const std::string kCli = CERTIMESH_CLI;

std::string shell_quoted(const fs::path& p) {
  std::string q(1, '\'');
  q.append(p.string());
  q.push_back('\'');
  return q;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

class MeshCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("certimesh_mesh_cli_" + std::to_string(getpid()));
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  // Runs `certimesh ARGS`, stdout and stderr captured; returns the exit status.
  int run(const std::string& args) {
    const std::string command =
        shell_quoted(kCli) + " " + args + " > " + shell_quoted(dir_ / "stdout") + " 2> " + shell_quoted(dir_ / "stderr");
    const int status = std::system(command.c_str());
    out_ = slurp(dir_ / "stdout");
    err_ = slurp(dir_ / "stderr");
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }

  fs::path dir_;
  std::string out_, err_;
};

TEST_F(MeshCommand, DefaultPlateIsWrittenCertifiedAndPictured) {
  for (const char* algorithm : {"front", "delaunay"}) {
    const fs::path mesh = dir_ / (std::string("plate_") + algorithm + ".vtu");
    const fs::path domain = dir_ / "plate.poly";
    ASSERT_EQ(run("mesh builtin:plate -o " + shell_quoted(mesh) + " --algorithm " + algorithm + " --certificate " +
                  shell_quoted(dir_ / "c.json") + " --svg " + shell_quoted(dir_ / "p.svg") + " --save-domain " + shell_quoted(domain)),
              0)
        << err_;
    EXPECT_NE(out_.find("triangles"), std::string::npos);
    EXPECT_NE(slurp(dir_ / "c.json").find("\"valid\": true"), std::string::npos) << slurp(dir_ / "c.json");
    EXPECT_NE(slurp(dir_ / "p.svg").find("<svg"), std::string::npos);
    // The independent check, in a process of its own, of the files as written.
    EXPECT_EQ(run("check " + shell_quoted(mesh) + " --domain " + shell_quoted(domain)), 0) << out_ << err_;
  }
}

TEST_F(MeshCommand, PolyFileWithSizeInEveryFormat) {
  const fs::path poly = dir_ / "l.poly";
  std::ofstream(poly) << "6 2 0 0\n1 0 0\n2 2 0\n3 2 1\n4 1 1\n5 1 2\n6 0 2\n6 1\n1 1 2 1\n2 2 3 1\n3 3 4 1\n"
                         "4 4 5 1\n5 5 6 1\n6 6 1 1\n0\n";
  for (const char* ext : {".mesh", ".msh", ".vtu", ".node"}) {
    const fs::path mesh = dir_ / (std::string("l") + ext);
    ASSERT_EQ(run("mesh " + shell_quoted(poly) + " -o " + shell_quoted(mesh) + " --size 0.1 --quiet"), 0) << err_;
    EXPECT_EQ(run("check " + shell_quoted(mesh) + " --domain " + shell_quoted(poly)), 0) << ext << ": " << out_ << err_;
  }
}

TEST_F(MeshCommand, InvalidDomainIsNamedAndNothingIsWritten) {
  const fs::path poly = dir_ / "bowtie.poly";
  std::ofstream(poly) << "4 2 0 0\n1 0 0\n2 1 1\n3 1 0\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n";
  const fs::path mesh = dir_ / "bowtie.vtu";
  EXPECT_EQ(run("mesh " + shell_quoted(poly) + " -o " + shell_quoted(mesh) + " --certificate " + shell_quoted(dir_ / "c.json")), 1);
  EXPECT_NE(err_.find("error:"), std::string::npos);
  EXPECT_NE(err_.find("cross"), std::string::npos) << err_;
  EXPECT_FALSE(fs::exists(mesh));
  EXPECT_FALSE(fs::exists(dir_ / "c.json"));
}

TEST_F(MeshCommand, NonFiniteCoordinateIsRefusedWithItsLine) {
  const fs::path poly = dir_ / "nan.poly";
  std::ofstream(poly) << "3 2 0 0\n1 0 0\n2 nan 0\n3 0 1\n3 0\n1 1 2\n2 2 3\n3 3 1\n0\n";
  EXPECT_NE(run("mesh " + shell_quoted(poly) + " -o " + shell_quoted(dir_ / "x.vtu")), 0);
  EXPECT_NE(err_.find("error:"), std::string::npos);
  EXPECT_FALSE(fs::exists(dir_ / "x.vtu"));
}

TEST_F(MeshCommand, BadOptionsAreUsageErrors) {
  EXPECT_EQ(run("mesh builtin:plate -o " + shell_quoted(dir_ / "x.vtu") + " --size -1"), 2);
  EXPECT_EQ(run("mesh builtin:plate -o " + shell_quoted(dir_ / "x.vtu") + " --gamma 0.5"), 2);
  EXPECT_EQ(run("mesh builtin:plate"), 2);
  EXPECT_EQ(run("mesh builtin:nothing -o " + shell_quoted(dir_ / "x.vtu")), 2);
  EXPECT_FALSE(fs::exists(dir_ / "x.vtu"));
}

}  // namespace
