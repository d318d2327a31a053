// Input segments for the local modifications (input_segments_2.h).
#include "certimesh/generators/improvement/input_segments_2.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "../pipeline/point_on_segment.h"
#include "certimesh/predicates/orient2d.h"

namespace certimesh::generators {

namespace {

using topology::Point2d;

predicates::Point2 as_point(const Point2d& p) { return {p[0], p[1]}; }

// Whether s meets the box [lo, hi] (closed), exactly: the separating axis theorem for a
// segment and a box in the plane has three axes, the two coordinate axes (bounding boxes
// overlap) and the segment's normal (the box's corners are not all strictly on one side).
bool meets_box(const topology::InputSegment2& s, const Point2d& lo, const Point2d& hi) {
  for (std::size_t k = 0; k < 2; ++k)
    if (std::max(s.start[k], s.end[k]) < lo[k] || std::min(s.start[k], s.end[k]) > hi[k]) return false;
  int positive = 0, negative = 0;
  for (const Point2d& corner : {lo, hi, Point2d{lo[0], hi[1]}, Point2d{hi[0], lo[1]}}) {
    const auto sign = predicates::orient2d(as_point(s.start), as_point(s.end), as_point(corner));
    positive += sign == predicates::Sign::positive;
    negative += sign == predicates::Sign::negative;
  }
  return positive < 4 && negative < 4;
}

std::optional<topology::InputSegment2> segment_containing(const std::vector<topology::InputSegment2>& segments, const Point2d& p) {
  if (!std::isfinite(p[0]) || !std::isfinite(p[1])) return std::nullopt;
  // The neighbouring doubles bound p's rounding box (half an ulp each way) from outside: a
  // segment that misses this box misses the rounding box too.
  const Point2d lo{std::nextafter(p[0], -HUGE_VAL), std::nextafter(p[1], -HUGE_VAL)};
  const Point2d hi{std::nextafter(p[0], HUGE_VAL), std::nextafter(p[1], HUGE_VAL)};
  std::optional<topology::InputSegment2> found;
  for (const topology::InputSegment2& s : segments) {
    if (!meets_box(s, lo, hi)) continue;
    if (found || p == s.start || p == s.end) return std::nullopt;  // several segments, or a domain vertex
    found = s;
  }
  return found;
}

}  // namespace

topology::InputSegments2 input_segments_of(const PlanarDomain& domain) {
  auto segments = std::make_shared<std::vector<topology::InputSegment2>>();
  for (const DomainSegment& s : domain.segments) {
    const Point2 a = domain.points[s.a], b = domain.points[s.b];
    segments->push_back({{a.x, a.y}, {b.x, b.y}});
  }
  topology::InputSegments2 answer;
  answer.segment_containing = [segments](const Point2d& p) { return segment_containing(*segments, p); };
  answer.point_on = [](const topology::InputSegment2& s, double f) {
    const auto q = detail::point_on_segment(as_point(s.start), as_point(s.end), std::clamp(f, 0.0, 1.0));
    return Point2d{q.x, q.y};
  };
  return answer;
}

}  // namespace certimesh::generators
