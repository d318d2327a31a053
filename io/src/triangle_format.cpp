// Triangle (2D) and TetGen (3D) files. One record per line; the first point of the .node (or
// of the .poly's inline points) is numbered 0 or 1 and fixes how every vertex reference of the
// mesh is numbered (as Triangle's `firstnumber`); each file's own records are numbered
// consecutively from 0 or 1. certimesh writes 1-based files.
#include "certimesh/io/triangle_format.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <string_view>

#include "certimesh/io/format_error.h"
#include "certimesh/io/mesh_file.h"
#include "text_labels.h"
#include "text_reader.h"
#include "text_writer.h"

namespace certimesh::io {

namespace {

using detail::TextReader;
namespace fs = std::filesystem;

constexpr std::int64_t kTriangleIntegerMin = std::numeric_limits<std::int64_t>::min();
constexpr std::int64_t kTriangleIntegerMax = std::numeric_limits<std::int64_t>::max();

// The bound behind every "count cannot fit in the file" check: each field of a record takes at
// least one byte. (Counting separators too would be tighter, but then a record that merely
// lacks a field could be reported as a wrong count on the header line rather than on its own
// line; the looser bound still keeps every allocation within a small multiple of the file.)
constexpr std::size_t kMinBytesPerField = 1;

// ---------------------------------------------------------------------------------------------
// Fields

// The numbers of one file's records: the first is 0 or 1, the others follow consecutively.
class RecordNumbers {
 public:
  explicit RecordNumbers(std::string what) : what_(std::move(what)) {}
  void read(TextReader& in, std::size_t index) {
    const std::int64_t id = in.read_integer(what_ + " number", kTriangleIntegerMin, kTriangleIntegerMax);
    if (index == 0) {
      if (id != 0 && id != 1) {
        in.fail("the first " + what_ + " is numbered " + std::to_string(id) + "; it must be 0 or 1");
      }
      first_ = id;
    } else if (id != first_ + static_cast<std::int64_t>(index)) {
      in.fail(what_ + " numbers must be consecutive: expected " +
              std::to_string(first_ + static_cast<std::int64_t>(index)) + ", got " +
              std::to_string(id));
    }
  }
  std::int64_t first() const { return first_; }

