// Condition 4, second half: boundary facets meet only in shared vertices and edges. Broad
// phase: the box grid; narrow phase: the exact intersection predicates, which already treat
// shared vertices (same id, same point) as the allowed contact (intersection/mode.h).
#include <algorithm>
#include <array>

#include "certimesh/predicates/intersection/segment_segment_2d.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/intersection/triangle_segment_3d.h"
#include "certimesh/predicates/intersection/triangle_triangle_3d.h"
#include "close_pairs.h"
#include "stages.h"
#include "sweep_2d.h"

namespace certimesh::certificate::detail {

using predicates::IntersectionMode;
using predicates::Overlap;

namespace {

std::array<predicates::Vertex3, 3> triangle(const MeshView& m, Index a, Index b, Index c) {
  return {{{m.p3(a), a}, {m.p3(b), b}, {m.p3(c), c}}};
}

// A fast certificate that triangles f and g meet at most in their shared vertices: in some
// coordinate projection, the line through an edge pq of one triangle has its third vertex
// strictly on one side and every vertex of the other triangle that is not p or q strictly on
// the other (certain filter signs only). The projections then meet only in shared vertices on
// that line, and the first triangle projects injectively (its third vertex is off the line),
// so the triangles meet only in shared vertices. Two convex polygons that touch at most in a
// common vertex or edge are separated by a line through an edge of one of them, so this
// usually succeeds; when it does not, the exact rules below decide.
bool separated_in_projection(const MeshView& m, const Index* f, const Index* g) {
  using predicates::FilteredSign;
  for (int drop = 0; drop < 3; ++drop) {
    const int u = drop == 0 ? 1 : 0, w = drop == 2 ? 1 : 2;
    auto p = [&](Index v) { return predicates::Point2{m.coord(v, u), m.coord(v, w)}; };
    for (int pass = 0; pass < 2; ++pass, std::swap(f, g))
      for (int i = 0; i < 3; ++i) {
        const Index a = f[i], b = f[(i + 1) % 3];
        const FilteredSign inner = predicates::orient2d_filtered(p(a), p(b), p(f[(i + 2) % 3]));
        bool apart = inner != FilteredSign::uncertain;
        for (int j = 0; j < 3 && apart; ++j)
          apart = g[j] == a || g[j] == b || predicates::orient2d_filtered(p(a), p(b), p(g[j])) == -inner;
        if (apart) return true;
      }
  }
  return false;
}

// Exact, after the fast certificate; the predicates treat shared ids as the allowed contact.
bool triangles_meet(const MeshView& m, const Index* f, const Index* g) {
  if (separated_in_projection(m, f, g)) return false;
  return predicates::triangle_triangle_3d(triangle(m, f[0], f[1], f[2]), triangle(m, g[0], g[1], g[2]),
                                          IntersectionMode::exact) == Overlap::intersect;
}

bool facets_meet(const MeshView& m, const Index* f, const Index* g) {
  if (m.dim == 3) return triangles_meet(m, f, g);
  // Two segments from one vertex (same id, so the same point) in directions that are not
  // collinear meet only there: one orient2d instead of the general test (the sweep tests every
  // pair of neighbours, and at a pinch or a fan those share their vertex).
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      if (f[i] == g[j] && f[1 - i] != g[1 - j])
        return predicates::orient2d(m.p2(f[i]), m.p2(f[1 - i]), m.p2(g[1 - j])) == predicates::Sign::zero &&
               predicates::segment_segment_2d(std::array<predicates::Vertex2, 2>{{{m.p2(f[0]), f[0]}, {m.p2(f[1]), f[1]}}},
                                              std::array<predicates::Vertex2, 2>{{{m.p2(g[0]), g[0]}, {m.p2(g[1]), g[1]}}},
                                              IntersectionMode::exact) == Overlap::intersect;
  const std::array<predicates::Vertex2, 2> s{{{m.p2(f[0]), f[0]}, {m.p2(f[1]), f[1]}}};
  const std::array<predicates::Vertex2, 2> t{{{m.p2(g[0]), g[0]}, {m.p2(g[1]), g[1]}}};
  return predicates::segment_segment_2d(s, t, IntersectionMode::exact) == Overlap::intersect;
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

}  // namespace

Finding contact_of(const MeshView& m, const FacetSet& set, std::size_t i, std::size_t j, Defect touching, Defect crossing,
                   const std::string& what) {
  if (!facets_meet(m, set.facet(i), set.facet(j))) return {};
  const std::int64_t v = t_junction_vertex(m, set.facet(i), set.facet(j));
  if (v < 0)
    return finding(crossing, set.owner[i], set.owner[j], -1,
                   what + "s " + std::to_string(i) + " and " + std::to_string(j) + " intersect beyond their shared vertices");
  const std::size_t host = !std::count(set.facet(i), set.facet(i) + m.dim, static_cast<Index>(v)) ? i : j;
  const std::size_t guest = host == i ? j : i;
  return finding(touching, set.owner[host], set.owner[guest], v,
                 "vertex " + std::to_string(v) + " lies on " + what + " " + std::to_string(host) + " without being one of its vertices");
}

// 2D: the plane sweep, O(n log n) in the worst case. 3D: the box grid (its worst case, many
// facets whose boxes overlap, is stated in proofs/mesh_certificate.md section 6); a touching
// pair is reported before a crossing one.
Finding first_contact(const MeshView& m, const FacetSet& set, Defect touching, Defect crossing,
                      const std::string& what) {
  if (m.dim == 2) {
    std::vector<SweepAnswer> none;
    return sweep_2d(m, set, touching, crossing, what, {}, none);
  }
  std::vector<Box> boxes(set.size());
  for (std::size_t f = 0; f < set.size(); ++f) boxes[f] = facet_box(m, set.facet(f), m.dim);
  Finding crossing_found;
  BoxGrid(boxes, m.dim).any_pair([&](std::size_t i, std::size_t j) {
    Finding c = contact_of(m, set, i, j, touching, crossing, what);
    if (c.defect == touching) {
      crossing_found = std::move(c);
      return true;
    }
    if (crossing_found.defect == Defect::none) crossing_found = std::move(c);
    return false;
  });
  return crossing_found;
}

Finding check_boundary_embedding(const MeshView& m, const FacetSet& boundary) {
  // 2D: the single-cover sweep (winding.cpp) is this same sweep with queries added; it reports
  // the first contact, with these defects, before any winding number, so running it here too
  // would sweep the boundary twice.
  if (m.dim == 2) return {};
  return first_contact(m, boundary, Defect::t_junction, Defect::boundary_intersection,
                       m.dim == 2 ? "boundary edge" : "boundary triangle");
}

}  // namespace certimesh::certificate::detail
