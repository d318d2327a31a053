// Algorithm 31: edge flip (local_modifications_2.h).
#include <algorithm>

#include "local_geometry_2.h"

namespace certimesh::topology {

std::optional<LocalChange2> try_flip(TriangleMesh2& mesh, ElementId element, int local_edge,
                                     const LocalModificationOptions2& options) {
  if (is_constrained_edge(mesh, element, local_edge)) return std::nullopt;
  const auto vs = mesh.vertices(element);
  const VertexId c = vs[static_cast<std::size_t>(local_edge)];
  const VertexId a = vs[static_cast<std::size_t>((local_edge + 1) % 3)];
  const VertexId b = vs[static_cast<std::size_t>((local_edge + 2) % 3)];
  const ElementId across = mesh.neighbour(element, local_edge);
  const VertexId d = mesh.vertices(across)[static_cast<std::size_t>(mesh.mirror_facet(element, local_edge))];
  // The quadrilateral (c, a, d, b) is counterclockwise; it is strictly convex exactly when both
  // triangles on the other diagonal are strictly counterclockwise.
  const Label label = mesh.label(element);
  const std::vector<local::VirtualTriangle> added{local::virtual_triangle(mesh, {c, a, d}, label),
                                                  local::virtual_triangle(mesh, {c, d, b}, label)};
  if (!local::is_positive(added[0]) || !local::is_positive(added[1])) return std::nullopt;
  // An edge (c, d) elsewhere would become a third holder's facet: not a manifold any more.
  if (mesh.find_facet({c, d})) return std::nullopt;
  const double q0 = std::min(local::quality_of(mesh, element, options), local::quality_of(mesh, across, options));
  const double q1 = std::min(local::quality_of(added[0], options), local::quality_of(added[1], options));
  if (!(q1 > q0)) return std::nullopt;
  return local::replace_elements(mesh, {element, across}, added);
}

}  // namespace certimesh::topology