 private:
  std::string what_;
  std::int64_t first_ = 1;
};

// How vertex references are numbered: from the .node's first point number.
struct PointNumbering {
  std::int64_t first = 1;
  std::size_t count = 0;
};

Index read_vertex(TextReader& in, const PointNumbering& points, std::string_view what) {
  const std::int64_t id = in.read_integer(what, kTriangleIntegerMin, kTriangleIntegerMax);
  if (id == 0 && points.first == 1) {
    in.fail(std::string(what) + " is 0 in a 1-based file (the first point is numbered 1)");
  }
  if (id < points.first || static_cast<std::uint64_t>(id - points.first) >= points.count) {
    in.fail(std::string(what) + " " + std::to_string(id) + " does not exist (the points are " +
            (points.count == 0 ? std::string("none")
                               : "numbered " + std::to_string(points.first) + " to " +
                                     std::to_string(points.first - 1 +
                                                    static_cast<std::int64_t>(points.count))) +
            ")");
  }
  return static_cast<Index>(id - points.first);
}

Label read_marker(TextReader& in, std::string_view what) {
  return static_cast<Label>(in.read_integer(what, std::numeric_limits<Label>::min(),
                                            std::numeric_limits<Label>::max()));
}

// Element attributes are labels when every one is an integer in range (the common case, and
// the reading of a material id); otherwise they are kept as reals (Triangle's regional
// attributes such as 0.05) and the labels are labels_of_attributes of them.
bool integral_label(double value) {
  return std::trunc(value) == value && value >= std::numeric_limits<Label>::min() &&
         value <= std::numeric_limits<Label>::max();
}

void attributes_to_labels(std::vector<double>& attributes, std::vector<Label>& labels) {
  if (!std::all_of(attributes.begin(), attributes.end(), integral_label)) return;
  labels.reserve(attributes.size());
  for (const double a : attributes) labels.push_back(static_cast<Label>(a));
  attributes.clear();
}

std::size_t read_small_count(TextReader& in, std::string_view what) {
  return in.read_count(what, 2);  // each such field needs at least a digit and a separator
}

// ---------------------------------------------------------------------------------------------
// Sections

// "N dim nattr nmarker" and N point lines; returns how vertex references are numbered.
PointNumbering read_points(TextReader& in, MeshData& mesh) {
  in.begin_record();
  const auto count = static_cast<std::size_t>(in.read_integer("point count", 0, kTriangleIntegerMax));
  const auto dim = static_cast<std::size_t>(in.read_integer("dimension (2 or 3)", 2, 3));
  const std::size_t attributes = read_small_count(in, "point attribute count");
  const auto markers = in.read_integer("point marker count (0 or 1)", 0, 1);
  in.end_record("the point header");
  in.check_count_fits("point count", count, kMinBytesPerField * (1 + dim + attributes + static_cast<std::size_t>(markers)));
  mesh.dimension = static_cast<int>(dim);
  mesh.coordinates.reserve(count * dim);
  RecordNumbers numbers("point");
  for (std::size_t p = 0; p < count; ++p) {
    in.begin_record();
    numbers.read(in, p);
    for (std::size_t k = 0; k < dim; ++k) mesh.coordinates.push_back(in.read_double("coordinate"));
    for (std::size_t a = 0; a < attributes; ++a) in.read_double("point attribute");
    if (markers == 1) mesh.point_labels.push_back(read_marker(in, "point marker"));
    in.end_record("the point");
  }
  detail::drop_all_zero(mesh.point_labels);
  return {numbers.first(), count};
}

// A section of cells: "count [corners] nattr|nmarker", then "id v1..vk [label]" lines.
struct CellSection {
  std::string what;       // "triangle", "tetrahedron", "segment", "face"
  std::size_t corners;
  bool label_is_attribute;  // .ele: first regional attribute; .edge/.face: boundary marker
};

void read_cells(TextReader& in, const CellSection& section, const PointNumbering& points,
                std::vector<Index>& cells, std::vector<Label>& labels, std::vector<double>* attributes = nullptr) {
  in.begin_record();
  const auto count = static_cast<std::size_t>(in.read_integer(section.what + " count", 0, kTriangleIntegerMax));
  std::size_t fields_per_label = 0;
  if (section.label_is_attribute) {
    const auto corners = in.read_integer("nodes per " + section.what, 0, kTriangleIntegerMax);
    if (static_cast<std::size_t>(corners) != section.corners) {
      in.fail(std::to_string(corners) + " nodes per " + section.what + " (certimesh reads linear " +
              section.what + "s: " + std::to_string(section.corners) + ")");
    }
    fields_per_label = read_small_count(in, "attribute count");
  } else {
    fields_per_label = static_cast<std::size_t>(in.read_integer("boundary marker count (0 or 1)", 0, 1));
  }
  in.end_record("the " + section.what + " header");
  in.check_count_fits(section.what + " count", count, kMinBytesPerField * (1 + section.corners + fields_per_label));
  cells.reserve(count * section.corners);
  std::vector<double> real_attributes;
  RecordNumbers numbers(section.what);
  for (std::size_t c = 0; c < count; ++c) {
    in.begin_record();
    numbers.read(in, c);
    for (std::size_t k = 0; k < section.corners; ++k) cells.push_back(read_vertex(in, points, "vertex"));
    if (fields_per_label > 0 && section.label_is_attribute) {
      real_attributes.push_back(in.read_double("regional attribute"));
      if (attributes == nullptr && !integral_label(real_attributes.back())) {
        std::string shown;
        append_double(shown, real_attributes.back());
        in.fail("regional attribute " + shown + " of a " + section.what +
                " is not an integer label (only 2D triangles keep real attributes)");
      }
      for (std::size_t a = 1; a < fields_per_label; ++a) in.read_double("regional attribute");
    } else if (fields_per_label > 0) {
      labels.push_back(read_marker(in, "boundary marker"));
    }
    in.end_record("the " + section.what);
  }
  attributes_to_labels(real_attributes, labels);
  if (!real_attributes.empty()) {  // labels too, for the formats that keep only integers
    labels = labels_of_attributes(real_attributes);
    *attributes = std::move(real_attributes);
  }
  detail::drop_all_zero(labels);
}

// "count", then "id x y [z]" lines (holes), or "id x y [z] attribute [constraint]" (regions:
// the constraint is the maximum area in 2D, volume in 3D; a missing or negative one is none).
void read_domain_points(TextReader& in, int dimension, bool with_attribute, std::vector<double>& points,
                        MeshData* regions) {
  const std::string what = with_attribute ? "region" : "hole";
  in.begin_record();
  const auto dim = static_cast<std::size_t>(dimension);
  const std::size_t count = in.read_count(what + " count", kMinBytesPerField * (1 + dim));
  in.end_record("the " + what + " count");
  RecordNumbers numbers(what);
  for (std::size_t h = 0; h < count; ++h) {
    in.begin_record();
    numbers.read(in, h);
    for (std::size_t k = 0; k < dim; ++k) points.push_back(in.read_double(what + " coordinate"));
    if (with_attribute) {
      regions->region_attributes.push_back(in.read_double("regional attribute"));
      regions->region_max_measures.push_back(
          in.record_has_more() ? in.read_double(dimension == 2 ? "maximum area" : "maximum volume") : -1.0);
    }
    in.end_record("the " + what);
  }
  if (with_attribute && std::all_of(regions->region_max_measures.begin(), regions->region_max_measures.end(),
                                    [](double m) { return m < 0; })) {
    regions->region_max_measures.clear();
  }
}

// One polygon of a facet: "k c1 .. ck", the corners possibly continued on the following lines
// (TetGen reads them so); in a .smesh the facet's marker follows the last corner on its line.
void read_polygon(TextReader& in, const PointNumbering& points, FacetList& facets) {
  in.begin_record();
  const std::size_t corners = in.read_count("polygon corner count", 2);
  if (corners == 0) in.fail("a facet polygon with 0 corners");
  const std::size_t first = facets.corners.size();
  for (std::size_t k = 0; k < corners; ++k) {
    if (!in.record_has_more()) in.begin_record();  // the corner list goes on on the next line
    const Index v = read_vertex(in, points, "corner");
    for (std::size_t j = first; j < facets.corners.size(); ++j) {
      if (facets.corners[j] == v) {
        in.fail("the polygon repeats corner " + std::to_string(points.first + static_cast<std::int64_t>(v)));
      }
    }
    facets.corners.push_back(v);
  }
  facets.polygon_end.push_back(facets.corners.size());
}

// A .poly facet: "npolygons [nholes [marker]]", npolygons polygons, then nholes "id x y z".
void read_poly_facet(TextReader& in, const PointNumbering& points, bool with_marker, FacetList& facets) {
  in.begin_record();
  const std::size_t polygons = in.read_count("polygon count", 2);
  std::size_t holes = 0;
  if (in.record_has_more()) holes = in.read_count("facet hole count", 4);
  Label marker = 0;
  if (with_marker && in.record_has_more()) marker = read_marker(in, "facet marker");
  in.end_record("the facet header");
  for (std::size_t p = 0; p < polygons; ++p) {
    read_polygon(in, points, facets);
    in.end_record("the polygon's corners");
  }
  RecordNumbers numbers("facet hole");
  for (std::size_t h = 0; h < holes; ++h) {
    in.begin_record();
    numbers.read(in, h);
    for (int k = 0; k < 3; ++k) facets.holes.push_back(in.read_double("facet hole coordinate"));
    in.end_record("the facet hole");
  }
  facets.facet_end.push_back(facets.polygon_end.size());
  facets.hole_end.push_back(facets.holes.size() / 3);
  facets.labels.push_back(marker);
}

// A .smesh facet: one polygon, "k c1 .. ck [marker]".
void read_smesh_facet(TextReader& in, const PointNumbering& points, bool with_marker, FacetList& facets) {
  read_polygon(in, points, facets);
  Label marker = 0;
  if (with_marker && in.record_has_more()) marker = read_marker(in, "facet marker");
  in.end_record("the facet");
  facets.facet_end.push_back(facets.polygon_end.size());
  facets.hole_end.push_back(facets.holes.size() / 3);
  facets.labels.push_back(marker);
}

void read_facets(TextReader& in, const PointNumbering& points, bool smesh, MeshData& mesh) {
  in.begin_record();
  const std::size_t facets = in.read_count("facet count", 2);
  const auto markers = in.read_integer("facet marker count (0 or 1)", 0, 1);
  in.end_record("the facet header");
  for (std::size_t f = 0; f < facets; ++f) {
    if (smesh) {
      read_smesh_facet(in, points, markers == 1, mesh.facets);
    } else {
      read_poly_facet(in, points, markers == 1, mesh.facets);
    }
  }
  detail::drop_all_zero(mesh.facets.labels);
}

// ---------------------------------------------------------------------------------------------
// Files

fs::path companion_path(const fs::path& main, std::string_view extension) {
  fs::path p = main;
  p.replace_extension(extension);
  return p;
}

std::optional<TextReader> open_companion(const fs::path& main, std::string_view extension,
                                         const CompanionFiles& companions, bool required) {
  const fs::path path = companion_path(main, extension);
  std::optional<std::string> contents = companions(path);
  if (!contents) {
    if (required) {
      throw FormatError(main.string(), 0, "the companion file " + path.string() + " does not exist");
    }
    return std::nullopt;
  }
  return TextReader(path.string(), std::move(*contents));
}

void expect_end(TextReader& in) {
  if (!in.at_end()) in.fail("unexpected " + TextReader::quoted(in.next_token()) + " after the last record");
}

// X.poly (2D or 3D) or X.smesh (3D): points (or none, then from X.node), segments or facets,
// holes, and the optional regions.
MeshData parse_poly(TextReader& in, const fs::path& main, const CompanionFiles& companions) {
  const bool smesh = main.extension() == ".smesh";
  MeshData mesh;
  PointNumbering points = read_points(in, mesh);
  if (points.count == 0) {
    std::optional<TextReader> node = open_companion(main, ".node", companions, true);
    const int declared = mesh.dimension;
    points = read_points(*node, mesh);
    expect_end(*node);
    if (mesh.dimension != declared) {
      throw FormatError(main.string(), 1, "the .poly says dimension " + std::to_string(declared) +
                                              " but " + node->name() + " holds " +
                                              std::to_string(mesh.dimension) + "D points");
    }
  }
  if (smesh && mesh.dimension != 3) throw FormatError(main.string(), 1, "a .smesh file holds a 3D domain, but its points are 2D");
  if (mesh.dimension == 2) {
    read_cells(in, {"segment", 2, false}, points, mesh.segments, mesh.segment_labels);
  } else {
    read_facets(in, points, smesh, mesh);
  }
  read_domain_points(in, mesh.dimension, false, mesh.holes, nullptr);
  if (!in.at_end()) read_domain_points(in, mesh.dimension, true, mesh.region_points, &mesh);
  if (!in.at_end()) in.fail("unexpected " + TextReader::quoted(in.next_token()) + " after the region list");
  return mesh;
}

// The mesh X from X.node, X.ele, X.face (3D) and X.edge; `main` is the one that must exist.
MeshData parse_mesh_files(TextReader& main_in, const fs::path& main, const CompanionFiles& companions) {
  const std::string extension = main.extension().string();
  auto file = [&](std::string_view ext, bool required) -> std::optional<TextReader> {
    if (extension == ext) return std::move(main_in);
    return open_companion(main, ext, companions, required);
  };
  MeshData mesh;
  std::optional<TextReader> node = file(".node", true);
  const PointNumbering points = read_points(*node, mesh);
  expect_end(*node);
  const bool three_d = mesh.dimension == 3;
  if (extension == ".face" && !three_d) {
    throw FormatError(main.string(), 0, "a .face file belongs to a 3D mesh, but the points are 2D");
  }
  if (std::optional<TextReader> ele = file(".ele", extension == ".ele")) {
    if (three_d) {
      read_cells(*ele, {"tetrahedron", 4, true}, points, mesh.tetrahedra, mesh.tetrahedron_labels);
    } else {
      read_cells(*ele, {"triangle", 3, true}, points, mesh.triangles, mesh.triangle_labels, &mesh.triangle_attributes);
    }
    expect_end(*ele);
  }
  if (three_d) {
    if (std::optional<TextReader> face = file(".face", extension == ".face")) {
      read_cells(*face, {"face", 3, false}, points, mesh.triangles, mesh.triangle_labels);
      expect_end(*face);
    }
  }
  if (std::optional<TextReader> edge = file(".edge", extension == ".edge")) {
    read_cells(*edge, {"edge", 2, false}, points, mesh.segments, mesh.segment_labels);
    expect_end(*edge);
  }
  return mesh;
}

std::optional<std::string> read_file_if_exists(const fs::path& path) {
  std::error_code ec;
  if (!fs::is_regular_file(path, ec)) return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw FormatError(path.string(), 0, "cannot open the file for reading");
  std::ostringstream buffer;
  buffer << in.rdbuf();
  if (in.bad()) throw FormatError(path.string(), 0, "read error");
  return std::move(buffer).str();
}

// ---------------------------------------------------------------------------------------------
// Writing

void append_label_field(std::string& out, const std::vector<Label>& labels, std::size_t i) {
  if (labels.empty()) return;
  out += ' ';
  detail::append_integer(out, labels[i]);
}

void append_node_points(std::string& out, const MeshData& mesh) {
  const auto dim = static_cast<std::size_t>(mesh.dimension);
  const std::size_t n = mesh.point_count();
  out += std::to_string(n) + " " + std::to_string(dim) + " 0 " + (mesh.point_labels.empty() ? "0\n" : "1\n");
  for (std::size_t p = 0; p < n; ++p) {
    detail::append_integer(out, p + 1);
    for (std::size_t k = 0; k < dim; ++k) {
      out += ' ';
      append_double(out, mesh.coordinates[p * dim + k]);
    }
    append_label_field(out, mesh.point_labels, p);
    out += '\n';
  }
}

// Cell records "id v1..vk [label]", 1-based; the header is the caller's.
void append_cell_records(std::string& out, const std::vector<Index>& cells,
                         const std::vector<Label>& labels, std::size_t corners) {
  const std::size_t count = cells.size() / corners;
  for (std::size_t c = 0; c < count; ++c) {
    detail::append_integer(out, c + 1);
    for (std::size_t k = 0; k < corners; ++k) {
      out += ' ';
      detail::append_integer(out, std::uint64_t{cells[c * corners + k]} + 1);
    }
    append_label_field(out, labels, c);
    out += '\n';
  }
}

std::string marker_header(std::size_t count, const std::vector<Label>& labels) {
  return std::to_string(count) + (labels.empty() ? " 0\n" : " 1\n");
}

void append_domain_points(std::string& out, const std::vector<double>& points, int dimension,
                          const MeshData* regions) {
  const auto dim = static_cast<std::size_t>(dimension);
  const std::size_t count = points.size() / dim;
  out += std::to_string(count) + "\n";
  for (std::size_t h = 0; h < count; ++h) {
    detail::append_integer(out, h + 1);
    for (std::size_t k = 0; k < dim; ++k) {
      out += ' ';
      append_double(out, points[h * dim + k]);
    }
    if (regions != nullptr) {
      out += ' ';
      append_double(out, regions->region_attributes[h]);
      out += ' ';  // the constraint, -1 for none (Triangle and TetGen need the field)
      append_double(out, regions->region_max_measures.empty() ? -1.0 : regions->region_max_measures[h]);
    }
    out += '\n';
  }
}

void append_regions(std::string& out, const MeshData& mesh) {
  append_domain_points(out, mesh.region_points, mesh.dimension, &mesh);
}

void append_polygon(std::string& out, const FacetList& facets, std::size_t p) {
  const std::uint64_t begin = facets.corner_begin(p), end = facets.polygon_end[p];
  detail::append_integer(out, end - begin);
  for (std::uint64_t c = begin; c < end; ++c) {
    out += ' ';
    detail::append_integer(out, std::uint64_t{facets.corners[c]} + 1);
  }
}

// The facet list of a 3D .poly (smesh = false) or .smesh: the mesh's facets, or else its
// triangles as one-triangle facets.
void append_facets(std::string& out, const MeshData& mesh, bool smesh) {
  FacetList from_triangles;
  const FacetList* facets = &mesh.facets;
  if (mesh.facets.empty()) {
    from_triangles.corners = mesh.triangles;
    from_triangles.labels = mesh.triangle_labels;
    for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
      from_triangles.polygon_end.push_back(3 * (t + 1));
      from_triangles.facet_end.push_back(t + 1);
      from_triangles.hole_end.push_back(0);
    }
    facets = &from_triangles;
  }
  out += marker_header(facets->facet_count(), facets->labels);
  for (std::size_t f = 0; f < facets->facet_count(); ++f) {
    const std::uint64_t first = facets->polygon_begin(f), holes = facets->hole_begin(f);
    if (smesh) {
      append_polygon(out, *facets, first);
      append_label_field(out, facets->labels, f);
      out += '\n';
      continue;
    }
    detail::append_integer(out, facets->facet_end[f] - first);
    if (!facets->labels.empty() || facets->hole_end[f] > holes) {
      out += ' ';
      detail::append_integer(out, facets->hole_end[f] - holes);
      append_label_field(out, facets->labels, f);
    }
    out += '\n';
    for (std::uint64_t p = first; p < facets->facet_end[f]; ++p) {
      append_polygon(out, *facets, p);
      out += '\n';
    }
    for (std::uint64_t h = holes; h < facets->hole_end[f]; ++h) {
      detail::append_integer(out, h - holes + 1);
      for (std::size_t k = 0; k < 3; ++k) {
        out += ' ';
        append_double(out, facets->holes[3 * h + k]);
      }
      out += '\n';
    }
  }
}

std::string format_poly(const MeshData& mesh, const std::string& name, bool smesh) {
  if (!mesh.tetrahedra.empty() || (mesh.dimension == 2 && !mesh.triangles.empty())) {
    throw FormatError(name, 0, "a .poly holds a domain, not elements: write the mesh as .node/.ele");
  }
  if (mesh.dimension == 3 && !mesh.segments.empty()) {
    throw FormatError(name, 0, "a 3D .poly cannot hold segments (only facets)");
  }
  if (mesh.dimension == 3 && !mesh.facets.empty() && !mesh.triangles.empty()) {
    throw FormatError(name, 0, "the domain has both facets and triangles: a .poly holds one facet list");
  }
  if (smesh && mesh.dimension != 3) throw FormatError(name, 0, "a .smesh holds a 3D domain");
  for (std::size_t f = 0; smesh && f < mesh.facets.facet_count(); ++f) {
    if (mesh.facets.facet_end[f] - mesh.facets.polygon_begin(f) != 1 || mesh.facets.hole_end[f] != mesh.facets.hole_begin(f)) {
      throw FormatError(name, 0, "facet " + std::to_string(f + 1) + " has several polygons or holes: a .smesh facet is one polygon (write a .poly)");
    }
  }
  std::string out;
  append_node_points(out, mesh);
  if (mesh.dimension == 2) {
    out += marker_header(mesh.segment_count(), mesh.segment_labels);
    append_cell_records(out, mesh.segments, mesh.segment_labels, 2);
  } else {
    append_facets(out, mesh, smesh);
  }
  append_domain_points(out, mesh.holes, mesh.dimension, nullptr);
  if (!mesh.region_points.empty()) append_regions(out, mesh);
  return out;
}

std::string format_ele(const MeshData& mesh) {
  const bool three_d = mesh.dimension == 3;
  const auto& cells = three_d ? mesh.tetrahedra : mesh.triangles;
  const auto& labels = three_d ? mesh.tetrahedron_labels : mesh.triangle_labels;
  const std::size_t corners = three_d ? 4 : 3;
  const bool real = !three_d && !mesh.triangle_attributes.empty();
  std::string out = std::to_string(cells.size() / corners) + " " + std::to_string(corners) +
                    (labels.empty() && !real ? " 0\n" : " 1\n");
  if (!real) {
    append_cell_records(out, cells, labels, corners);
    return out;
  }
  for (std::size_t c = 0; c < cells.size() / corners; ++c) {  // Triangle's real element attribute
    detail::append_integer(out, c + 1);
    for (std::size_t k = 0; k < corners; ++k) {
      out += ' ';
      detail::append_integer(out, std::uint64_t{cells[c * corners + k]} + 1);
    }
    out += ' ';
    append_double(out, mesh.triangle_attributes[c]);
    out += '\n';
  }
  return out;
}

std::string format_marked_cells(const std::vector<Index>& cells, const std::vector<Label>& labels,
                                std::size_t corners) {
  std::string out = marker_header(cells.size() / corners, labels);
  append_cell_records(out, cells, labels, corners);
  return out;
}

void write_mesh_files(const MeshData& mesh, const fs::path& path) {
  if (!mesh.holes.empty() || !mesh.region_points.empty() || !mesh.facets.empty()) {
    throw FormatError(path.string(), 0, "holes, region points and facets go only in a .poly file");
  }
  std::string node;
  append_node_points(node, mesh);
  const std::string ele = format_ele(mesh);
  // A companion that the mesh does not need is still written (empty) when a stale one
  // exists, so that reading X back gives exactly the mesh written.
  const fs::path face_path = companion_path(path, ".face");
  const fs::path edge_path = companion_path(path, ".edge");
  const bool write_face = mesh.dimension == 3 && (!mesh.triangles.empty() || fs::exists(face_path));
  const bool write_edge = !mesh.segments.empty() || fs::exists(edge_path);
  write_file_atomically(companion_path(path, ".node"), node);
  write_file_atomically(companion_path(path, ".ele"), ele);
  if (write_face) write_file_atomically(face_path, format_marked_cells(mesh.triangles, mesh.triangle_labels, 3));
  if (write_edge) write_file_atomically(edge_path, format_marked_cells(mesh.segments, mesh.segment_labels, 2));
}

}  // namespace

