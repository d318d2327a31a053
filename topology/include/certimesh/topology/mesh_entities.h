// Edge and facet extraction with interior/boundary classification. A facet is boundary when
// exactly one element holds it (no neighbour across it); an edge is boundary when it lies on a
// boundary facet (for triangles and surfaces the edges are the facets). Results are in a
// deterministic order: edges by (smaller vertex id, larger vertex id), facets by
// (element id, local index).
#pragma once

#include <cstdint>
#include <vector>

#include "certimesh/topology/index.h"
#include "certimesh/topology/vertex_stars.h"

namespace certimesh::topology {

struct EdgeRecord {
  VertexId a;  // a < b
  VertexId b;
  std::uint32_t element_count = 0;  // elements having this edge
  bool boundary = false;
};

struct FacetRecord {
  ElementId element;  // the holder with the smaller id
  int local = 0;      // facet `local` of `element` (opposite local vertex `local`)
  ElementId neighbour = no_element;
  bool boundary() const noexcept { return neighbour == no_element; }
};

template <class Mesh>
std::vector<EdgeRecord> extract_edges(const Mesh& mesh, const VertexStars<Mesh>& stars);

/// Every facet once: boundary facets, and each interior facet from its smaller-id element.
template <class Mesh>
std::vector<FacetRecord> extract_facets(const Mesh& mesh);

}  // namespace certimesh::topology
