// Conversions between the exchange form io::MeshData (what the file readers produce and the
// writers consume) and the mesh model.
//
// from_mesh_data builds the adjacency in O(N) expected time through the mesh's facet table.
// What the model cannot represent is reported as a ConversionError value naming the problem
// and the element: wrong dimension, no elements of the right kind, a vertex index out of range,
// a repeated vertex, a facet of a third element (non-manifold), a boundary segment/triangle
// that is no facet of the mesh. Vertex i of the file is VertexId{i}; element k is ElementId{k}.
// Facet labels come from the file's segments (triangle and surface meshes) or triangles
// (tetrahedral meshes).
//
// to_mesh_data numbers live vertices and elements consecutively in slot order and writes
// every boundary facet (outward oriented, local_facets.h) plus every labelled interior facet,
// each with its label, in (element, local facet) order.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "certimesh/io/mesh_data.h"
#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::topology {

struct ConversionError {
  enum class Kind {
    wrong_dimension,
    vertex_out_of_range,
    repeated_vertex,
    non_manifold_facet,
    labelled_facet_not_in_mesh,
  };
  Kind kind;
  std::size_t item = 0;  // the element, segment or triangle concerned (0-based)
  std::string message;   // one line naming the problem and where
};

template <class Mesh>
struct ConversionResult {
  std::optional<Mesh> mesh;
  std::optional<ConversionError> error;
  bool ok() const noexcept { return mesh.has_value(); }
};

template <class Mesh>
ConversionResult<Mesh> from_mesh_data(const io::MeshData& data);

template <class Mesh>
io::MeshData to_mesh_data(const Mesh& mesh);

}  // namespace certimesh::topology
