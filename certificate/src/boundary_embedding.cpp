// Condition 4, second half: boundary facets meet only in shared vertices and edges. Broad
// phase: the box grid; narrow phase: the exact intersection predicates, which already treat
// shared vertices (same id, same point) as the allowed contact (intersection/mode.h).
#include <algorithm>
#include <array>

#include "certimesh/predicates/intersection/segment_segment_2d.h"
#include "certimesh/predicates/intersection/triangle_segment_3d.h"
#include "certimesh/predicates/intersection/triangle_triangle_3d.h"
#include "close_pairs.h"
#include "stages.h"
#include "facet_contact.h"

namespace certimesh::certificate::detail {

using predicates::IntersectionMode;
using predicates::Overlap;

bool facets_meet(const MeshView& m, const Index* f, const Index* g) {
  if (m.dim == 2) {
    const std::array<predicates::Vertex2, 2> s{{{m.p2(f[0]), f[0]}, {m.p2(f[1]), f[1]}}};
    const std::array<predicates::Vertex2, 2> t{{{m.p2(g[0]), g[0]}, {m.p2(g[1]), g[1]}}};
    return predicates::segment_segment_2d(s, t, IntersectionMode::exact) == Overlap::intersect;
  }
  const std::array<predicates::Vertex3, 3> s{{{m.p3(f[0]), f[0]}, {m.p3(f[1]), f[1]}, {m.p3(f[2]), f[2]}}};
  const std::array<predicates::Vertex3, 3> t{{{m.p3(g[0]), g[0]}, {m.p3(g[1]), g[1]}, {m.p3(g[2]), g[2]}}};
  return predicates::triangle_triangle_3d(s, t, IntersectionMode::exact) == Overlap::intersect;
}

// Whether vertex v (not a vertex of f) lies on the closed facet f: a degenerate segment v-v.
bool vertex_on_facet(const MeshView& m, Index v, const Index* f) {
  if (m.dim == 2) {
    const std::array<predicates::Vertex2, 2> s{{{m.p2(f[0]), f[0]}, {m.p2(f[1]), f[1]}}};
    const std::array<predicates::Vertex2, 2> point{{{m.p2(v), v}, {m.p2(v), v}}};
    return predicates::segment_segment_2d(s, point, IntersectionMode::exact) == Overlap::intersect;
  }
  const std::array<predicates::Vertex3, 3> s{{{m.p3(f[0]), f[0]}, {m.p3(f[1]), f[1]}, {m.p3(f[2]), f[2]}}};
  const std::array<predicates::Vertex3, 2> point{{{m.p3(v), v}, {m.p3(v), v}}};
  return predicates::triangle_segment_3d(s, point, IntersectionMode::exact) == Overlap::intersect;
}

// A vertex of one facet lying on the other, not one of its vertices; -1 if none.
std::int64_t t_junction_vertex(const MeshView& m, const Index* f, const Index* g) {
  auto has = [&](const Index* h, Index v) {
    for (int i = 0; i < m.dim; ++i)
      if (h[i] == v) return true;
    return false;
  };
  for (int pass = 0; pass < 2; ++pass, std::swap(f, g))
    for (int i = 0; i < m.dim; ++i)
      if (!has(g, f[i]) && vertex_on_facet(m, f[i], g)) return f[i];
  return -1;
}

Finding first_contact(const MeshView& m, const FacetSet& set, Defect touching, Defect crossing,
                      const std::string& what) {
  std::vector<Box> boxes(set.size());
  for (std::size_t f = 0; f < set.size(); ++f) boxes[f] = facet_box(m, set.facet(f), m.dim);
  Finding crossing_found;
  BoxGrid(boxes, m.dim).any_pair([&](std::size_t i, std::size_t j) {
    if (!facets_meet(m, set.facet(i), set.facet(j))) return false;
    const std::int64_t v = t_junction_vertex(m, set.facet(i), set.facet(j));
    const std::size_t host = v >= 0 && !std::count(set.facet(i), set.facet(i) + m.dim, static_cast<Index>(v)) ? i : j;
    const std::size_t guest = host == i ? j : i;
    if (v >= 0) {
      crossing_found = finding(touching, set.owner[host], set.owner[guest], v,
                               "vertex " + std::to_string(v) + " lies on " + what + " " + std::to_string(host) +
                                   " without being one of its vertices");
      return true;
    }
    if (crossing_found.defect == Defect::none)
      crossing_found = finding(crossing, set.owner[i], set.owner[j], -1,
                               what + "s " + std::to_string(i) + " and " + std::to_string(j) +
                                   " intersect beyond their shared vertices");
    return false;
  });
  return crossing_found;
}

Finding check_boundary_embedding(const MeshView& m, const FacetSet& boundary) {
  return first_contact(m, boundary, Defect::t_junction, Defect::boundary_intersection,
                       m.dim == 2 ? "boundary edge" : "boundary triangle");
}

}  // namespace certimesh::certificate::detail
