#include "certimesh/topology/mesh_data_conversion.h"

#include <span>
#include <string>
#include <vector>

#include "certimesh/topology/mesh_entities.h"
#include "certimesh/topology/topology_error.h"

namespace certimesh::topology {

namespace {

template <class Mesh>
std::span<const io::Index> element_list(const io::MeshData& data) {
  if constexpr (Mesh::simplex_dimension == 3) return data.tetrahedra;
  else return data.triangles;
}
template <class Mesh>
std::span<const io::Label> element_labels(const io::MeshData& data) {
  if constexpr (Mesh::simplex_dimension == 3) return data.tetrahedron_labels;
  else return data.triangle_labels;
}
template <class Mesh>
std::span<const io::Index> facet_list(const io::MeshData& data) {
  if constexpr (Mesh::simplex_dimension == 3) return data.triangles;
  else return data.segments;
}
template <class Mesh>
std::span<const io::Label> facet_labels(const io::MeshData& data) {
  if constexpr (Mesh::simplex_dimension == 3) return data.triangle_labels;
  else return data.segment_labels;
}

constexpr const char* element_word(int simplex_dimension) {
  return simplex_dimension == 3 ? "tetrahedron" : "triangle";
}
constexpr const char* facet_word(int simplex_dimension) {
  return simplex_dimension == 3 ? "boundary triangle" : "segment";
}

ConversionError make_error(ConversionError::Kind kind, std::size_t item, std::string message) {
  return ConversionError{kind, item, std::move(message)};
}

// Reads `count` vertex ids of item `item`, refusing an index past the last point or a repeat.
template <std::size_t N>
std::optional<ConversionError> read_ids(std::span<const io::Index> flat, std::size_t item,
                                        std::size_t point_count, const char* what,
                                        std::array<VertexId, N>& out) {
  for (std::size_t k = 0; k < N; ++k) {
    const io::Index v = flat[item * N + k];
    if (v >= point_count)
      return make_error(ConversionError::Kind::vertex_out_of_range, item,
                        std::string(what) + " " + std::to_string(item) + ": vertex index " +
                            std::to_string(v) + " is out of range (" + std::to_string(point_count) +
                            " points)");
    out[k] = VertexId{v};
    for (std::size_t j = 0; j < k; ++j)
      if (out[j] == out[k])
        return make_error(ConversionError::Kind::repeated_vertex, item,
                          std::string(what) + " " + std::to_string(item) + ": vertex " +
                              std::to_string(v) + " appears twice");
  }
  return std::nullopt;
}

template <class Mesh>
std::optional<ConversionError> add_elements(const io::MeshData& data, Mesh& mesh) {
  constexpr int S = Mesh::simplex_dimension;
  const auto flat = element_list<Mesh>(data);
  const auto labels = element_labels<Mesh>(data);
  const std::size_t count = flat.size() / (S + 1);
  for (std::size_t k = 0; k < count; ++k) {
    typename Mesh::Element element{};
    if (auto error = read_ids(flat, k, data.point_count(), element_word(S), element)) return error;
    try {
      mesh.add_element(element, labels.empty() ? 0 : labels[k]);
    } catch (const TopologyError& e) {
      return make_error(ConversionError::Kind::non_manifold_facet, k,
                        std::string(element_word(S)) + " " + std::to_string(k) + ": " + e.what());
    }
  }
  return std::nullopt;
}

template <class Mesh>
std::optional<ConversionError> add_facet_labels(const io::MeshData& data, Mesh& mesh) {
  constexpr int S = Mesh::simplex_dimension;
  const auto flat = facet_list<Mesh>(data);
  const auto labels = facet_labels<Mesh>(data);
  const std::size_t count = flat.size() / S;
  for (std::size_t k = 0; k < count; ++k) {
    typename Mesh::Facet facet{};
    if (auto error = read_ids(flat, k, data.point_count(), facet_word(S), facet)) return error;
    if (!mesh.find_facet(facet))
      return make_error(ConversionError::Kind::labelled_facet_not_in_mesh, k,
                        std::string(facet_word(S)) + " " + std::to_string(k) +
                            " is not a facet of any " + element_word(S));
    mesh.set_facet_label(facet, labels.empty() ? 0 : labels[k]);
  }
  return std::nullopt;
}

}  // namespace

template <class Mesh>
ConversionResult<Mesh> from_mesh_data(const io::MeshData& data) {
  constexpr int E = Mesh::embedding_dimension;
  ConversionResult<Mesh> result;
  if (data.dimension != E) {
    result.error = make_error(ConversionError::Kind::wrong_dimension, 0,
                              "the file has " + std::to_string(data.dimension) +
                                  "D points, this mesh type needs " + std::to_string(E) + "D");
    return result;
  }
  Mesh mesh;
  const std::size_t points = data.point_count();
  mesh.reserve(points, element_list<Mesh>(data).size() / (Mesh::vertices_per_element));
  for (std::size_t i = 0; i < points; ++i) {
    typename Mesh::Point p{};
    for (std::size_t c = 0; c < E; ++c) p[c] = data.coordinates[i * E + c];
    mesh.add_vertex(p);
  }
  if (auto error = add_elements(data, mesh)) {
    result.error = std::move(error);
    return result;
  }
  if (auto error = add_facet_labels(data, mesh)) {
    result.error = std::move(error);
    return result;
  }
  result.mesh = std::move(mesh);
  return result;
}

template <class Mesh>
io::MeshData to_mesh_data(const Mesh& mesh) {
  constexpr int E = Mesh::embedding_dimension;
  constexpr int S = Mesh::simplex_dimension;
  io::MeshData data;
  data.dimension = E;
  std::vector<io::Index> new_index(mesh.vertex_slot_count(), 0);
  io::Index next = 0;
  for (std::uint32_t v = 0; v < mesh.vertex_slot_count(); ++v) {
    if (!mesh.is_live(VertexId{v})) continue;
    new_index[v] = next++;
    for (const double c : mesh.point(VertexId{v})) data.coordinates.push_back(c);
  }
  std::vector<io::Index>& elements = S == 3 ? data.tetrahedra : data.triangles;
  std::vector<io::Label>& labels = S == 3 ? data.tetrahedron_labels : data.triangle_labels;
  std::vector<io::Index>& facets = S == 3 ? data.triangles : data.segments;
  std::vector<io::Label>& facet_label_list = S == 3 ? data.triangle_labels : data.segment_labels;
  for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e) {
    if (!mesh.is_live(ElementId{e})) continue;
    for (const VertexId v : mesh.vertices(ElementId{e})) elements.push_back(new_index[v.value]);
    labels.push_back(mesh.label(ElementId{e}));
  }
  for (const FacetRecord& record : extract_facets(mesh)) {
    const auto facet = mesh.facet(record.element, record.local);
    const Label label = mesh.facet_label(facet);
    if (!record.boundary() && label == 0) continue;
    for (const VertexId v : facet) facets.push_back(new_index[v.value]);
    facet_label_list.push_back(label);
  }
  return data;
}

template ConversionResult<TriangleMesh2> from_mesh_data(const io::MeshData&);
template ConversionResult<SurfaceMesh3> from_mesh_data(const io::MeshData&);
template ConversionResult<TetrahedralMesh3> from_mesh_data(const io::MeshData&);
template io::MeshData to_mesh_data(const TriangleMesh2&);
template io::MeshData to_mesh_data(const SurfaceMesh3&);
template io::MeshData to_mesh_data(const TetrahedralMesh3&);

}  // namespace certimesh::topology
