// Internal: the broad phase of "which domain segments does a mesh vertex lie on" in 2D, by a
// plane sweep, in O((n + q) log n + k) for n segments, q points and k candidate pairs, whatever
// the shape. A box grid is quadratic where many long segments pass close together (the spikes
// of a 10^4-gon star: 17 million box overlaps for 240k vertices).
//
// For each point p it lists every segment that meets p's rounding box R (the reals that round
// to p), plus the few neighbours that bound the search; the exact test (on_simplex.h) then
// decides each candidate. Why no segment meeting R is missed:
//  * A segment meeting R has p.y in its y-range: R's y-range holds one double, p.y.
//  * Split R at y = p.y into a lower half R- and an upper half R+. A non-horizontal segment
//    meeting R+ above p.y spans [p.y, next(p.y)] upward (its upper end is a double above p.y);
//    one meeting R- below p.y spans [prev(p.y), p.y]; one meeting R only at height p.y ends
//    there or passes there, and spans one of the two half-bands. So: the segments spanning the
//    lower half-band (lower end below p.y) are searched for R-, those spanning the upper one
//    (upper end above p.y) for R+, and horizontal segments at height p.y apart.
//  * In a half-band, the segments spanning it are ordered left to right and do not cross (the
//    domain passed its first-contact test). Walking right from p, the first one whose line lies
//    strictly right of both right corners of p's box of neighbouring doubles (restricted to the
//    half-band) bounds the walk: every segment right of it stays right of it across the
//    half-band, so it misses R's half too. Likewise to the left.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "certimesh/predicates/point.h"

namespace certimesh::certificate::detail {

struct Segment2 {
  predicates::Point2 a, b;
};

/// (point, segment) pairs, each point's segments together: every segment meeting the point's
/// rounding box is among them (and some that do not). Points and segments finite; the
/// segments pairwise disjoint apart from shared endpoints, none of zero length.
std::vector<std::pair<std::uint32_t, std::uint32_t>> segments_near_points_2d(const std::vector<Segment2>& segments,
                                                                             const std::vector<predicates::Point2>& points);

}  // namespace certimesh::certificate::detail
