#include "certimesh/io/gmsh_format.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <string_view>
#include <utility>
#include <vector>

#include "certimesh/io/format_error.h"
#include "certimesh/io/mesh_file.h"
#include "text_reader.h"
#include "text_writer.h"

namespace certimesh::io {

namespace {

constexpr std::int64_t kMaxTag = std::numeric_limits<std::int64_t>::max();
constexpr std::int64_t kMinLabel = std::numeric_limits<Label>::min();
constexpr std::int64_t kMaxLabel = std::numeric_limits<Label>::max();

// The three cell kinds of MeshData and their Gmsh element types.
struct CellKind {
  int dimension;
  int gmsh_type;
  std::size_t arity;
};
constexpr std::array<CellKind, 3> kKinds{{{1, 1, 2}, {2, 2, 3}, {3, 4, 4}}};

const std::vector<Index>& cells_of_gmsh_kind(const MeshData& mesh, std::size_t kind) {
  return kind == 0 ? mesh.segments : kind == 1 ? mesh.triangles : mesh.tetrahedra;
}
const std::vector<Label>& labels_of_gmsh_kind(const MeshData& mesh, std::size_t kind) {
  return kind == 0 ? mesh.segment_labels : kind == 1 ? mesh.triangle_labels : mesh.tetrahedron_labels;
}
std::vector<Index>& cells_of_gmsh_kind(MeshData& mesh, std::size_t kind) {
  return kind == 0 ? mesh.segments : kind == 1 ? mesh.triangles : mesh.tetrahedra;
}
std::vector<Label>& labels_of_gmsh_kind(MeshData& mesh, std::size_t kind) {
  return kind == 0 ? mesh.segment_labels : kind == 1 ? mesh.triangle_labels : mesh.tetrahedron_labels;
}

// ---------------------------------------------------------------------------------------------
// Writing

double coordinate(const MeshData& mesh, std::size_t point, std::size_t axis) {
  const auto d = static_cast<std::size_t>(mesh.dimension);
  return axis < d ? mesh.coordinates[point * d + axis] : 0.0;
}

// One Gmsh entity: the cells of one kind that share one label.
struct Entity {
  std::size_t kind;
  int tag;
  Label label;
  std::vector<std::size_t> cells;  // indices into the kind's cells, ascending
};

std::vector<Entity> group_into_entities(const MeshData& mesh) {
  std::vector<Entity> entities;
  for (std::size_t kind = 0; kind < kKinds.size(); ++kind) {
    const auto& labels = labels_of_gmsh_kind(mesh, kind);
    const std::size_t count = cells_of_gmsh_kind(mesh, kind).size() / kKinds[kind].arity;
    std::map<Label, std::vector<std::size_t>> by_label;  // ordered: deterministic entity tags
    for (std::size_t c = 0; c < count; ++c) by_label[labels.empty() ? 0 : labels[c]].push_back(c);
    int tag = 1;
    for (auto& [label, cells] : by_label) entities.push_back({kind, tag++, label, std::move(cells)});
  }
  return entities;
}

void append_bounding_box(std::string& out, const MeshData& mesh, const std::vector<Index>& points) {
  std::array<double, 3> lo{0, 0, 0};
  std::array<double, 3> hi{0, 0, 0};
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t axis = 0; axis < 3; ++axis) {
      const double c = coordinate(mesh, points[i], axis);
      lo[axis] = i == 0 ? c : std::min(lo[axis], c);
      hi[axis] = i == 0 ? c : std::max(hi[axis], c);
    }
  }
  for (double c : lo) { append_double(out, c); out += ' '; }
  for (double c : hi) { append_double(out, c); out += ' '; }
}

std::vector<Index> points_of_entity(const MeshData& mesh, const Entity& entity) {
  const auto& cells = cells_of_gmsh_kind(mesh, entity.kind);
  const std::size_t arity = kKinds[entity.kind].arity;
  std::vector<Index> points;
  for (std::size_t c : entity.cells) {
    points.insert(points.end(), cells.begin() + static_cast<std::ptrdiff_t>(c * arity),
                  cells.begin() + static_cast<std::ptrdiff_t>((c + 1) * arity));
  }
  return points;
}

