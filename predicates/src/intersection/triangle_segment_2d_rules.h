// Algorithm 11 (digest B §3.4), written once for both sign sources (sign_source.h).
//
// Every `disjoint` rests on a separating line: the segment's line with the three triangle
// vertices strictly on one side (no orientation needed), or a side of the triangle with
// both segment ends strictly outside, which needs the triangle's own orientation to be
// certain so that "outside" is known. With exact signs the rules are complete for a
// non-degenerate triangle and a segment that is not a point at a shared vertex.
#pragma once

#include <array>

#include "bounding_box.h"
#include "certimesh/predicates/intersection/mode.h"
#include "certimesh/predicates/intersection/vertex.h"
#include "shared_vertices.h"
#include "sign_source.h"

namespace certimesh::predicates::intersection_detail {

/// Rule 1: the three triangle vertices strictly on one side of the line pq.
template <class Sg>
bool triangle_beside_line(const std::array<Point2, 3>& tri, const Point2& p, const Point2& q) {
  const int s0 = Sg::o2(p, q, tri[0]);
  return s0 != 0 && Sg::o2(p, q, tri[1]) == s0 && Sg::o2(p, q, tri[2]) == s0;
}

/// Rules 2-4: p and q strictly outside one side of the counterclockwise triangle.
template <class Sg>
bool beyond_a_side(const std::array<Point2, 3>& ccw, const Point2& p, const Point2& q) {
  for (int i = 0; i < 3; ++i) {
    const Point2 &a = ccw[i], &b = ccw[(i + 1) % 3];
    if (Sg::o2(a, b, p) < 0 && Sg::o2(a, b, q) < 0) return true;
  }
  return false;
}

/// Case 0 (no shared vertex). With p == q it is the exact point-in-triangle test.
template <class Sg>
Overlap triangle_segment_no_shared(const std::array<Point2, 3>& tri, const Point2& p,
                                   const Point2& q) {
  const std::array<Point2, 2> seg{p, q};
  if (boxes_apart(tri, seg) || triangle_beside_line<Sg>(tri, p, q)) return Overlap::disjoint;
  const int o = Sg::o2(tri[0], tri[1], tri[2]);
  if (o == 0) return Overlap::intersect;  // orientation unknown: no side certifies
  const std::array<Point2, 3> ccw = o > 0 ? tri : std::array<Point2, 3>{tri[0], tri[2], tri[1]};
  return beyond_a_side<Sg>(ccw, p, q) ? Overlap::disjoint : Overlap::intersect;
}

/// Case 1, fixed: triangle (v, a, b) and segment (v, w). Only the two sides through v may
/// certify; the opposite side never can (its sum is >= 0 in exact arithmetic, and a
/// filtered 0 there hides a real crossing: digest B §3.4 [CAVEAT]).
template <class Sg>
Overlap triangle_segment_one_shared(const Point2& v, const Point2& a, const Point2& b,
                                    const Point2& w) {
  if (w == v) return Overlap::disjoint;  // the segment is the shared point itself
  const int o = Sg::o2(v, a, b);
  if (o == 0) return Overlap::intersect;
  const Point2& first = o > 0 ? a : b;  // (v, first, last) counterclockwise
  const Point2& last = o > 0 ? b : a;
  if (Sg::o2(v, first, w) < 0 || Sg::o2(last, v, w) < 0) return Overlap::disjoint;
  return Overlap::intersect;
}

template <class Sg>
Overlap triangle_segment_2d_rules(const std::array<Vertex2, 3>& tri,
                                  const std::array<Vertex2, 2>& seg) {
  const std::span<const Vertex2> ts(tri), ss(seg);
  if (fully_shared(ss, ts) || fully_shared(ts, ss)) return Overlap::disjoint;
  for (int i = 0; i < 2; ++i) {
    const int j = shared_index(seg[i], ts);
    if (j >= 0)
      return triangle_segment_one_shared<Sg>(tri[j].point, tri[(j + 1) % 3].point,
                                             tri[(j + 2) % 3].point, seg[1 - i].point);
  }
  return triangle_segment_no_shared<Sg>({tri[0].point, tri[1].point, tri[2].point}, seg[0].point,
                                        seg[1].point);
}

}  // namespace certimesh::predicates::intersection_detail
