#include "certimesh/topology/mesh_entities.h"

#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::topology {

namespace {

int index_in_element(const auto& element, VertexId v) {
  for (std::size_t i = 0; i < element.size(); ++i)
    if (element[i] == v) return static_cast<int>(i);
  return -1;
}

// Whether edge (a, b) of element e lies on a facet of e that has no neighbour. The facets of
// e through a and b are those opposite its other local vertices.
template <class Mesh>
bool edge_on_open_facet(const Mesh& mesh, ElementId e, int local_a, int local_b) {
  for (int i = 0; i < Mesh::vertices_per_element; ++i)
    if (i != local_a && i != local_b && mesh.neighbour(e, i) == no_element) return true;
  return false;
}

}  // namespace

template <class Mesh>
std::vector<EdgeRecord> extract_edges(const Mesh& mesh, const VertexStars<Mesh>& stars) {
  std::vector<EdgeRecord> edges;
  for (std::uint32_t a = 0; a < mesh.vertex_slot_count(); ++a) {
    const VertexId va{a};
    for (const VertexId vb : stars.vertex_neighbours(va)) {
      if (vb < va) continue;
      EdgeRecord edge{va, vb, 0, false};
      for (const std::uint32_t e : stars.elements_around(va)) {
        const auto element = mesh.vertices(ElementId{e});
        const int lb = index_in_element(element, vb);
        if (lb < 0) continue;
        ++edge.element_count;
        edge.boundary = edge.boundary || edge_on_open_facet(mesh, ElementId{e}, index_in_element(element, va), lb);
      }
      edges.push_back(edge);
    }
  }
  return edges;
}

template <class Mesh>
std::vector<FacetRecord> extract_facets(const Mesh& mesh) {
  std::vector<FacetRecord> facets;
  for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e) {
    const ElementId id{e};
    if (!mesh.is_live(id)) continue;
    for (int i = 0; i < Mesh::vertices_per_element; ++i) {
      const ElementId n = mesh.neighbour(id, i);
      if (n == no_element || id < n) facets.push_back(FacetRecord{id, i, n});
    }
  }
  return facets;
}

#define CERTIMESH_INSTANTIATE_ENTITIES(MESH)                                                   \
  template std::vector<EdgeRecord> extract_edges(const MESH&, const VertexStars<MESH>&); \
  template std::vector<FacetRecord> extract_facets(const MESH&);
CERTIMESH_INSTANTIATE_ENTITIES(TriangleMesh2)
CERTIMESH_INSTANTIATE_ENTITIES(SurfaceMesh3)
CERTIMESH_INSTANTIATE_ENTITIES(TetrahedralMesh3)
#undef CERTIMESH_INSTANTIATE_ENTITIES

}  // namespace certimesh::topology