std::vector<Index> all_points(const MeshData& mesh) {
  std::vector<Index> points(mesh.point_count());
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = static_cast<Index>(i);
  return points;
}

// The entity that carries the node block: the first of the highest dimension; a mesh without
// cells gets an empty surface entity (tag 1) for its nodes.
std::pair<int, int> node_entity(const std::vector<Entity>& entities) {
  if (entities.empty()) return {2, 1};
  return {kKinds[entities.back().kind].dimension, 1};
}

void append_entities(std::string& out, const MeshData& mesh, const std::vector<Entity>& entities) {
  std::array<std::size_t, 3> per_dimension{0, 0, 0};
  for (const Entity& e : entities) ++per_dimension[e.kind];
  const bool synthetic_surface = entities.empty();
  if (synthetic_surface) per_dimension[1] = 1;
  out += "$Entities\n0 ";
  out += std::to_string(per_dimension[0]) + ' ' + std::to_string(per_dimension[1]) + ' ' +
         std::to_string(per_dimension[2]) + '\n';
  if (synthetic_surface) {
    out += "1 ";
    append_bounding_box(out, mesh, all_points(mesh));
    out += "0 0\n";
  }
  for (const Entity& e : entities) {
    out += std::to_string(e.tag) + ' ';
    append_bounding_box(out, mesh, points_of_entity(mesh, e));
    out += "1 " + std::to_string(e.label) + ' ';  // label 0 too: see gmsh_format.h
    out += "0\n";
  }
  out += "$EndEntities\n";
}

void append_nodes(std::string& out, const MeshData& mesh, std::pair<int, int> entity) {
  const std::size_t n = mesh.point_count();
  out += "$Nodes\n";
  out += n == 0 ? std::string("0 0 0 0\n") : "1 " + std::to_string(n) + " 1 " + std::to_string(n) + '\n';
  if (n == 0) {
    out += "$EndNodes\n";
    return;
  }
  out += std::to_string(entity.first) + ' ' + std::to_string(entity.second) + " 0 " + std::to_string(n) + '\n';
  for (std::size_t i = 0; i < n; ++i) {
    detail::append_integer(out, i + 1);
    out += '\n';
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t axis = 0; axis < 3; ++axis) {
      append_double(out, coordinate(mesh, i, axis));
      out += axis == 2 ? '\n' : ' ';
    }
  }
  out += "$EndNodes\n";
}

void append_elements(std::string& out, const MeshData& mesh, const std::vector<Entity>& entities) {
  std::array<std::size_t, 3> first_tag{};  // element tag of the first cell of each kind, minus 1
  std::size_t total = 0;
  for (std::size_t kind = 0; kind < kKinds.size(); ++kind) {
    first_tag[kind] = total;
    total += cells_of_gmsh_kind(mesh, kind).size() / kKinds[kind].arity;
  }
  out += "$Elements\n" + std::to_string(entities.size()) + ' ' + std::to_string(total) + ' ' +
         (total == 0 ? std::string("0 0") : "1 " + std::to_string(total)) + '\n';
  for (const Entity& e : entities) {
    const CellKind& kind = kKinds[e.kind];
    const auto& cells = cells_of_gmsh_kind(mesh, e.kind);
    out += std::to_string(kind.dimension) + ' ' + std::to_string(e.tag) + ' ' + std::to_string(kind.gmsh_type) +
           ' ' + std::to_string(e.cells.size()) + '\n';
    for (std::size_t c : e.cells) {
      detail::append_integer(out, first_tag[e.kind] + c + 1);
      for (std::size_t k = 0; k < kind.arity; ++k) {
        out += ' ';
        detail::append_integer(out, std::size_t{cells[c * kind.arity + k]} + 1);
      }
      out += '\n';
    }
  }
  out += "$EndElements\n";
}

