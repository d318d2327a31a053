#include "certimesh/topology/vertex_stars.h"

#include <algorithm>

#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::topology {

namespace {

// Element -> vertex ids as one flat array (dead slots keep zeros and are masked out).
template <class Mesh>
std::vector<std::uint32_t> flat_element_vertices(const Mesh& mesh, std::vector<std::uint8_t>& live) {
  constexpr std::size_t k = Mesh::vertices_per_element;
  std::vector<std::uint32_t> flat(mesh.element_slot_count() * k, 0);
  live.assign(mesh.element_slot_count(), 0);
  for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e) {
    if (!mesh.is_live(ElementId{e})) continue;
    live[e] = 1;
    const auto vs = mesh.vertices(ElementId{e});
    for (std::size_t i = 0; i < k; ++i) flat[e * k + i] = vs[i].value;
  }
  return flat;
}

}  // namespace

template <class Mesh>
VertexStars<Mesh>::VertexStars(const Mesh& mesh) : mesh_(&mesh) {
  std::vector<std::uint8_t> live;
  const std::vector<std::uint32_t> flat = flat_element_vertices(mesh, live);
  star_ = invert_incidence(flat, Mesh::vertices_per_element, mesh.vertex_slot_count(), live);
}

template <class Mesh>
std::vector<VertexId> VertexStars<Mesh>::vertex_neighbours(VertexId v) const {
  std::vector<VertexId> out;
  for (const std::uint32_t e : elements_around(v))
    for (const VertexId w : mesh_->vertices(ElementId{e}))
      if (w != v) out.push_back(w);
  std::sort(out.begin(), out.end());
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

template class VertexStars<TriangleMesh2>;
template class VertexStars<SurfaceMesh3>;
template class VertexStars<TetrahedralMesh3>;

}  // namespace certimesh::topology
