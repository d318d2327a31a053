// Coordinate frames for the exact fallback: where a point set is full-dimensional.
//
// A frame is the whole space (dim 3), a coordinate plane (dim 2, two axes) or a coordinate
// axis (dim 1). A point set of affine dimension k has a frame of dimension k onto which
// its affine hull projects one-to-one, chosen with exact signs; every question about
// convex hulls of the set is then asked in that frame.
#pragma once

#include <array>
#include <span>

#include "certimesh/predicates/point.h"

namespace certimesh::predicates::intersection_detail {

struct Frame {
  int dim = 3;
  std::array<int, 2> axis{0, 1};
};

inline constexpr Frame space_frame{3, {0, 1}};

inline double coord(const Point3& p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }

inline Point2 in_plane(const Point3& p, const Frame& f) {
  return {coord(p, f.axis[0]), coord(p, f.axis[1])};
}

/// Exact orientation in a frame of dimension 2 (three points) or 3 (four points).
int frame_orient2(const Frame& f, const Point3& a, const Point3& b, const Point3& c);

/// Whether a and b differ within the frame's coordinates.
bool frame_distinct(const Frame& f, const Point3& a, const Point3& b);

/// Affine dimension of a non-empty point set, a frame of that dimension onto which its
/// hull projects one-to-one, and indices of affinely independent points spanning it.
struct AffineSpan {
  int dim = 0;
  Frame frame;
  std::array<int, 4> basis{0, 0, 0, 0};
};
AffineSpan affine_span(std::span<const Point3> points, const Frame& ambient);

}  // namespace certimesh::predicates::intersection_detail
