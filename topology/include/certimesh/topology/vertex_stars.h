// Vertex stars Ω(v): for every vertex slot, the live elements that use it (the monograph's
// inverse list VT, §2.3), as CSR built in linear time by the counting sort of Algorithm 3.
// A snapshot: it does not follow later changes of the mesh; rebuild it after modifications
// (or walk from SimplexMesh::incident_element for a single vertex).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "certimesh/topology/csr.h"
#include "certimesh/topology/index.h"

namespace certimesh::topology {

template <class Mesh>
class VertexStars {
 public:
  explicit VertexStars(const Mesh& mesh);

  /// The live elements using v, in increasing id order. Empty for a dead or unused vertex.
  std::span<const std::uint32_t> elements_around(VertexId v) const noexcept { return star_.row(v.value); }
  /// The vertices joined to v by an edge of some element, in increasing id order.
  std::vector<VertexId> vertex_neighbours(VertexId v) const;
  const Csr& csr() const noexcept { return star_; }

 private:
  const Mesh* mesh_;
  Csr star_;
};

}  // namespace certimesh::topology
