// The boundary trace that the local modifications keep (local_modifications_2.h).
#include "local_geometry_2.h"

namespace certimesh::topology {

bool is_constrained_edge(const TriangleMesh2& mesh, ElementId element, int local_edge) {
  const ElementId across = mesh.neighbour(element, local_edge);
  if (across == no_element) return true;
  if (mesh.facet_label(mesh.facet(element, local_edge)) != 0) return true;
  // Different materials on the two sides: an interface even if no facet label says so.
  return mesh.label(across) != mesh.label(element);
}

bool is_trace_vertex(const TriangleMesh2& mesh, VertexId v) {
  const auto star = local::ordered_star(mesh, v);
  if (!star || !star->closed) return true;
  for (const ElementId e : star->elements) {
    const int i = local::local_index(mesh, e, v);
    // The two edges of e through v are the facets opposite its other two vertices.
    if (is_constrained_edge(mesh, e, (i + 1) % 3) || is_constrained_edge(mesh, e, (i + 2) % 3))
      return true;
  }
  return false;
}

}  // namespace certimesh::topology
