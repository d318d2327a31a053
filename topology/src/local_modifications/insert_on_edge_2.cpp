// Algorithm 30: a node on an edge (local_modifications_2.h). On a constrained edge the node is
// the caller's boundary projection (the monograph's F((t1 + t2) / 2)) or, on an input segment,
// the rounding of an exact point of it (design decision 2); either is then checked exactly.
#include <algorithm>
#include <cmath>
#include <limits>

#include "input_segment_run_2.h"
#include "local_geometry_2.h"

namespace certimesh::topology {

namespace {

// The two halves of triangle (c, a, b) when m goes on its edge (a, b).
void append_halves(const TriangleMesh2& mesh, VertexId c, VertexId a, VertexId b, VertexId m,
                   const Point2d& at, Label label, std::vector<local::VirtualTriangle>& out) {
  for (const auto& vs : {TriangleMesh2::Element{a, m, c}, TriangleMesh2::Element{m, b, c}}) {
    local::VirtualTriangle t{vs, {}, label};
    for (std::size_t i = 0; i < 3; ++i) t.points[i] = vs[i] == m ? at : mesh.point(vs[i]);
    out.push_back(t);
  }
}

// The node on the constrained edge (a, b) when both ends are on one input segment: the
// rounding of the exact point of the segment half-way between the ends' fractions, strictly
// between them along it. A segment that the edge spans whole (both ends domain vertices) is
// recognised by asking the caller about the point half-way along (a, b).
std::optional<Point2d> node_on_input_segment(const Point2d& a, const Point2d& b, const InputSegments2& segments) {
  auto segment = segments.segment_containing(a);
  if (!segment) segment = segments.segment_containing(b);
  if (!segment) {
    const InputSegment2 whole{a, b};
    const auto containing = segments.segment_containing(segments.point_on(whole, 0.5));
    if (!containing || !local::same_segment(*containing, whole)) return std::nullopt;
    segment = whole;
  }
  if (!local::lies_on(a, *segment, segments) || !local::lies_on(b, *segment, segments)) return std::nullopt;
  const double f = 0.5 * (local::fraction_along(a, *segment) + local::fraction_along(b, *segment));
  const Point2d at = segments.point_on(*segment, f);
  if (!local::strictly_between(a, at, b, *segment)) return std::nullopt;
  return at;
}

}  // namespace

std::optional<LocalChange2> try_insert_on_edge(TriangleMesh2& mesh, ElementId element, int local_edge,
                                               const LocalModificationOptions2& options) {
  const auto vs = mesh.vertices(element);
  const VertexId c = vs[static_cast<std::size_t>(local_edge)];
  const VertexId a = vs[static_cast<std::size_t>((local_edge + 1) % 3)];
  const VertexId b = vs[static_cast<std::size_t>((local_edge + 2) % 3)];
  const bool constrained = is_constrained_edge(mesh, element, local_edge);
  if (constrained && !options.boundary_projection && !options.input_segments) return std::nullopt;
  Point2d at = local::midpoint(mesh.point(a), mesh.point(b));
  if (constrained && options.boundary_projection) {
    at = options.boundary_projection(a, b, at);
  } else if (constrained) {
    const auto on_segment = node_on_input_segment(mesh.point(a), mesh.point(b), options.input_segments);
    if (!on_segment) return std::nullopt;
    at = *on_segment;
  }
  if (!std::isfinite(at[0]) || !std::isfinite(at[1])) return std::nullopt;

  // The new vertex's id is not known before it is added: a placeholder that no live vertex has.
  const VertexId m = VertexId::none();
  std::vector<local::VirtualTriangle> added;
  std::vector<ElementId> removed{element};
  append_halves(mesh, c, a, b, m, at, mesh.label(element), added);
  const ElementId across = mesh.neighbour(element, local_edge);
  if (across != no_element) {
    const VertexId d = mesh.vertices(across)[static_cast<std::size_t>(mesh.mirror_facet(element, local_edge))];
    removed.push_back(across);
    append_halves(mesh, d, b, a, m, at, mesh.label(across), added);
  }
  // Lemma 5.2.2: valid iff every half is strictly counterclockwise, decided exactly.
  double q1 = std::numeric_limits<double>::infinity();
  for (const auto& t : added) {
    if (!local::is_positive(t)) return std::nullopt;
    q1 = std::min(q1, local::quality_of(t, options));
  }
  double q0 = std::numeric_limits<double>::infinity();
  for (const ElementId e : removed) q0 = std::min(q0, local::quality_of(mesh, e, options));
  if (!(q1 > q0)) return std::nullopt;

  const Label edge_label = mesh.facet_label({a, b});
  const VertexId new_vertex = mesh.add_vertex(at);
  for (auto& t : added)
    for (auto& v : t.vertices)
      if (v == m) v = new_vertex;
  auto change = local::replace_elements(mesh, removed, added);
  if (edge_label != 0) {
    mesh.set_facet_label({a, b}, 0);
    mesh.set_facet_label({a, new_vertex}, edge_label);
    mesh.set_facet_label({new_vertex, b}, edge_label);
  }
  return change;
}

}  // namespace certimesh::topology
