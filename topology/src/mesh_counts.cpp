#include "certimesh/topology/mesh_counts.h"

#include <vector>

#include "certimesh/topology/mesh_entities.h"
#include "certimesh/topology/simplex_mesh.h"
#include "certimesh/topology/vertex_stars.h"
#include "disjoint_sets.h"

namespace certimesh::topology {

namespace {

template <class Mesh>
std::size_t element_components(const Mesh& mesh, const std::vector<FacetRecord>& facets) {
  detail::DisjointSets sets(mesh.element_slot_count());
  for (const FacetRecord& f : facets)
    if (!f.boundary()) sets.unite(f.element.value, f.neighbour.value);
  std::size_t roots = 0;
  for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e)
    if (mesh.is_live(ElementId{e}) && sets.find(e) == e) ++roots;
  return roots;
}

// Boundary vertices and the connected components of the boundary (facets joined at vertices).
template <class Mesh>
void count_boundary(const Mesh& mesh, const std::vector<FacetRecord>& facets, MeshCounts& counts) {
  detail::DisjointSets sets(mesh.vertex_slot_count());
  // vector<bool>: GCC 12 misreports vector<uint8_t>(n, 0) here as -Wfree-nonheap-object.
  std::vector<bool> on_boundary(mesh.vertex_slot_count(), false);
  for (const FacetRecord& f : facets) {
    if (!f.boundary()) continue;
    const auto vs = mesh.facet(f.element, f.local);
    for (const VertexId v : vs) {
      on_boundary[v.value] = true;
      sets.unite(vs[0].value, v.value);
    }
  }
  for (std::uint32_t v = 0; v < on_boundary.size(); ++v) {
    if (!on_boundary[v]) continue;
    ++counts.boundary_vertices;
    if (sets.find(v) == v) ++counts.boundary_components;
  }
}

std::size_t saturating_difference(std::size_t a, std::size_t b) { return a > b ? a - b : 0; }

}  // namespace

template <class Mesh>
MeshCounts count_mesh(const Mesh& mesh) {
  MeshCounts counts;
  for (std::uint32_t v = 0; v < mesh.vertex_slot_count(); ++v) {
    if (!mesh.is_live(VertexId{v})) continue;
    if (mesh.incident_element_count(VertexId{v}) > 0)
      ++counts.vertices;
    else
      ++counts.unused_vertices;
  }
  const VertexStars<Mesh> stars(mesh);
  for (const EdgeRecord& e : extract_edges(mesh, stars)) {
    ++counts.edges;
    ++(e.boundary ? counts.boundary_edges : counts.interior_edges);
  }
  const std::vector<FacetRecord> facets = extract_facets(mesh);
  if constexpr (Mesh::simplex_dimension == 3) {
    counts.tetrahedra = mesh.element_count();
    counts.triangles = facets.size();
    for (const FacetRecord& f : facets) ++(f.boundary() ? counts.boundary_faces : counts.interior_faces);
  } else {
    counts.triangles = mesh.element_count();
  }
  counts.components = element_components(mesh, facets);
  count_boundary(mesh, facets, counts);
  const bool surface = Mesh::embedding_dimension == 3 && Mesh::simplex_dimension == 2;
  counts.holes = surface ? counts.boundary_components
                         : saturating_difference(counts.boundary_components, counts.components);
  return counts;
}

template MeshCounts count_mesh(const TriangleMesh2&);
template MeshCounts count_mesh(const SurfaceMesh3&);
template MeshCounts count_mesh(const TetrahedralMesh3&);

}  // namespace certimesh::topology
