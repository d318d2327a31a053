// Malformed and hostile .msh input: every case is a FormatError naming the file, the line of
// the offending token and the problem, never a crash, a hang or a huge allocation.
#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "certimesh/io/format_error.h"
#include "certimesh/io/gmsh_format.h"
#include "text_mutation.h"

namespace certimesh::testing {
namespace {

struct MalformedCase {
  const char* title;
  std::string text;
  std::size_t line;  // the line the error must name (counted by hand in `text`)
  const char* why;   // a fragment the message must contain
};

const std::string kHeader = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";                 // lines 1-3
const std::string kNodes = "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n";  // 4-13

std::vector<MalformedCase> cases() {
  return {
      {"empty file", "", 1, "expected $MeshFormat"},
      {"garbage", "hello world\n", 1, "expected $MeshFormat"},
      {"version 2.2", "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n", 2, "version 2.2 is not supported"},
      {"version 4", "$MeshFormat\n4 0 8\n$EndMeshFormat\n", 2, "version 4 is not supported"},
      {"binary", "$MeshFormat\n4.1 1 8\n$EndMeshFormat\n", 2, "binary"},
      {"no nodes", kHeader, 4, "no $Nodes section"},
      {"truncated nodes", kHeader + "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0", 6, "cannot fit"},
      {"missing $EndNodes", kHeader + "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n", 13,
       "expected $EndNodes"},
      {"blocks hold more nodes than declared", kHeader + "$Nodes\n1 2 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n",
       5, "declares 2 nodes, its blocks hold 3"},
      {"more blocks than present", kHeader + "$Nodes\n2 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n", 13,
       "entity dimension"},
      {"NaN coordinate", kHeader + "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 nan 0\n0 1 0\n$EndNodes\n", 11,
       "not finite"},
      {"Inf coordinate", kHeader + "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 0\n1 0 0\n-inf 1 0\n$EndNodes\n", 12,
       "not finite"},
      {"coordinate out of range", kHeader + "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n3\n0 0 1e400\n1 0 0\n0 1 0\n$EndNodes\n", 10,
       "out of the range"},
      {"node tag 0", kHeader + "$Nodes\n1 3 1 3\n2 1 0 3\n1\n0\n3\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n", 8, "node tag 0"},
      {"duplicate node tag", kHeader + "$Nodes\n1 3 1 3\n2 1 0 3\n1\n2\n2\n0 0 0\n1 0 0\n0 1 0\n$EndNodes\n", 9,
       "node tag 2 appears twice"},
      {"a billion nodes", kHeader + "$Nodes\n1 1000000000 1 1000000000\n2 1 0 1000000000\n1\n0 0 0\n$EndNodes\n", 5,
       "cannot fit"},
      {"a billion elements", kHeader + kNodes + "$Elements\n1 1000000000 1 1000000000\n2 1 2 1000000000\n1 1 2 3\n$EndElements\n",
       15, "cannot fit"},
      {"a billion elements in a block", kHeader + kNodes + "$Elements\n1 1 1 1\n2 1 2 1000000000\n1 1 2 3\n$EndElements\n",
       16, "cannot fit"},
      {"element names a missing node", kHeader + kNodes + "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 4\n$EndElements\n", 17,
       "node tag 4, which no $Nodes block defines"},
      {"element count differs from blocks", kHeader + kNodes + "$Elements\n1 2 1 2\n2 1 2 1\n1 1 2 3\n$EndElements\n", 15,
       "declares 2 elements, its blocks hold 1"},
      {"truncated element block", kHeader + kNodes + "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2", 16, "cannot fit"},
      {"truncated element", kHeader + kNodes + "$Elements\n1 2 1 2\n2 1 2 2\n1 1 2 3\n2 1 2    \n", 19,
       "unexpected end of file"},
      {"quadrangle", kHeader + kNodes + "$Elements\n1 1 1 1\n2 1 3 1\n1 1 2 3 3\n$EndElements\n", 16,
       "element type 3 is not supported"},
      {"second-order triangle", kHeader + kNodes + "$Elements\n1 1 1 1\n2 1 9 1\n1 1 2 3 1 2 3\n$EndElements\n", 16,
       "element type 9 is not supported"},
      {"duplicate element tag", kHeader + kNodes + "$Elements\n1 2 1 2\n2 1 2 2\n1 1 2 3\n1 3 2 1\n$EndElements\n", 18,
       "element tag 1 appears twice"},
      {"elements before nodes", kHeader + "$Elements\n0 0 0 0\n$EndElements\n", 4, "$Elements before $Nodes"},
      {"unterminated section", kHeader + "$Comments\nsome text\n", 6, "no $EndComments"},
      {"stray token between sections", kHeader + kNodes + "42\n", 14, "expected a section"},
      {"physical tag beyond int32", kHeader + "$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 3000000000 0\n$EndEntities\n", 6,
       "physical tag"},
      {"point label not an integer",
       kHeader + kNodes + "$NodeData\n1\n\"label\"\n1\n0\n3\n0\n1\n1\n2 1.5\n$EndNodeData\n", 23, "not a 32-bit integer"},
      {"point label of a missing node",
       kHeader + kNodes + "$NodeData\n1\n\"label\"\n1\n0\n3\n0\n1\n1\n7 1\n$EndNodeData\n", 23, "node tag 7"},
      {"a billion point labels",
       kHeader + kNodes + "$NodeData\n1\n\"label\"\n1\n0\n3\n0\n1\n1000000000\n1 1\n$EndNodeData\n", 22, "more than the rest"},
  };
}

TEST(GmshMalformed, EveryCaseNamesFileLineAndWhy) {
  for (const MalformedCase& c : cases()) {
    SCOPED_TRACE(c.title);
    try {
      (void)io::parse_gmsh_format("bad.msh", c.text);
      ADD_FAILURE() << "accepted";
    } catch (const io::FormatError& e) {
      EXPECT_EQ(e.file(), "bad.msh");
      EXPECT_EQ(e.line(), c.line) << e.what();
      EXPECT_NE(e.why().find(c.why), std::string::npos) << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("bad.msh:" + std::to_string(c.line) + ": ", 0), 0u) << e.what();
    }
  }
}

TEST(GmshMalformed, EveryPrefixOfAValidFileIsRefusedOrReadNeverCrashes) {
  // Truncation anywhere: either a FormatError or (cut after $EndElements) the full mesh.
  const std::string text = kHeader + kNodes + "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n";
  for (std::size_t cut = 0; cut < text.size(); ++cut) {
    try {
      const io::MeshData m = io::parse_gmsh_format("cut.msh", text.substr(0, cut));
      EXPECT_TRUE(m.triangles.empty() || m.triangles == (std::vector<io::Index>{0, 1, 2})) << "cut " << cut;
    } catch (const io::FormatError& e) {
      EXPECT_GE(e.line(), 1u) << "cut " << cut;
    }
  }
}

TEST(GmshMalformed, MissingFileIsAFormatError) {
  EXPECT_THROW((void)io::read_gmsh_format(std::filesystem::path(::testing::TempDir()) / "certimesh_no_such_file.msh"), io::FormatError);
}

TEST(GmshMalformed, RandomByteMutationsOnlyEverThrowFormatError) {
  // Seeded (reproducible) corruption of a valid file: overwrite, insert or delete a few bytes,
  // biased towards characters that matter to the format. Anything but a FormatError or a
  // result fails; the sanitizer rerun of the suite catches memory errors on the way.
  const std::string valid = kHeader + kNodes + "$Elements\n1 1 1 1\n2 1 2 1\n1 1 2 3\n$EndElements\n$NodeData\n1\n\"label\"\n1\n0\n3\n0\n1\n1\n2 5\n$EndNodeData\n";
  std::mt19937_64 rng(20261129);
  std::size_t refused = 0;
  for (int round = 0; round < 20000; ++round) {
    const std::string text = mutate_text(valid, rng);
    try {
      (void)io::parse_gmsh_format("mutated.msh", text);
    } catch (const io::FormatError& error) {
      ++refused;
      EXPECT_EQ(std::string(error.what()).rfind("mutated.msh:", 0), 0u) << error.what();
    }
  }
  EXPECT_GT(refused, 5000u);  // the mutations do break the files
}

}  // namespace
}  // namespace certimesh::testing
