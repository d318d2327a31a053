// Algorithm 33: edge collapse (local_modifications_2.h).
//
// The endpoints a, b of an unconstrained edge merge: at the midpoint when both are free, at
// the trace endpoint (which stays put) when one is on the trace, never when both are -- an
// interior edge between two trace vertices would pinch the domain. The two triangles on the
// edge vanish; every other triangle of the two stars must stay strictly counterclockwise
// with the merged vertex, decided exactly. The link condition (the common neighbours of a and
// b are exactly the two apexes of the edge) refuses duplicate edges and non-manifold stars.
// A boundary vertex may also merge into a boundary neighbour along their boundary edge, where
// the options allow the boundary to lose it (may_leave_boundary below).
#include <algorithm>
#include <limits>

#include "certimesh/predicates/orient2d.h"
#include "input_segment_run_2.h"
#include "local_geometry_2.h"

namespace certimesh::topology {

namespace {

std::vector<VertexId> sorted_link(const local::OrderedStar2& star) {
  std::vector<VertexId> link = star.link;
  std::sort(link.begin(), link.end());
  return link;
}

bool link_condition_holds(const local::OrderedStar2& star_a, const local::OrderedStar2& star_b,
                          VertexId c, VertexId d) {
  const auto link_a = sorted_link(star_a), link_b = sorted_link(star_b);
  std::vector<VertexId> common;
  std::set_intersection(link_a.begin(), link_a.end(), link_b.begin(), link_b.end(), std::back_inserter(common));
  std::vector<VertexId> apexes{std::min(c, d), std::max(c, d)};
  if (c == d) apexes.pop_back();  // a boundary edge has one apex
  return common == apexes;
}

// Whether the boundary vertex gone, between its boundary neighbours kept and other, may go
// without the boundary leaving the input: either it lies exactly on the straight line through
// its neighbours (coarsen_straight_boundary: the boundary polygon keeps its point set), or it
// is a Steiner vertex inside an input segment that holds both neighbours (input_segments: the
// new boundary edge (kept, other) joins two points of that segment, as the certificate reads
// them, so the boundary still lies on the input).
bool may_leave_boundary(const TriangleMesh2& mesh, VertexId kept, VertexId gone, VertexId other,
                        const LocalModificationOptions2& options) {
  const auto p = [&](VertexId v) {
    const auto q = mesh.point(v);
    return predicates::Point2{q[0], q[1]};
  };
  if (options.coarsen_straight_boundary && predicates::orient2d(p(kept), p(gone), p(other)) == predicates::Sign::zero)
    return true;
  return options.input_segments && local::segment_run(mesh, gone, options.input_segments).has_value();
}

// Merges `gone` into `kept` along their open boundary edge, apex c, when gone is a boundary
// vertex that may leave (may_leave_boundary): its only constrained edges are its two boundary
// edges and they carry the same label. In a valid mesh the two boundary edges cannot overlap,
// so gone is between kept and its other boundary neighbour.
std::optional<LocalChange2> collapse_boundary_vertex(TriangleMesh2& mesh, ElementId element, VertexId kept,
                                                     VertexId gone, VertexId c,
                                                     const LocalModificationOptions2& options) {
  const auto star_gone = local::ordered_star(mesh, gone);
  const auto star_kept = local::ordered_star(mesh, kept);
  if (!star_gone || !star_kept || star_gone->closed) return std::nullopt;
  const VertexId first = star_gone->link.front(), last = star_gone->link.back();
  if (first != kept && last != kept) return std::nullopt;
  const VertexId other = first == kept ? last : first;
  for (const ElementId e : star_gone->elements) {
    const int i = local::local_index(mesh, e, gone);
    for (const int facet : {(i + 1) % 3, (i + 2) % 3})
      if (mesh.neighbour(e, facet) != no_element && is_constrained_edge(mesh, e, facet)) return std::nullopt;
  }
  const Label boundary_label = mesh.facet_label({gone, kept});
  if (mesh.facet_label({gone, other}) != boundary_label) return std::nullopt;
  if (!may_leave_boundary(mesh, kept, gone, other, options)) return std::nullopt;
  if (!link_condition_holds(*star_kept, *star_gone, c, c) || mesh.find_facet({kept, other})) return std::nullopt;

  std::vector<ElementId> removed{element};
  std::vector<local::VirtualTriangle> added;
  double q0 = options.collapse_reference == CollapseReference::survivors_and_removed
                  ? local::quality_of(mesh, element, options)
                  : std::numeric_limits<double>::infinity();
  double q1 = std::numeric_limits<double>::infinity();
  for (const ElementId e : star_gone->elements) {
    if (e == element) continue;
    removed.push_back(e);
    q0 = std::min(q0, local::quality_of(mesh, e, options));
    auto t = local::virtual_triangle(mesh, mesh.vertices(e), mesh.label(e));
    for (std::size_t i = 0; i < 3; ++i)
      if (t.vertices[i] == gone) t.vertices[i] = kept, t.points[i] = mesh.point(kept);
    if (!local::is_positive(t)) return std::nullopt;
    q1 = std::min(q1, local::quality_of(t, options));
    added.push_back(t);
  }
  if (!(q1 > q0)) return std::nullopt;
  mesh.set_facet_label({gone, kept}, 0);
  mesh.set_facet_label({gone, other}, 0);
  auto change = local::replace_elements(mesh, removed, added);
  mesh.remove_vertex(gone);
  mesh.set_facet_label({kept, other}, boundary_label);
  return change;
}

}  // namespace

std::optional<LocalChange2> try_edge_collapse(TriangleMesh2& mesh, ElementId element, int local_edge,
                                              const LocalModificationOptions2& options) {
  const auto vs = mesh.vertices(element);
  const VertexId c = vs[static_cast<std::size_t>(local_edge)];
  if (is_constrained_edge(mesh, element, local_edge)) {
    const bool may_coarsen = options.coarsen_straight_boundary || options.input_segments;
    if (!may_coarsen || mesh.neighbour(element, local_edge) != no_element) return std::nullopt;
    const VertexId a = vs[static_cast<std::size_t>((local_edge + 1) % 3)];
    const VertexId b = vs[static_cast<std::size_t>((local_edge + 2) % 3)];
    if (auto change = collapse_boundary_vertex(mesh, element, a, b, c, options)) return change;
    return collapse_boundary_vertex(mesh, element, b, a, c, options);
  }
  VertexId kept = vs[static_cast<std::size_t>((local_edge + 1) % 3)];
  VertexId gone = vs[static_cast<std::size_t>((local_edge + 2) % 3)];
  const ElementId across = mesh.neighbour(element, local_edge);
  const VertexId d = mesh.vertices(across)[static_cast<std::size_t>(mesh.mirror_facet(element, local_edge))];
  const bool kept_on_trace = is_trace_vertex(mesh, kept), gone_on_trace = is_trace_vertex(mesh, gone);
  if (kept_on_trace && gone_on_trace) return std::nullopt;
  if (gone_on_trace) std::swap(kept, gone);
  const auto star_kept = local::ordered_star(mesh, kept);
  const auto star_gone = local::ordered_star(mesh, gone);
  if (!star_kept || !star_gone || !link_condition_holds(*star_kept, *star_gone, c, d))
    return std::nullopt;
  const Point2d merged = (kept_on_trace || gone_on_trace)
                             ? mesh.point(kept)
                             : local::midpoint(mesh.point(kept), mesh.point(gone));

  std::vector<ElementId> removed{element, across};
  std::vector<local::VirtualTriangle> added;
  double q0 = options.collapse_reference == CollapseReference::survivors_and_removed
                  ? std::min(local::quality_of(mesh, element, options), local::quality_of(mesh, across, options))
                  : std::numeric_limits<double>::infinity();
  double q1 = std::numeric_limits<double>::infinity();
  for (const auto* star : {&*star_kept, &*star_gone})
    for (const ElementId e : star->elements) {
      if (e == element || e == across) continue;
      removed.push_back(e);
      q0 = std::min(q0, local::quality_of(mesh, e, options));
      auto t = local::virtual_triangle(mesh, mesh.vertices(e), mesh.label(e));
      for (std::size_t i = 0; i < 3; ++i)
        if (t.vertices[i] == kept || t.vertices[i] == gone) t.vertices[i] = kept, t.points[i] = merged;
      if (!local::is_positive(t)) return std::nullopt;
      q1 = std::min(q1, local::quality_of(t, options));
      added.push_back(t);
    }
  if (!(q1 > q0)) return std::nullopt;
  auto change = local::replace_elements(mesh, removed, added);
  mesh.remove_vertex(gone);
  mesh.move_vertex(kept, merged);
  return change;
}

}  // namespace certimesh::topology
