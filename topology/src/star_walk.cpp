#include "certimesh/topology/star_walk.h"

#include <algorithm>

#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::topology {

template <class Mesh>
std::vector<ElementId> walk_star(const Mesh& mesh, VertexId v) {
  std::vector<ElementId> star;
  if (!mesh.is_live(v) || mesh.incident_element(v) == no_element) return star;
  // Breadth-first over the star; the visited list is the star itself (small: a linear
  // search beats a hash set at typical star sizes of 6 to 30 elements).
  star.push_back(mesh.incident_element(v));
  for (std::size_t next = 0; next < star.size(); ++next) {
    const ElementId e = star[next];
    const auto vertices = mesh.vertices(e);
    for (int i = 0; i < Mesh::vertices_per_element; ++i) {
      if (vertices[static_cast<std::size_t>(i)] == v) continue;  // facet i avoids v
      const ElementId n = mesh.neighbour(e, i);
      if (n != no_element && std::find(star.begin(), star.end(), n) == star.end()) star.push_back(n);
    }
  }
  std::sort(star.begin(), star.end());
  return star;
}

template std::vector<ElementId> walk_star(const TriangleMesh2&, VertexId);
template std::vector<ElementId> walk_star(const SurfaceMesh3&, VertexId);
template std::vector<ElementId> walk_star(const TetrahedralMesh3&, VertexId);

}  // namespace certimesh::topology
