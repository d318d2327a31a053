// Medit .mesh, ASCII (the INRIA libMeshb keyword format). A file is a sequence of keywords;
// the ones certimesh holds are read, simplicial sections it cannot hold are refused, and any
// other keyword followed by a count is skipped one line per record. Indices are 1-based.
#include "certimesh/io/medit_format.h"

#include <array>
#include <cstdint>
#include <limits>
#include <string_view>

#include "certimesh/io/mesh_file.h"
#include "text_labels.h"
#include "text_reader.h"
#include "text_writer.h"

namespace certimesh::io {

namespace {

using detail::TextReader;

constexpr std::int64_t kMeditIntegerMin = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kMeditIntegerMax = std::numeric_limits<std::int64_t>::max();

Label read_ref(TextReader& in, std::string_view what) {
  return static_cast<Label>(in.read_integer(what, std::numeric_limits<Label>::min(),
                                            std::numeric_limits<Label>::max()));
}

Index read_vertex_index(TextReader& in, std::size_t vertex_count) {
  const std::int64_t i = in.read_integer("vertex index", kMeditIntegerMin, kMeditIntegerMax);
  if (i == 0) in.fail("vertex index 0 in a 1-based file (the first vertex is 1)");
  if (i < 0 || static_cast<std::uint64_t>(i) > vertex_count) {
    in.fail("vertex index " + std::to_string(i) + " does not exist (the file has " +
            std::to_string(vertex_count) + " vertices, numbered from 1)");
  }
  return static_cast<Index>(i - 1);
}

// The parser's state: which sections it has read, so that each is read once and in an order
// where every index refers to vertices already known.
struct MeditParser {
  TextReader& in;
  MeshData mesh;
  bool have_dimension = false;
  bool have_vertices = false;
  bool have_edges = false;
  bool have_triangles = false;
  bool have_tetrahedra = false;

  void read_dimension() {
    if (have_dimension) in.fail("a second Dimension keyword");
    mesh.dimension = static_cast<int>(in.read_integer("dimension (2 or 3)", 2, 3));
    have_dimension = true;
  }

  void read_vertices() {
    if (!have_dimension) in.fail("Vertices before Dimension");
    if (have_vertices) in.fail("a second Vertices section");
    const auto dim = static_cast<std::size_t>(mesh.dimension);
    const std::size_t count = in.read_count("vertex count", dim + 1);  // a byte per field at least
    mesh.coordinates.reserve(count * dim);
    mesh.point_labels.reserve(count);
    for (std::size_t v = 0; v < count; ++v) {
      for (std::size_t k = 0; k < dim; ++k) mesh.coordinates.push_back(in.read_double("coordinate"));
      mesh.point_labels.push_back(read_ref(in, "vertex reference"));
    }
    detail::drop_all_zero(mesh.point_labels);
    have_vertices = true;
  }

  void read_cells(std::string_view keyword, std::size_t corners, bool& seen,
                  std::vector<Index>& cells, std::vector<Label>& labels) {
    if (!have_vertices) in.fail(std::string(keyword) + " before Vertices");
    if (seen) in.fail("a second " + std::string(keyword) + " section");
    const std::size_t count = in.read_count(std::string(keyword) + " count", corners + 1);
    cells.reserve(count * corners);
    labels.reserve(count);
    const std::size_t vertex_count = mesh.point_count();
    for (std::size_t c = 0; c < count; ++c) {
      for (std::size_t k = 0; k < corners; ++k) cells.push_back(read_vertex_index(in, vertex_count));
      labels.push_back(read_ref(in, "reference"));
    }
    detail::drop_all_zero(labels);
    seen = true;
  }

  // A keyword certimesh does not hold: its count, then one record per line.
  void skip_section(std::string_view keyword) {
    const std::string name = TextReader::quoted(keyword);  // the keyword may be any length
    const std::size_t count = in.read_count(name + " count", 2);
    in.rest_of_line();
    for (std::size_t r = 0; r < count; ++r) {
      in.begin_record();
      if (!in.record_has_more()) {
        in.fail("unexpected end of file in the " + name + " section");
      }
      while (in.record_has_more()) in.next_token();
      in.end_record(name);
    }
  }

