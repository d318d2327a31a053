// Boundary Steiner vertices inside an input segment (input_segment_run_2.h).
#include "input_segment_run_2.h"

#include <algorithm>
#include <cmath>

namespace certimesh::topology::local {

namespace {

// No edge through v other than its two boundary edges is constrained.
bool only_boundary_edges_constrained(const TriangleMesh2& mesh, VertexId v, const OrderedStar2& star) {
  for (const ElementId e : star.elements) {
    const int i = local_index(mesh, e, v);
    for (const int facet : {(i + 1) % 3, (i + 2) % 3})
      if (mesh.neighbour(e, facet) != no_element && is_constrained_edge(mesh, e, facet)) return false;
  }
  return true;
}

}  // namespace

bool same_segment(const InputSegment2& s, const InputSegment2& t) {
  return (s.start == t.start && s.end == t.end) || (s.start == t.end && s.end == t.start);
}

bool lies_on(const Point2d& p, const InputSegment2& s, const InputSegments2& segments) {
  if (p == s.start || p == s.end) return true;
  const auto containing = segments.segment_containing(p);
  return containing && same_segment(*containing, s);
}

std::optional<SegmentRun2> segment_run(const TriangleMesh2& mesh, VertexId v, const InputSegments2& segments) {
  if (!segments) return std::nullopt;
  auto star = ordered_star(mesh, v);
  if (!star || star->closed || star->link.size() < 2) return std::nullopt;
  const auto segment = segments.segment_containing(mesh.point(v));
  if (!segment || !only_boundary_edges_constrained(mesh, v, *star)) return std::nullopt;
  const VertexId before = star->link.front(), after = star->link.back();
  if (!lies_on(mesh.point(before), *segment, segments) || !lies_on(mesh.point(after), *segment, segments))
    return std::nullopt;
  return SegmentRun2{std::move(*star), *segment, before, after};
}

double fraction_along(const Point2d& p, const InputSegment2& s) {
  const double dx = s.end[0] - s.start[0], dy = s.end[1] - s.start[1];
  const double f = ((p[0] - s.start[0]) * dx + (p[1] - s.start[1]) * dy) / (dx * dx + dy * dy);
  return std::clamp(f, 0.0, 1.0);
}

bool strictly_between(const Point2d& a, const Point2d& x, const Point2d& b, const InputSegment2& s) {
  const bool along_x = std::abs(s.end[0] - s.start[0]) >= std::abs(s.end[1] - s.start[1]);
  const std::size_t k = along_x ? 0 : 1;
  if (s.end[k] == s.start[k]) return false;  // a degenerate segment: no order to trust
  const auto lo = std::min(a[k], b[k]), hi = std::max(a[k], b[k]);
  return lo < x[k] && x[k] < hi;
}

}  // namespace certimesh::topology::local
