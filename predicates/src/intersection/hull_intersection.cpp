#include "hull_intersection.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

#include "certimesh/predicates/orient3d.h"

namespace certimesh::predicates::intersection_detail {
namespace {

bool intervals_meet(std::span<const Point3> p, std::span<const Point3> q, int axis) {
  const auto range = [axis](std::span<const Point3> s) {
    double lo = coord(s[0], axis), hi = lo;
    for (const Point3& x : s) {
      lo = std::min(lo, coord(x, axis));
      hi = std::max(hi, coord(x, axis));
    }
    return std::array<double, 2>{lo, hi};
  };
  const auto a = range(p), b = range(q);
  return a[0] <= b[1] && b[0] <= a[1];
}

// Side of x relative to the hyperplane through h (2 points in a plane frame, 3 in space).
int side(const Frame& f, const std::array<Point3, 3>& h, const Point3& x) {
  if (f.dim == 2) return frame_orient2(f, h[0], h[1], x);
  return to_int(orient3d(h[0], h[1], h[2], x));
}

// Whether h spans a hyperplane of the frame (two distinct points, three non-collinear).
bool spans_hyperplane(const Frame& f, const std::array<Point3, 3>& h) {
  if (f.dim == 2) return frame_distinct(f, h[0], h[1]);
  return affine_span(h, space_frame).dim == 2;
}

// Points of s on h if every point of p is on one closed side and every point of q on
// the other; otherwise false.
bool weakly_separates(const Frame& f, const std::array<Point3, 3>& h, std::span<const Point3> p,
                      std::span<const Point3> q, std::vector<Point3>& p_on,
                      std::vector<Point3>& q_on) {
  int p_side = 0, q_side = 0;
  p_on.clear();
  q_on.clear();
  const auto scan = [&](std::span<const Point3> s, int& s_side, std::vector<Point3>& on) {
    for (const Point3& x : s) {
      const int v = side(f, h, x);
      if (v == 0)
        on.push_back(x);
      else if (s_side == 0)
        s_side = v;
      else if (s_side != v)
        return false;
    }
    return true;
  };
  if (!scan(p, p_side, p_on) || !scan(q, q_side, q_on)) return false;
  return p_side == 0 || q_side == 0 || p_side != q_side;
}

bool full_dimensional_meet(std::span<const Point3> p, std::span<const Point3> q, const Frame& f) {
  std::vector<Point3> all(p.begin(), p.end());
  all.insert(all.end(), q.begin(), q.end());
  const std::size_t n = all.size();
  std::vector<Point3> p_on, q_on;
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j)
      for (std::size_t k = (f.dim == 2 ? n - 1 : j + 1); k < n; ++k) {
        const std::array<Point3, 3> h{all[i], all[j], all[k]};
        if (!spans_hyperplane(f, h) || !weakly_separates(f, h, p, q, p_on, q_on)) continue;
        return hulls_intersect(p_on, q_on, f);
      }
  return true;  // no separating hyperplane: the hulls meet
}

}  // namespace

bool hulls_intersect(std::span<const Point3> p, std::span<const Point3> q, const Frame& ambient) {
  if (p.empty() || q.empty()) return false;
  std::vector<Point3> all(p.begin(), p.end());
  all.insert(all.end(), q.begin(), q.end());
  const AffineSpan s = affine_span(all, ambient);
  if (s.dim == 0) return true;
  if (s.dim < ambient.dim) return hulls_intersect(p, q, s.frame);
  if (ambient.dim == 1) return intervals_meet(p, q, ambient.axis[0]);
  return full_dimensional_meet(p, q, ambient);
}

}  // namespace certimesh::predicates::intersection_detail
