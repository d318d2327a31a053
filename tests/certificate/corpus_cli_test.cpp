// The fixed corpus (corpus/MANIFEST.tsv, written by corpus/make_corpus.py) through the CLI:
// `certimesh check FILE [--domain D] --certificate OUT.json` must exit 0 (valid), 1 (invalid)
// or 2 (unreadable) as the manifest says, name the expected defect on stdout (or say
// "error: FILE..." on stderr), and write a certificate JSON that parses and records the
// element count, the verdict, the defect, a SHA-256 digest and the version (checked by
// check_certificate_json.py under /usr/bin/python3) -- or no certificate when unreadable.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;

struct CorpusCase {
  std::string file;
  std::string domain;  // empty: none
  int exit_code = 0;
  std::vector<std::string> defects;  // alternatives ('|' in the manifest); empty for exit 2
  std::string elements;
};

// Test names and failure messages show a case as its manifest row, not as bytes.
void PrintTo(const CorpusCase& c, std::ostream* os) {
  *os << c.file << " " << (c.domain.empty() ? "-" : c.domain) << " exit " << c.exit_code;
}

const fs::path kDataDir = CERTIMESH_TEST_DATA_DIR;

std::vector<CorpusCase> read_manifest() {
  std::vector<CorpusCase> cases;
  std::ifstream in(kDataDir / "corpus" / "MANIFEST.tsv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    std::istringstream fields(line);
    CorpusCase c;
    std::string domain, exit_code, defects;
    std::getline(fields, c.file, '\t');
    std::getline(fields, domain, '\t');
    std::getline(fields, exit_code, '\t');
    std::getline(fields, defects, '\t');
    std::getline(fields, c.elements, '\t');
    c.domain = domain == "-" ? "" : domain;
    c.exit_code = std::stoi(exit_code);
    std::istringstream alternatives(defects);
    for (std::string d; std::getline(alternatives, d, '|');)
      if (d != "-") c.defects.push_back(d);
    cases.push_back(c);
  }
  return cases;
}

// Appends rather than operator+ chains: GCC 12 reports a false -Wrestrict on the latter.
std::string quoted(const fs::path& p) {
  std::string q(1, '\'');
  q.append(p.string());
  q.push_back('\'');
  return q;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

int exit_status(int system_result) { return WIFEXITED(system_result) ? WEXITSTATUS(system_result) : -1; }

class Corpus : public ::testing::TestWithParam<CorpusCase> {
 protected:
  void SetUp() override {
    out_ = fs::temp_directory_path() / ("certimesh_corpus_" + std::to_string(getpid()) + "_" +
                                        std::to_string(counter_++));
    fs::create_directories(out_);
  }
  void TearDown() override { fs::remove_all(out_); }
  fs::path out_;
  static inline int counter_ = 0;
};

TEST_P(Corpus, CheckReportsTheExpectedVerdict) {
  const CorpusCase& c = GetParam();
  const fs::path corpus = kDataDir / "corpus";
  const fs::path json = out_ / "certificate.json";
  std::string command = quoted(CERTIMESH_CLI) + " check " + quoted(corpus / c.file);
  if (!c.domain.empty()) command += " --domain " + quoted(corpus / c.domain);
  command += " --certificate " + quoted(json) + " >" + quoted(out_ / "stdout") + " 2>" + quoted(out_ / "stderr");
  const int code = exit_status(std::system(command.c_str()));
  const std::string out = slurp(out_ / "stdout");
  const std::string err = slurp(out_ / "stderr");
  ASSERT_EQ(code, c.exit_code) << command << "\nstdout: " << out << "\nstderr: " << err;

  if (c.exit_code == 2) {
    EXPECT_NE(err.find("error: "), std::string::npos) << err;
    const std::string& culprit = c.domain.find("does_not_exist") != std::string::npos ? c.domain : c.file;
    EXPECT_NE(err.find(culprit), std::string::npos) << "the error should name " << culprit << ": " << err;
    EXPECT_FALSE(fs::exists(json)) << "a certificate was written for unreadable input";
    return;
  }
  if (c.exit_code == 0) {
    EXPECT_NE(out.find("valid: "), std::string::npos) << out;
    EXPECT_EQ(out.find("invalid"), std::string::npos) << out;
  } else {
    bool named = false;
    for (const std::string& d : c.defects) named = named || out.find("invalid: " + d) != std::string::npos;
    EXPECT_TRUE(named) << "expected invalid: " << c.defects.front() << "\n" << out;
  }
  ASSERT_TRUE(fs::exists(json));
  std::string defects;
  for (const std::string& d : c.defects) {
    if (!defects.empty()) defects.push_back('|');
    defects.append(d);
  }
  const std::string check = "/usr/bin/python3 " + quoted(kDataDir / "check_certificate_json.py") + " " +
                            quoted(json) + " " + std::to_string(c.exit_code) + " '" +
                            (defects.empty() ? "none" : defects) + "' " + c.elements;
  EXPECT_EQ(exit_status(std::system(check.c_str())), 0) << check << "\n" << slurp(json);
}

std::string case_name(const ::testing::TestParamInfo<CorpusCase>& p) {
  std::string name = p.param.file.substr(0, p.param.file.find('.'));
  if (!p.param.domain.empty()) name += "_with_" + p.param.domain.substr(0, p.param.domain.find('.'));
  for (char& ch : name)
    if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
  return name;
}

INSTANTIATE_TEST_SUITE_P(Cli, Corpus, ::testing::ValuesIn(read_manifest()), case_name);

TEST(CorpusManifest, CoversEveryDefect) {
  // Every Defect name except the two the readers refuse before the checker runs
  // (index_out_of_range, non_finite_coordinate: exit 2 by the issue) appears in the manifest.
  const std::vector<std::string> names{
      "no_elements", "duplicate_vertex", "unused_vertex", "repeated_vertex", "duplicate_element",
      "non_manifold_facet", "inconsistent_orientation", "flat_element", "inverted_element",
      "non_manifold_boundary", "t_junction", "boundary_intersection", "multiple_cover", "invalid_domain",
      "facet_off_domain_boundary", "vertex_off_domain_boundary", "domain_boundary_not_covered",
      "hole_covered", "region_not_meshed"};
  const std::string manifest = slurp(kDataDir / "corpus" / "MANIFEST.tsv");
  for (const std::string& n : names) EXPECT_NE(manifest.find(n), std::string::npos) << n;
}

}  // namespace
