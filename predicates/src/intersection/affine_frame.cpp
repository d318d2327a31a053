#include "affine_frame.h"

#include <cstddef>

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "projection.h"

namespace certimesh::predicates::intersection_detail {

int frame_orient2(const Frame& f, const Point3& a, const Point3& b, const Point3& c) {
  return to_int(orient2d(in_plane(a, f), in_plane(b, f), in_plane(c, f)));
}

bool frame_distinct(const Frame& f, const Point3& a, const Point3& b) {
  if (f.dim == 3) return !(a == b);
  for (int i = 0; i < f.dim; ++i)
    if (coord(a, f.axis[i]) != coord(b, f.axis[i])) return true;
  return false;
}

namespace {

// The coordinate axis of `ambient` along which a and b differ (they do).
Frame line_frame(const Frame& ambient, const Point3& a, const Point3& b) {
  const int n = ambient.dim == 3 ? 3 : ambient.dim;
  for (int i = 0; i < n; ++i) {
    const int ax = ambient.dim == 3 ? i : ambient.axis[i];
    if (coord(a, ax) != coord(b, ax)) return {1, {ax, ax}};
  }
  return {1, {0, 0}};
}

// In space: the coordinate plane in which a, b, c project to a true triangle, if any.
bool plane_frame(const Point3& a, const Point3& b, const Point3& c, Frame& out) {
  for (int k = 0; k < 3; ++k) {
    const int dropped = projection_axis(k);
    const Frame f{2, {(dropped + 1) % 3, (dropped + 2) % 3}};
    if (frame_orient2(f, a, b, c) != 0) {
      out = f;
      return true;
    }
  }
  return false;
}

}  // namespace

AffineSpan affine_span(std::span<const Point3> pts, const Frame& ambient) {
  AffineSpan s;
  const int n = static_cast<int>(pts.size());
  int i1 = 1;
  while (i1 < n && !frame_distinct(ambient, pts[0], pts[i1])) ++i1;
  if (i1 == n) return s;  // one point
  s = {1, line_frame(ambient, pts[0], pts[i1]), {0, i1, 0, 0}};
  if (ambient.dim == 1) return s;
  for (int i2 = 1; i2 < n; ++i2) {
    Frame plane = ambient;
    const bool spans = ambient.dim == 2 ? frame_orient2(ambient, pts[0], pts[i1], pts[i2]) != 0
                                        : plane_frame(pts[0], pts[i1], pts[i2], plane);
    if (!spans) continue;
    s = {2, plane, {0, i1, i2, 0}};
    if (ambient.dim == 2) return s;
    for (int i3 = 1; i3 < n; ++i3)
      if (orient3d(pts[0], pts[i1], pts[i2], pts[i3]) != Sign::zero)
        return {3, space_frame, {0, i1, i2, i3}};
    return s;
  }
  return s;
}

}  // namespace certimesh::predicates::intersection_detail