void append_point_labels(std::string& out, const MeshData& mesh) {
  if (mesh.point_labels.empty()) return;
  out += "$NodeData\n1\n\"label\"\n1\n0\n3\n0\n1\n" + std::to_string(mesh.point_count()) + '\n';
  for (std::size_t i = 0; i < mesh.point_labels.size(); ++i) {
    detail::append_integer(out, i + 1);
    out += ' ';
    detail::append_integer(out, mesh.point_labels[i]);
    out += '\n';
  }
  out += "$EndNodeData\n";
}

// ---------------------------------------------------------------------------------------------
// Reading

struct NodeRecord {
  std::int64_t tag;
  std::size_t line;
  std::array<double, 3> xyz;
};

struct CellRecord {
  std::int64_t tag;
  std::size_t line;
  Label label;
  std::array<Index, 4> nodes;
};

struct PointLabelRecord {
  std::int64_t tag;
  std::size_t line;
  Label label;
};

class GmshReader {
 public:
  explicit GmshReader(detail::TextReader& in) : in_(in) { in_.set_comment_chars(""); }

  MeshData read() {
    if (in_.next_token() != "$MeshFormat") in_.fail("expected $MeshFormat at the start of a Gmsh file");
    read_mesh_format();
    for (std::string_view section = in_.next_token(); !section.empty(); section = in_.next_token()) {
      dispatch(section);
    }
    if (!has_nodes_) in_.fail("no $Nodes section");
    return assemble();
  }

 private:
  void dispatch(std::string_view section) {
    if (section == "$Entities") {
      read_entities();
    } else if (section == "$Nodes") {
      read_nodes();
    } else if (section == "$Elements") {
      read_elements();
    } else if (section == "$NodeData") {
      read_node_data();
    } else if (section.size() > 1 && section.front() == '$' && !section.starts_with("$End")) {
      skip_section(section);
    } else {
      in_.fail("expected a section such as $Nodes, got '" + std::string(section) + "'");
    }
  }

  void expect(std::string_view keyword) {
    const std::string_view token = in_.next_token();
    if (token != keyword) {
      in_.fail(token.empty() ? "unexpected end of file, expected " + std::string(keyword)
                             : "expected " + std::string(keyword) + ", got '" + std::string(token) + "'");
    }
  }

  void read_mesh_format() {
    const std::string_view version = in_.expect_token("the format version");
    if (version != "4.1") {
      in_.fail("Gmsh format version " + std::string(version) +
               " is not supported (certimesh reads 4.1 ASCII; re-save with gmsh -format msh41)");
    }
    if (in_.read_integer("file-type", 0, 1) == 1) {
      in_.fail("binary .msh (file-type 1) is not supported; save as ASCII (Mesh.Binary = 0)");
    }
    in_.read_integer("data-size", 1, 16);
    expect("$EndMeshFormat");
  }

  void skip_section(std::string_view section) {
    const std::string end = "$End" + std::string(section.substr(1));
    const std::size_t start = in_.line();
    for (std::string_view token = in_.next_token(); token != end; token = in_.next_token()) {
      if (token.empty()) {
        in_.fail("unexpected end of file in the " + std::string(section) + " section of line " +
                 std::to_string(start) + " (no " + end + ")");
      }
    }
  }

  std::vector<Label> read_physical_tags() {
    const std::size_t count = in_.read_count("number of physical tags", 2);
    std::vector<Label> tags;
    for (std::size_t i = 0; i < count; ++i) {
      tags.push_back(static_cast<Label>(in_.read_integer("physical tag", kMinLabel, kMaxLabel)));
    }
    return tags;
  }