MeshData parse_triangle_format(const fs::path& path, std::string contents, const CompanionFiles& companions) {
  const std::string extension = path.extension().string();
  TextReader in(path.string(), std::move(contents));
  if (extension == ".poly" || extension == ".smesh") return parse_poly(in, path, companions);
  if (extension == ".node" || extension == ".ele" || extension == ".face" || extension == ".edge") {
    return parse_mesh_files(in, path, companions);
  }
  throw FormatError(path.string(), 0, "not a Triangle/TetGen file (.node .ele .face .edge .poly .smesh)");
}

MeshData read_triangle_format(const fs::path& path) {
  std::optional<std::string> contents = read_file_if_exists(path);
  if (!contents) throw FormatError(path.string(), 0, "cannot open the file for reading");
  return parse_triangle_format(path, std::move(*contents), read_file_if_exists);
}

void write_triangle_format(const MeshData& mesh, const fs::path& path) {
  detail::check_writable(mesh, path.string());
  const std::string extension = path.extension().string();
  if (extension == ".poly" || extension == ".smesh") {
    write_file_atomically(path, format_poly(mesh, path.string(), extension == ".smesh"));
  } else if (extension == ".node" || extension == ".ele" || extension == ".face" || extension == ".edge") {
    write_mesh_files(mesh, path);
  } else {
    throw FormatError(path.string(), 0, "not a Triangle/TetGen file (.node .ele .face .edge .poly .smesh)");
  }
}

}  // namespace certimesh::io
