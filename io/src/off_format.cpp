// OFF reader (off_format.h). Line records: a vertex or a face is one line, so a short line is
// named instead of silently borrowing the next line's numbers.
#include "certimesh/io/off_format.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <string_view>

#include "text_reader.h"

namespace certimesh::io {

namespace {

using detail::TextReader;

constexpr std::int64_t kMaxCount = std::numeric_limits<std::uint32_t>::max();

struct OffParser {
  TextReader& in;
  MeshData mesh;
  std::vector<std::vector<Index>> faces;

  void read_header() {
    const std::string_view first = in.next_token();
    if (first.empty()) in.fail("empty file (expected OFF)");
    if (first == "COFF" || first == "NOFF" || first == "CNOFF" || first == "STOFF" || first == "4OFF" || first == "nOFF") {
      in.fail("the " + std::string(first) + " variant is not supported (certimesh reads plain OFF: x y z per vertex)");
    }
    if (first != "OFF") in.fail("expected OFF, got " + TextReader::quoted(first));
    // `OFF BINARY` then fails on its count: "expected vertex count (an integer), got 'BINARY'".
  }

  void read_vertices(std::size_t count) {
    mesh.coordinates.reserve(3 * count);
    for (std::size_t v = 0; v < count; ++v) {
      in.begin_record();
      for (int k = 0; k < 3; ++k) mesh.coordinates.push_back(in.read_double("coordinate"));
      in.end_record("the vertex's x y z");
    }
  }

  void read_face(std::size_t vertex_count) {
    in.begin_record();
    const auto corners = static_cast<std::size_t>(in.read_integer("face corner count", 0, kMaxCount));
    if (corners < 3) in.fail("a face of " + std::to_string(corners) + " corners (a face needs at least 3)");
    in.check_count_fits("face corner count", corners, 2);
    std::vector<Index> face;
    face.reserve(corners);
    for (std::size_t k = 0; k < corners; ++k) {
      const std::int64_t i = in.read_integer("vertex index", std::numeric_limits<std::int64_t>::min(), std::numeric_limits<std::int64_t>::max());
      if (i < 0 || static_cast<std::uint64_t>(i) >= vertex_count) {
        in.fail("vertex index " + std::to_string(i) + " does not exist (the file has " + std::to_string(vertex_count) + " vertices, numbered from 0)");
      }
      const auto index = static_cast<Index>(i);
      if (std::find(face.begin(), face.end(), index) != face.end()) in.fail("vertex " + std::to_string(i) + " twice in one face");
      face.push_back(index);
    }
    while (in.record_has_more()) in.read_double("face colour");  // colours: numbers, ignored
    in.end_record("the face");
    faces.push_back(std::move(face));
  }

  // Every face a triangle: MeshData::triangles; otherwise every face a one-polygon facet.
  void store_faces() {
    const bool all_triangles = std::all_of(faces.begin(), faces.end(), [](const auto& f) { return f.size() == 3; });
    FacetList& f = mesh.facets;
    for (const auto& face : faces) {
      if (all_triangles) {
        mesh.triangles.insert(mesh.triangles.end(), face.begin(), face.end());
        continue;
      }
      f.corners.insert(f.corners.end(), face.begin(), face.end());
      f.polygon_end.push_back(f.corners.size());
      f.facet_end.push_back(f.polygon_end.size());
      f.hole_end.push_back(0);
    }
  }

  MeshData parse() {
    mesh.dimension = 3;
    read_header();
    const std::size_t vertex_count = in.read_count("vertex count", 6);  // "0 0 0\n" at least
    const std::size_t face_count = in.read_count("face count", 8);      // "3 0 1 2\n"
    in.read_integer("edge count", 0, std::numeric_limits<std::int64_t>::max());  // ignored, as every reader does
    // "0 0 0\n" per vertex and "3 0 1 2\n" per face at least, the last line break optional.
    if (6 * vertex_count + 8 * face_count > in.remaining_bytes() + 1)
      in.fail(std::to_string(vertex_count) + " vertices and " + std::to_string(face_count) + " faces cannot fit in the " +
              std::to_string(in.remaining_bytes()) + " bytes left in the file");
    read_vertices(vertex_count);
    faces.reserve(face_count);
    for (std::size_t f = 0; f < face_count; ++f) read_face(vertex_count);
    if (!in.at_end()) {
      in.next_token();
      in.fail("unexpected data after the " + std::to_string(face_count) + " faces the header announces");
    }
    store_faces();
    return std::move(mesh);
  }
};

}  // namespace

MeshData parse_off_format(std::string name, std::string contents) {
  TextReader in(std::move(name), std::move(contents));
  return OffParser{in, {}, {}}.parse();
}

MeshData read_off_format(const std::filesystem::path& path) {
  TextReader in(path);
  return OffParser{in, {}, {}}.parse();
}

}  // namespace certimesh::io