  bool read_keyword(std::string_view keyword) {
    if (keyword == "End") return false;
    if (keyword == "Dimension") {
      read_dimension();
    } else if (keyword == "Vertices") {
      read_vertices();
    } else if (keyword == "Edges") {
      read_cells(keyword, 2, have_edges, mesh.segments, mesh.segment_labels);
    } else if (keyword == "Triangles") {
      read_cells(keyword, 3, have_triangles, mesh.triangles, mesh.triangle_labels);
    } else if (keyword == "Tetrahedra") {
      if (mesh.dimension != 3) in.fail("Tetrahedra in a 2D file");
      read_cells(keyword, 4, have_tetrahedra, mesh.tetrahedra, mesh.tetrahedron_labels);
    } else if (keyword == "Quadrilaterals" || keyword == "Hexahedra" || keyword == "Prisms" ||
               keyword == "Pyramids") {
      in.fail(std::string(keyword) + " are not supported: certimesh holds simplicial meshes");
    } else if (keyword == "MeshVersionFormatted") {
      in.fail("a second MeshVersionFormatted keyword");
    } else if (!keyword.empty() && ((keyword[0] >= 'A' && keyword[0] <= 'Z') ||
                                    (keyword[0] >= 'a' && keyword[0] <= 'z'))) {
      skip_section(keyword);
    } else {
      in.fail("expected a keyword, got " + TextReader::quoted(keyword));
    }
    return true;
  }

  MeshData parse() {
    const std::string_view first = in.next_token();
    if (first.empty()) in.fail("empty file (expected MeshVersionFormatted)");
    if (first != "MeshVersionFormatted") {
      in.fail("expected MeshVersionFormatted, got " + TextReader::quoted(first));
    }
    in.read_integer("MeshVersionFormatted (1 or 2 in an ASCII file)", 1, 2);
    for (;;) {
      const std::string_view keyword = in.next_token();
      if (keyword.empty()) in.fail("missing End (truncated file?)");
      if (!read_keyword(keyword)) break;
    }
    if (!have_dimension) in.fail("End before Dimension");
    return std::move(mesh);
  }
};

void append_cells(std::string& out, const char* keyword, const std::vector<Index>& cells,
                  const std::vector<Label>& labels, std::size_t corners) {
  if (cells.empty()) return;
  const std::size_t count = cells.size() / corners;
  out += keyword;
  out += '\n';
  detail::append_integer(out, count);
  out += '\n';
  for (std::size_t c = 0; c < count; ++c) {
    for (std::size_t k = 0; k < corners; ++k) {
      detail::append_integer(out, std::uint64_t{cells[c * corners + k]} + 1);
      out += ' ';
    }
    detail::append_integer(out, labels.empty() ? Label{0} : labels[c]);
    out += '\n';
  }
}

std::string format_medit_named(const MeshData& mesh, const std::string& name) {
  detail::check_writable(mesh, name);
  if (!mesh.holes.empty() || !mesh.region_points.empty()) {
    throw FormatError(name, 0, "a .mesh file cannot hold holes or region points (write a .poly)");
  }
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  std::string out = "MeshVersionFormatted 2\nDimension " + std::to_string(dim) + "\n";
  const std::size_t n = mesh.point_count();
  if (n > 0) {
    out += "Vertices\n";
    detail::append_integer(out, n);
    out += '\n';
    for (std::size_t v = 0; v < n; ++v) {
      for (std::size_t k = 0; k < dim; ++k) {
        append_double(out, mesh.coordinates[v * dim + k]);
        out += ' ';
      }
      detail::append_integer(out, mesh.point_labels.empty() ? Label{0} : mesh.point_labels[v]);
      out += '\n';
    }
  }
  append_cells(out, "Edges", mesh.segments, mesh.segment_labels, 2);
  append_cells(out, "Triangles", mesh.triangles, mesh.triangle_labels, 3);
  append_cells(out, "Tetrahedra", mesh.tetrahedra, mesh.tetrahedron_labels, 4);
  out += "End\n";
  return out;
}

}  // namespace

MeshData parse_medit_format(std::string name, std::string contents) {
  TextReader in(std::move(name), std::move(contents));
  return MeditParser{in, {}}.parse();
}

MeshData read_medit_format(const std::filesystem::path& path) {
  TextReader in(path);
  return MeditParser{in, {}}.parse();
}

std::string format_medit(const MeshData& mesh) { return format_medit_named(mesh, "(.mesh output)"); }

void write_medit_format(const MeshData& mesh, const std::filesystem::path& path) {
  write_file_atomically(path, format_medit_named(mesh, path.string()));
}

}  // namespace certimesh::io
