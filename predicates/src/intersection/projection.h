// The three coordinate-plane projections of space, in the order the tests try them:
// drop z, drop x, drop y. A separating line in any of them certifies separation in space;
// the exact tests use the first in which the triangle's projection is not degenerate.
#pragma once

#include "certimesh/predicates/point.h"

namespace certimesh::predicates::intersection_detail {

inline Point2 project(const Point3& p, int dropped_axis) {
  switch (dropped_axis) {
    case 0:
      return {p.y, p.z};
    case 1:
      return {p.z, p.x};
    default:
      return {p.x, p.y};
  }
}

/// Dropped axis of the k-th projection tried (k = 0, 1, 2).
constexpr int projection_axis(int k) { return k == 0 ? 2 : k - 1; }

}  // namespace certimesh::predicates::intersection_detail