  void read_entity(int dimension) {
    const std::int64_t tag = in_.read_integer("entity tag", std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
    const int coordinates = dimension == 0 ? 3 : 6;
    for (int i = 0; i < coordinates; ++i) in_.read_double("entity bounding box coordinate");
    const std::vector<Label> physical = read_physical_tags();
    if (dimension > 0) {
      const std::size_t bounding = in_.read_count("number of bounding entities", 2);
      for (std::size_t i = 0; i < bounding; ++i) in_.read_integer("bounding entity tag", -kMaxTag, kMaxTag);
    }
    entity_label_[{dimension, tag}] = physical.empty() ? 0 : physical.front();
  }

  void read_entities() {
    std::array<std::size_t, 4> counts{};
    for (auto& count : counts) count = in_.read_count("number of entities", 10);
    for (int dimension = 0; dimension < 4; ++dimension) {
      for (std::size_t i = 0; i < counts[static_cast<std::size_t>(dimension)]; ++i) read_entity(dimension);
    }
    expect("$EndEntities");
  }

  void read_node_block() {
    const auto dimension = in_.read_integer("entity dimension", 0, 3);
    in_.read_integer("entity tag", std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
    const bool parametric = in_.read_integer("parametric flag", 0, 1) == 1;
    const std::size_t extra = parametric ? static_cast<std::size_t>(dimension) : 0;
    const std::size_t count = in_.read_count("number of nodes in the block", 8 + 2 * extra);
    const std::size_t first = nodes_.size();
    for (std::size_t i = 0; i < count; ++i) {
      const std::int64_t tag = in_.read_integer("node tag", 1, kMaxTag);
      nodes_.push_back({tag, in_.line(), {}});
    }
    for (std::size_t i = 0; i < count; ++i) {
      for (double& c : nodes_[first + i].xyz) c = in_.read_double("node coordinate");
      for (std::size_t k = 0; k < extra; ++k) in_.read_double("parametric coordinate");
    }
  }

  void read_nodes() {
    if (has_nodes_) in_.fail("a second $Nodes section");
    has_nodes_ = true;
    const std::size_t blocks = in_.read_count("number of node blocks", 8);
    const std::size_t header_line = in_.line();
    const std::size_t declared = in_.read_count("number of nodes", 8);
    in_.read_integer("minimum node tag", 0, kMaxTag);
    in_.read_integer("maximum node tag", 0, kMaxTag);
    if (declared > std::numeric_limits<Index>::max()) in_.fail("more than 2^32 - 1 nodes");
    for (std::size_t b = 0; b < blocks; ++b) read_node_block();
    // Gmsh 4.8 counts, in the header, the nodes of entities it then does not save (Mesh.SaveAll
    // = 0), so only blocks holding more nodes than declared are refused.
    if (nodes_.size() > declared) {
      throw FormatError(in_.name(), header_line, "the $Nodes header declares " + std::to_string(declared) + " nodes, its blocks hold " +
               std::to_string(nodes_.size()));
    }
    expect("$EndNodes");
    index_nodes();
  }

  // Point i is the node of the i-th smallest tag, whatever the block order.
  void index_nodes() {
    std::stable_sort(nodes_.begin(), nodes_.end(),
                     [](const NodeRecord& a, const NodeRecord& b) { return a.tag < b.tag; });
    for (std::size_t i = 1; i < nodes_.size(); ++i) {
      if (nodes_[i].tag == nodes_[i - 1].tag) {
        throw FormatError(in_.name(), std::max(nodes_[i].line, nodes_[i - 1].line),
                          "node tag " + std::to_string(nodes_[i].tag) + " appears twice");
      }
    }
  }

  Index node_index(std::int64_t tag, const char* what) {
    const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), tag,
                                     [](const NodeRecord& n, std::int64_t t) { return n.tag < t; });
    if (it == nodes_.end() || it->tag != tag) {
      in_.fail(std::string(what) + " names node tag " + std::to_string(tag) + ", which no $Nodes block defines");
    }
    return static_cast<Index>(it - nodes_.begin());
  }

  // Index into kKinds of a Gmsh element type, kKinds.size() for points (skipped); refuses others.
  std::size_t kind_of_type(std::int64_t type) {
    for (std::size_t k = 0; k < kKinds.size(); ++k) {
      if (kKinds[k].gmsh_type == type) return k;
    }
    if (type == 15) return kKinds.size();
    in_.fail("element type " + std::to_string(type) +
             " is not supported (certimesh reads 1 line, 2 triangle, 4 tetrahedron and skips 15 point)");
  }

