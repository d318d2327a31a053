// The angle floor of the improvement (ImprovementOptions2::min_angle_floor): a score that
// makes "the worst score of the changed triangles rises" also mean "no triangle falls below
// the floor, and the smallest angle below it never falls further". A triangle whose smallest
// angle a is below the floor A scores a/A − 1 (in [−1, 0)); every other one scores its quality
// q (in [0, 1]). Angles are approximate (they compare, never decide validity).
#pragma once

#include <algorithm>
#include <cmath>

#include "certimesh/topology/quality.h"

namespace certimesh::generators {

/// The smallest angle of the triangle (a, b, c), in degrees; 0 for a degenerate one.
inline double smallest_angle_degrees(const topology::Point2d& a, const topology::Point2d& b, const topology::Point2d& c) {
  const auto angle = [](const topology::Point2d& o, const topology::Point2d& p, const topology::Point2d& q) {
    const double ux = p[0] - o[0], uy = p[1] - o[1], wx = q[0] - o[0], wy = q[1] - o[1];
    return std::atan2(std::fabs(ux * wy - uy * wx), ux * wx + uy * wy);
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)}) * (180.0 / 3.14159265358979323846);
}

/// The floored score: `quality` itself when the floor is 0 or the triangle's smallest angle is
/// at least `floor_degrees`, else angle/floor − 1.
inline double floored_score(double quality, const topology::Point2d& a, const topology::Point2d& b,
                            const topology::Point2d& c, double floor_degrees) {
  if (!(floor_degrees > 0.0)) return quality;
  const double angle = smallest_angle_degrees(a, b, c);
  return angle < floor_degrees ? angle / floor_degrees - 1.0 : quality;
}

}  // namespace certimesh::generators
