// Whether a mesh vertex lies on a domain segment / triangle (on_simplex.h): exactly, by the
// predicates; certainly not, by orient signs at the corners of the box of neighbouring doubles;
// otherwise by the separating axis theorem in rationals.
#include "on_simplex.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "exact_sum.h"
#include "next_double.h"
#include "rational.h"

namespace certimesh::certificate::detail {
namespace {

// Half-way to the next double towards `toward`: the rounding box ends there.
Q half_way(double x, double toward) {
  const double y = std::nextafter(x, toward);
  return std::isfinite(y) ? (Q(x) + Q(y)) / 2 : Q(x);
}

// Point x seen along coordinate axis k (3D: the other two coordinates, in order; 2D: x itself).
predicates::Point2 drop_axis(const double* x, int k, int dim) {
  return dim == 2 ? predicates::Point2{x[0], x[1]} : predicates::Point2{k == 0 ? x[1] : x[0], k == 2 ? x[1] : x[2]};
}

}  // namespace

// Whether p lies exactly on the segment (s[2] null) or triangle `s`, by the exact predicates:
// the common case (grid vertices, exact midpoints), so the rational box test runs only for the rest.
bool lies_exactly_on(const std::array<const double*, 3>& s, int dim, const double* p) {
  using namespace predicates;
  if (s[2] == nullptr) {  // a segment: collinear in every coordinate plane, and within its box
    for (int k = 0; k < dim; ++k)
      if (std::min(s[0][k], s[1][k]) > p[k] || p[k] > std::max(s[0][k], s[1][k])) return false;
    for (int k = 0; k < (dim == 2 ? 1 : 3); ++k)
      if (orient2d(drop_axis(s[0], k, dim), drop_axis(s[1], k, dim), drop_axis(p, k, dim)) != Sign::zero) return false;
    return true;
  }
  auto pt = [](const double* x) { return Point3{x[0], x[1], x[2]}; };
  if (orient3d(pt(s[0]), pt(s[1]), pt(s[2]), pt(p)) != Sign::zero) return false;
  for (int k = 0; k < 3; ++k) {  // coplanar: decide in a coordinate plane the triangle keeps its area in
    const Sign t = orient2d(drop_axis(s[0], k, dim), drop_axis(s[1], k, dim), drop_axis(s[2], k, dim));
    if (t == Sign::zero) continue;
    for (int i = 0; i < 3; ++i)
      if (orient2d(drop_axis(s[static_cast<std::size_t>(i)], k, dim), drop_axis(s[static_cast<std::size_t>((i + 1) % 3)], k, dim), drop_axis(p, k, dim)) == -t) return false;
    return true;
  }
  return false;
}

namespace {

// A cheap exact proof that p's accepted box misses the segment (2D) / triangle `s`: `outer`, a
// double box containing it (the box of p's neighbouring doubles, or accepted_bounds under a
// tolerance), lies strictly on one side of the facet's line / plane, or, in the plane, strictly
// outside one edge. Otherwise: rationals.
bool box_certainly_misses(const std::array<const double*, 3>& s, int dim, const Box& outer) {
  using namespace predicates;
  std::array<std::array<double, 3>, 2> box{};  // lo, hi
  for (int k = 0; k < dim; ++k) {
    box[0][k] = outer.lo[k], box[1][k] = outer.hi[k];
    if (!std::isfinite(box[0][k]) || !std::isfinite(box[1][k]) || (dim == 3 && s[2] == nullptr)) return false;
  }
  auto all_corners = [&](int kx, int ky, int kz, Sign want, auto&& sign_at) {  // kz < 0: a 2D box
    for (int b = 0; b < (kz < 0 ? 4 : 8); ++b)
      if (sign_at(box[b & 1][kx], box[b >> 1 & 1][ky], kz < 0 ? 0.0 : box[b >> 2 & 1][kz]) != want) return false;
    return true;
  };
  auto outside_an_edge = [&](int k, int n, Sign t) {  // projected along axis k; n edges
    const int kx = dim == 2 || k != 0 ? 0 : 1, ky = dim == 2 || k == 2 ? 1 : 2;
    for (int i = 0; i < n; ++i) {
      const Point2 u = drop_axis(s[static_cast<std::size_t>(i)], k, dim), v = drop_axis(s[static_cast<std::size_t>((i + 1) % (n == 1 ? 2 : 3))], k, dim);
      if (all_corners(kx, ky, -1, -t, [&](double x, double y, double) { return orient2d(u, v, {x, y}); })) return true;
    }
    return false;
  };
  if (dim == 2) return outside_an_edge(2, 1, Sign::negative) || outside_an_edge(2, 1, Sign::positive);
  const Point3 a{s[0][0], s[0][1], s[0][2]}, b{s[1][0], s[1][1], s[1][2]}, c{s[2][0], s[2][1], s[2][2]};
  for (Sign side : {Sign::negative, Sign::positive})
    if (all_corners(0, 1, 2, side, [&](double x, double y, double z) { return orient3d(a, b, c, {x, y, z}); })) return true;
  for (int k = 0; k < 3; ++k)
    if (const Sign t = orient2d(drop_axis(s[0], k, dim), drop_axis(s[1], k, dim), drop_axis(s[2], k, dim)); t != Sign::zero) return outside_an_edge(k, 3, t);
  return false;
}

// The box of reals accepted for p: its rounding box, widened to `ulps` ulps (the distance to
// the neighbouring double) and to `absolute` per coordinate when a tolerance is given.
void accepted_box(const double* p, int dim, const BoundaryTolerance& tol, Vec& lo, Vec& hi) {
  const double inf = std::numeric_limits<double>::infinity();
  for (int k = 0; k < dim; ++k) {
    lo[k] = half_way(p[k], -inf), hi[k] = half_way(p[k], inf);
    const Q x = p[k];
    if (tol.ulps > 0.5) {
      lo[k] = std::min<Q>(lo[k], x - (x - lo[k]) * 2 * Q(tol.ulps));
      hi[k] = std::max<Q>(hi[k], x + (hi[k] - x) * 2 * Q(tol.ulps));
    }
    if (tol.absolute > 0) lo[k] = std::min<Q>(lo[k], x - Q(tol.absolute)), hi[k] = std::max<Q>(hi[k], x + Q(tol.absolute));
  }
}

// Whether the simplex `pts` (2 or 3 points) meets p's accepted box. Separating axis theorem,
// exact: the box's axes, the simplex's normal (2D segment, 3D triangle) and the edge x axis
// cross products (3D).
bool meets_box(const std::vector<Vec>& pts, int dim, const double* p, const BoundaryTolerance& tol) {
  Vec lo{0, 0, 0}, hi{0, 0, 0};
  accepted_box(p, dim, tol, lo, hi);
  std::vector<Vec> axes;
  for (int k = 0; k < dim; ++k) axes.push_back(Vec{Q(k == 0), Q(k == 1), Q(k == 2)});
  std::vector<Vec> edges;
  for (std::size_t i = 0; i + 1 < pts.size() + (pts.size() == 3); ++i)
    edges.push_back(minus(pts[(i + 1) % pts.size()], pts[i]));
  if (dim == 2) axes.push_back(Vec{-edges[0][1], edges[0][0], 0});
  if (dim == 3 && pts.size() == 3) axes.push_back(cross(edges[0], edges[1]));
  for (std::size_t e = 0; dim == 3 && e < edges.size(); ++e)
    for (int k = 0; k < 3; ++k) axes.push_back(cross(edges[e], axes[static_cast<std::size_t>(k)]));
  for (const Vec& a : axes) {
    Q fmin = a[0] * pts[0][0] + a[1] * pts[0][1] + a[2] * pts[0][2], fmax = fmin, bmin = 0, bmax = 0;
    for (const Vec& q : pts) {
      const Q x = a[0] * q[0] + a[1] * q[1] + a[2] * q[2];
      fmin = std::min(fmin, x), fmax = std::max(fmax, x);
    }
    for (int k = 0; k < dim; ++k) bmin += a[k] * (a[k] > 0 ? lo[k] : hi[k]), bmax += a[k] * (a[k] > 0 ? hi[k] : lo[k]);
    if (fmax < bmin || bmax < fmin) return false;
  }
  return true;
}


// Whether segment ab meets p's rounding box (2D, no tolerance), in integers: the separating
// axis test of meets_box with no rational. The box axes: a double s is at least the box's lower
// end (half-way to p's lower neighbour) iff s >= p, and at most its upper end iff s <= p. The
// segment's normal: f(x) = (b - a) x (x - a) is affine, so at a box corner c = (p + q) / 2, q
// the diagonal neighbour double of p towards that corner, 2 f(c) = f(p) + f(q): products of
// doubles, summed exactly, f(p) and the constant part of f(q) once for both corners. The line
// meets the box iff f is <= 0 at its lowest corner and >= 0 at its highest.
bool segment_meets_rounding_box(const double* a, const double* b, const double* p) {
  for (int k = 0; k < 2; ++k)
    if (std::max(a[k], b[k]) < p[k] || std::min(a[k], b[k]) > p[k]) return false;
  // f(x) = bx xy - ax xy - by xx + ay xx + (by ax - bx ay): f(p) and twice the constant.
  ExactProductSum at_p;
  at_p.add(b[0], p[1]), at_p.add(a[0], p[1], -1), at_p.add(b[1], p[0], -1), at_p.add(a[1], p[0]);
  at_p.add(b[1], a[0], 2), at_p.add(b[0], a[1], -2);
  auto twice_f_at_corner = [&](int towards) {  // +1: the corner where f is largest; -1: smallest
    // f grows with x when b.y < a.y, with y when b.x > a.x; q steps one double that way.
    auto step = [&](double x, int grows) {
      if (grows == 0) return x;
      const double y = next_double(x, grows * towards > 0 ? 1 : -1);
      return std::isfinite(y) ? y : x;  // the box ends at x there (half_way)
    };
    const double qx = step(p[0], (b[1] < a[1]) - (b[1] > a[1])), qy = step(p[1], (b[0] > a[0]) - (b[0] < a[0]));
    ExactProductSum sum = at_p;  // f(p) + f(q)
    sum.add(b[0], qy), sum.add(a[0], qy, -1), sum.add(b[1], qx, -1), sum.add(a[1], qx);
    return sum.sign();
  };
  return twice_f_at_corner(-1) <= 0 && twice_f_at_corner(+1) >= 0;
}

}  // namespace

bool meets_accepted_box(const std::array<const double*, 3>& s, int dim, const double* p, const BoundaryTolerance& tol) {
  // 2D, no tolerance: the integer test at once. The sweep's candidates are mostly the segments
  // the point is near, where the corner signs of the shortcut below are near zero and take the
  // predicates' exact stage, four times, before this test runs all the same.
  if (dim == 2 && !tol.active()) return segment_meets_rounding_box(s[0], s[1], p);
  Box outer;
  for (int k = 0; k < dim; ++k) outer.lo[k] = next_down(p[k]), outer.hi[k] = next_up(p[k]);
  if (box_certainly_misses(s, dim, tol.active() ? accepted_bounds(p, dim, tol) : outer)) return false;
  std::vector<Vec> pts;
  for (const double* x : s)
    if (x != nullptr) pts.push_back(point_of(x, dim));
  return meets_box(pts, dim, p, tol);
}

Box accepted_bounds(const double* p, int dim, const BoundaryTolerance& tol) {
  Box b;
  for (int k = 0; k < dim; ++k) {
    const double step = std::max(std::abs(p[k] - std::nextafter(p[k], -HUGE_VAL)), std::abs(std::nextafter(p[k], HUGE_VAL) - p[k]));
    const double reach = std::max(tol.absolute, (std::max(tol.ulps, 0.5) + 1) * step);  // outward, generously
    b.lo[k] = std::nextafter(p[k] - reach, -HUGE_VAL), b.hi[k] = std::nextafter(p[k] + reach, HUGE_VAL);
  }
  return b;
}

}  // namespace certimesh::certificate::detail