  std::size_t read_element_block() {
    const auto dimension = static_cast<int>(in_.read_integer("entity dimension", 0, 3));
    const std::int64_t entity = in_.read_integer("entity tag", std::numeric_limits<int>::min(), std::numeric_limits<int>::max());
    const std::size_t kind = kind_of_type(in_.read_integer("element type", std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
    const std::size_t arity = kind < kKinds.size() ? kKinds[kind].arity : 1;
    const std::size_t count = in_.read_count("number of elements in the block", 2 * (arity + 1));
    const auto found = entity_label_.find({dimension, entity});
    const Label label = found == entity_label_.end() ? 0 : found->second;
    for (std::size_t i = 0; i < count; ++i) {
      CellRecord cell{in_.read_integer("element tag", 1, kMaxTag), in_.line(), label, {}};
      for (std::size_t k = 0; k < arity; ++k) {
        cell.nodes[k] = node_index(in_.read_integer("node tag", 1, kMaxTag), "an element");
      }
      if (kind < kKinds.size()) cells_[kind].push_back(cell);
    }
    return count;
  }

  void read_elements() {
    if (!has_nodes_) in_.fail("$Elements before $Nodes");
    if (has_elements_) in_.fail("a second $Elements section");
    has_elements_ = true;
    const std::size_t blocks = in_.read_count("number of element blocks", 8);
    const std::size_t header_line = in_.line();
    const std::size_t declared = in_.read_count("number of elements", 4);
    in_.read_integer("minimum element tag", 0, kMaxTag);
    in_.read_integer("maximum element tag", 0, kMaxTag);
    std::size_t read = 0;
    for (std::size_t b = 0; b < blocks; ++b) read += read_element_block();
    if (read != declared) {
      throw FormatError(in_.name(), header_line, "the $Elements header declares " + std::to_string(declared) + " elements, its blocks hold " +
               std::to_string(read));
    }
    expect("$EndElements");
  }

  // A quoted string tag, possibly spread over several tokens ("my view").
  std::string read_string_tag() {
    std::string text(in_.expect_token("a string tag"));
    while (text.front() == '"' && (text.size() == 1 || text.back() != '"')) {
      text += ' ';
      text += in_.expect_token("the end of a quoted string tag");
    }
    if (text.size() >= 2 && text.front() == '"' && text.back() == '"') text = text.substr(1, text.size() - 2);
    return text;
  }

  void read_node_data() {
    const std::size_t strings = in_.read_count("number of string tags", 2);
    std::string name;
    for (std::size_t i = 0; i < strings; ++i) {
      std::string tag = read_string_tag();
      if (i == 0) name = std::move(tag);
    }
    const std::size_t reals = in_.read_count("number of real tags", 2);
    for (std::size_t i = 0; i < reals; ++i) in_.read_double("real tag");
    const std::size_t integers = in_.read_count("number of integer tags", 2);
    std::vector<std::int64_t> integer_tags;
    for (std::size_t i = 0; i < integers; ++i) integer_tags.push_back(in_.read_integer("integer tag", -kMaxTag, kMaxTag));
    const bool is_point_labels = name == "label" && integer_tags.size() >= 3 && integer_tags[1] == 1 &&
                                 point_labels_.empty() && !has_point_labels_;
    if (!is_point_labels) {
      skip_section("$NodeData");
      return;
    }
    has_point_labels_ = true;
    if (integer_tags[2] < 0 || static_cast<std::size_t>(integer_tags[2]) > in_.remaining_bytes() / 4) {
      in_.fail("the \"label\" view declares " + std::to_string(integer_tags[2]) +
               " values, more than the rest of the file can hold");
    }
    for (std::int64_t i = 0; i < integer_tags[2]; ++i) read_point_label();
    expect("$EndNodeData");
  }

  void read_point_label() {
    const std::int64_t tag = in_.read_integer("node tag", 1, kMaxTag);
    const double value = in_.read_double("point label");
    if (value != std::floor(value) || value < static_cast<double>(kMinLabel) || value > static_cast<double>(kMaxLabel)) {
      in_.fail("point label is not a 32-bit integer");
    }
    point_labels_.push_back({tag, in_.line(), static_cast<Label>(value)});
  }

  MeshData assemble() {
    MeshData mesh;
    const bool has_z = std::any_of(nodes_.begin(), nodes_.end(), [](const NodeRecord& n) { return n.xyz[2] != 0.0; });
    mesh.dimension = !cells_[2].empty() || has_z ? 3 : 2;
    for (const NodeRecord& n : nodes_) {
      mesh.coordinates.insert(mesh.coordinates.end(), n.xyz.begin(), n.xyz.begin() + mesh.dimension);
    }
    for (std::size_t kind = 0; kind < kKinds.size(); ++kind) assemble_cells(mesh, kind);
    if (has_point_labels_) {
      mesh.point_labels.assign(nodes_.size(), 0);
      for (const PointLabelRecord& p : point_labels_) {
        const auto it = std::lower_bound(nodes_.begin(), nodes_.end(), p.tag,
                                         [](const NodeRecord& n, std::int64_t t) { return n.tag < t; });
        if (it == nodes_.end() || it->tag != p.tag) {
          throw FormatError(in_.name(), p.line, "the \"label\" view names node tag " + std::to_string(p.tag) +
                                                    ", which no $Nodes block defines");
        }
        mesh.point_labels[static_cast<std::size_t>(it - nodes_.begin())] = p.label;
      }
    }
    return mesh;
  }

  // Cells of one kind in element-tag order, so that a written mesh reads back in its order.
  void assemble_cells(MeshData& mesh, std::size_t kind) {
    auto& records = cells_[kind];
    std::stable_sort(records.begin(), records.end(), [](const CellRecord& a, const CellRecord& b) { return a.tag < b.tag; });
    for (std::size_t i = 1; i < records.size(); ++i) {
      if (records[i].tag == records[i - 1].tag) {
        throw FormatError(in_.name(), std::max(records[i].line, records[i - 1].line),
                          "element tag " + std::to_string(records[i].tag) + " appears twice");
      }
    }
    const bool any_label = std::any_of(records.begin(), records.end(), [](const CellRecord& c) { return c.label != 0; });
    for (const CellRecord& c : records) {
      cells_of_gmsh_kind(mesh, kind).insert(cells_of_gmsh_kind(mesh, kind).end(), c.nodes.begin(),
                                  c.nodes.begin() + static_cast<std::ptrdiff_t>(kKinds[kind].arity));
      if (any_label) labels_of_gmsh_kind(mesh, kind).push_back(c.label);
    }
  }

  detail::TextReader& in_;
  std::map<std::pair<int, std::int64_t>, Label> entity_label_;
  std::vector<NodeRecord> nodes_;
  std::array<std::vector<CellRecord>, 3> cells_;
  std::vector<PointLabelRecord> point_labels_;
  bool has_nodes_ = false;
  bool has_elements_ = false;
  bool has_point_labels_ = false;
};

}  // namespace

MeshData read_gmsh_format(const std::filesystem::path& path) {
  detail::TextReader in(path);
  return GmshReader(in).read();
}

MeshData parse_gmsh_format(std::string name, std::string contents) {
  detail::TextReader in(std::move(name), std::move(contents));
  return GmshReader(in).read();
}

namespace {

std::string format_gmsh_named(const MeshData& mesh, const std::string& name) {
  detail::check_writable(mesh, name);
  const std::vector<Entity> entities = group_into_entities(mesh);
  std::string out = "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  append_entities(out, mesh, entities);
  append_nodes(out, mesh, node_entity(entities));
  append_elements(out, mesh, entities);
  append_point_labels(out, mesh);
  return out;
}

}  // namespace

std::string format_gmsh(const MeshData& mesh) { return format_gmsh_named(mesh, "(.msh output)"); }

void write_gmsh_format(const MeshData& mesh, const std::filesystem::path& path) {
  write_file_atomically(path, format_gmsh_named(mesh, path.string()));
}

}  // namespace certimesh::io
