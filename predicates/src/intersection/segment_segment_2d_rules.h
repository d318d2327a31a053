// The segment-segment rules, written once for both sign sources (sign_source.h).
//
// With exact signs they are complete for non-degenerate segments; zero-length segments
// with a shared vertex go to the exact fallback (exact_fallback.h) instead.
#pragma once

#include <array>

#include "bounding_box.h"
#include "certimesh/predicates/intersection/mode.h"
#include "certimesh/predicates/intersection/vertex.h"
#include "shared_vertices.h"
#include "sign_source.h"

namespace certimesh::predicates::intersection_detail {

/// p and q strictly on one side of the line ab: that line separates.
template <class Sg>
bool strictly_one_side(const Point2& a, const Point2& b, const Point2& p, const Point2& q) {
  const int sp = Sg::o2(a, b, p);
  return sp != 0 && Sg::o2(a, b, q) == sp;
}

/// p and q strictly on opposite sides of a coordinate line through v.
inline bool opposite_about(const Point2& v, const Point2& p, const Point2& q) {
  return compare(p.x, v.x) * compare(q.x, v.x) < 0 || compare(p.y, v.y) * compare(q.y, v.y) < 0;
}

/// Segments [v, a] and [v, b] sharing v: they meet beyond v only when collinear and
/// pointing the same way.
template <class Sg>
Overlap one_shared_segments(const Point2& v, const Point2& a, const Point2& b) {
  if (a == v || b == v) return Overlap::disjoint;      // one segment is the shared point itself
  if (Sg::o2(v, a, b) != 0) return Overlap::disjoint;  // not collinear: lines cross at v only
  return opposite_about(v, a, b) ? Overlap::disjoint : Overlap::intersect;
}

template <class Sg>
Overlap segment_segment_rules(const std::array<Vertex2, 2>& s, const std::array<Vertex2, 2>& t) {
  const std::span<const Vertex2> ss(s), ts(t);
  if (fully_shared(ss, ts) || fully_shared(ts, ss)) return Overlap::disjoint;
  for (int i = 0; i < 2; ++i) {
    const int j = shared_index(s[i], ts);
    if (j >= 0) return one_shared_segments<Sg>(s[i].point, s[1 - i].point, t[1 - j].point);
  }
  const Point2 &s0 = s[0].point, &s1 = s[1].point, &t0 = t[0].point, &t1 = t[1].point;
  if (strictly_one_side<Sg>(s0, s1, t0, t1) || strictly_one_side<Sg>(t0, t1, s0, s1) ||
      boxes_apart(std::array{s0, s1}, std::array{t0, t1}))
    return Overlap::disjoint;
  return Overlap::intersect;
}

}  // namespace certimesh::predicates::intersection_detail
