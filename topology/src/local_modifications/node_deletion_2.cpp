// Algorithm 34: node deletion (local_modifications_2.h).
//
// Only free interior vertices are deleted: a vertex on the boundary, a cut or a material
// interface is on the trace and stays (with the trace kept, the monograph's material-interface
// rule -- merge only along the interface -- never has a case to decide). The hole is filled by
// the fan from each link vertex in turn; the first fan whose triangles are all strictly
// counterclockwise (exactly), whose new diagonals are not edges already, and whose worst
// quality beats the star's is committed.
#include <algorithm>
#include <limits>

#include "local_geometry_2.h"

namespace certimesh::topology {

namespace {

// The fan from link[apex] over the closed link, or std::nullopt when it is not valid.
std::optional<std::vector<local::VirtualTriangle>> fan_from(const TriangleMesh2& mesh,
                                                             const std::vector<VertexId>& link,
                                                             std::size_t apex, Label label) {
  const std::size_t n = link.size();
  std::vector<local::VirtualTriangle> fan;
  for (std::size_t j = 1; j + 1 < n; ++j) {
    const VertexId b = link[(apex + j) % n], c = link[(apex + j + 1) % n];
    // Diagonals (apex, b) for j >= 2 are new edges; one that exists already would be shared by
    // a third triangle.
    if (j >= 2 && mesh.find_facet({link[apex], b})) return std::nullopt;
    auto t = local::virtual_triangle(mesh, {link[apex], b, c}, label);
    if (!local::is_positive(t)) return std::nullopt;
    fan.push_back(t);
  }
  return fan;
}

}  // namespace

std::optional<LocalChange2> try_node_deletion(TriangleMesh2& mesh, VertexId v,
                                              const LocalModificationOptions2& options) {
  if (is_trace_vertex(mesh, v)) return std::nullopt;
  const auto star = local::ordered_star(mesh, v);
  if (star->link.size() < 3) return std::nullopt;
  double q0 = std::numeric_limits<double>::infinity();
  for (const ElementId e : star->elements) q0 = std::min(q0, local::quality_of(mesh, e, options));
  // No constrained edge through v: the whole star has one label.
  const Label label = mesh.label(star->elements.front());
  for (std::size_t apex = 0; apex < star->link.size(); ++apex) {
    const auto fan = fan_from(mesh, star->link, apex, label);
    if (!fan) continue;
    double q1 = std::numeric_limits<double>::infinity();
    for (const auto& t : *fan) q1 = std::min(q1, local::quality_of(t, options));
    if (!(q1 > q0)) continue;
    auto change = local::replace_elements(mesh, star->elements, *fan);
    mesh.remove_vertex(v);
    return change;
  }
  return std::nullopt;
}

}  // namespace certimesh::topology
