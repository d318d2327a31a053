// STL reader (stl_format.h).
#include "certimesh/io/stl_format.h"

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string_view>
#include <unordered_map>

#include "certimesh/io/format_error.h"
#include "text_reader.h"

namespace certimesh::io {

namespace {

using detail::TextReader;

// Corners to vertices: equal coordinates (-0 == 0) are one vertex, first appearance first.
class Welder {
 public:
  explicit Welder(MeshData& mesh) : mesh_(mesh) {}

  Index vertex(const std::array<double, 3>& p) {
    Key key{};
    for (int k = 0; k < 3; ++k) key[std::size_t(k)] = std::bit_cast<std::uint64_t>(p[std::size_t(k)] == 0.0 ? 0.0 : p[std::size_t(k)]);
    const auto [it, inserted] = index_.emplace(key, static_cast<Index>(mesh_.point_count()));
    if (inserted) mesh_.coordinates.insert(mesh_.coordinates.end(), p.begin(), p.end());
    return it->second;
  }

 private:
  using Key = std::array<std::uint64_t, 3>;
  struct Hash {
    std::size_t operator()(const Key& k) const noexcept {
      std::uint64_t h = 0x9e3779b97f4a7c15ull;
      for (const std::uint64_t x : k) h = (h ^ x) * 0xff51afd7ed558ccdull, h ^= h >> 32;
      return static_cast<std::size_t>(h);
    }
  };
  MeshData& mesh_;
  std::unordered_map<Key, Index, Hash> index_;  // looked up only, never iterated: deterministic
};

bool iequals(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto lower = [](char c) { return c >= 'A' && c <= 'Z' ? char(c - 'A' + 'a') : c; };
    if (lower(a[i]) != lower(b[i])) return false;
  }
  return true;
}

void expect_keyword(TextReader& in, std::string_view keyword) {
  std::string quoted(1, '\'');  // (not "'" + std::string: GCC 12's -Wrestrict false positive)
  quoted.append(keyword);
  quoted.push_back('\'');
  const std::string_view token = in.expect_token(quoted);
  if (!iequals(token, keyword)) in.fail("expected " + quoted + ", got " + TextReader::quoted(token));
}

MeshData parse_ascii(std::string name, std::string contents) {
  TextReader in(std::move(name), std::move(contents));
  in.set_comment_chars("");
  MeshData mesh;
  mesh.dimension = 3;
  Welder weld(mesh);
  Label solid = 0;
  for (std::string_view token = in.next_token(); !token.empty(); token = in.next_token()) {
    if (!iequals(token, "solid")) in.fail("expected 'solid', got " + TextReader::quoted(token));
    ++solid;
    in.rest_of_line();  // the solid's name
    for (;;) {
      const std::string_view t = in.expect_token("'facet' or 'endsolid'");
      if (iequals(t, "endsolid")) break;
      if (!iequals(t, "facet")) in.fail("expected 'facet' or 'endsolid', got " + TextReader::quoted(t));
      expect_keyword(in, "normal");
      for (int k = 0; k < 3; ++k) in.expect_token("a normal component");  // ignored
      expect_keyword(in, "outer");
      expect_keyword(in, "loop");
      for (int c = 0; c < 3; ++c) {
        expect_keyword(in, "vertex");
        std::array<double, 3> p{};
        for (double& x : p) x = in.read_double("vertex coordinate");
        mesh.triangles.push_back(weld.vertex(p));
      }
      const std::string_view end = in.expect_token("'endloop'");
      if (iequals(end, "vertex")) in.fail("a facet with more than 3 vertices (STL facets are triangles)");
      if (!iequals(end, "endloop")) in.fail("expected 'endloop', got " + TextReader::quoted(end));
      expect_keyword(in, "endfacet");
      mesh.triangle_labels.push_back(solid);
    }
    in.rest_of_line();  // the name after endsolid
  }
  if (solid == 0) in.fail("empty file (expected 'solid')");
  if (solid == 1) mesh.triangle_labels.clear();
  return mesh;
}

std::uint32_t little_endian_32(const char* bytes) {
  std::uint32_t x = 0;
  std::memcpy(&x, bytes, 4);
  if constexpr (std::endian::native == std::endian::big) x = __builtin_bswap32(x);
  return x;
}

MeshData parse_binary(const std::string& name, const std::string& contents, std::size_t count) {
  MeshData mesh;
  mesh.dimension = 3;
  mesh.triangles.reserve(3 * count);
  Welder weld(mesh);
  for (std::size_t t = 0; t < count; ++t) {
    const char* record = contents.data() + 84 + 50 * t + 12;  // after the normal
    for (int c = 0; c < 3; ++c) {
      std::array<double, 3> p{};
      for (int k = 0; k < 3; ++k) {
        p[std::size_t(k)] = std::bit_cast<float>(little_endian_32(record + 12 * c + 4 * k));
        if (!std::isfinite(p[std::size_t(k)])) {
          throw FormatError(name, 0, "triangle " + std::to_string(t) + " (0-based), corner " + std::to_string(c) +
                                         ": coordinate is not finite (" + (std::isnan(p[std::size_t(k)]) ? "nan" : "inf") + ")");
        }
      }
      mesh.triangles.push_back(weld.vertex(p));
    }
  }
  return mesh;
}

bool begins_with_solid(const std::string& contents) {
  std::size_t i = 0;
  while (i < contents.size() && (contents[i] == ' ' || contents[i] == '\t' || contents[i] == '\r' || contents[i] == '\n')) ++i;
  return iequals(std::string_view(contents).substr(i, 5), "solid");
}

}  // namespace

MeshData parse_stl_format(std::string name, std::string contents) {
  if (contents.size() >= 84) {
    const std::uint64_t count = little_endian_32(contents.data() + 80);
    if (84 + 50 * count == contents.size()) return parse_binary(name, contents, count);
  }
  if (begins_with_solid(contents) && contents.find('\0') == std::string::npos) return parse_ascii(std::move(name), std::move(contents));
  if (contents.size() < 84) {
    throw FormatError(name, 0, "not an STL file: " + std::to_string(contents.size()) +
                                   " bytes, too short for binary STL (84 bytes at least) and not beginning with 'solid'");
  }
  const std::uint64_t count = little_endian_32(contents.data() + 80);
  throw FormatError(name, 0, "binary STL header announces " + std::to_string(count) + " triangles (84 + 50*" +
                                 std::to_string(count) + " = " + std::to_string(84 + 50 * count) + " bytes) but the file has " +
                                 std::to_string(contents.size()) + " bytes (truncated?)");
}

MeshData read_stl_format(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FormatError(path.string(), 0, "cannot open the file for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw FormatError(path.string(), 0, "read error");
  return parse_stl_format(path.string(), std::move(buffer).str());
}

}  // namespace certimesh::io
