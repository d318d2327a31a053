// Bench-only prototypes: NOT certimesh's predicates, and not part of certimesh's
// proofs. Every prototype falls back to certimesh's own exact stage, and the start-up
// cross-check (bench_predicates.cpp) compares each one with the exact stage on every
// data set.
//
// BM_<p>_prototype (all four predicates): certimesh's own filter -- the same
// differences, the same determinant evaluation order, the same maxima, guards and
// proven constants (detail/filters.h, filter_constants.h) -- with only the control flow
// changed:
//
//   certimesh:  if (!(guards)) uncertain; if (det > eb) +; if (det < -eb) -; uncertain
//               => a compare-and-branch on the sign of det, a coin flip on random
//                  input: a mispredicted branch every other call.
//   prototype:  s = (det > eb) - (det < -eb)  (setcc, no branch), ok = guards & (s != 0)
//               => one branch, taken only when the filter fails (well predicted).
//
// It computes the same values and makes the same comparisons, so it answers exactly
// what certimesh's filter answers: a drop-in change.
//
// BM_orient2d_prototype_ozaki: an Ozaki-style filter (Ozaki, Buenger, Ogita, Oishi,
// Rump, BIT 56, 2016; the filter GEOS adopted), also branch-free:
// dl = acx*bcy, dr = acy*bcx, det = dl - dr, certain when |det| > theta*|dl + dr| +
// DBL_MIN. No maxima, no guards: overflow gives inf/NaN and every comparison false
// (uncertain); the DBL_MIN term is a deliberately generous allowance for underflow in
// the two products. theta is the JTS/GEOS literal (3u rounded up). Adopting it in the
// kernel would need its own Gappa proof, like every other constant there.
//
// BM_orient2d_prototype_fastexact: the Ozaki-style filter, then -- when every coordinate
// difference is exact and its magnitude 0 or within [2^-480, 2^500] -- the exact sign of
// acx*bcy - acy*bcx without expansions: rounding is monotone, so fl(p) > fl(q) implies
// p > q; only when the two rounded products tie does the sign come from their TwoProduct
// tails (exact in that range), whose rounded difference has the exact sign. Anything
// else goes to certimesh's exact stage.
#pragma once

#include <algorithm>
#include <cmath>

#include "certimesh/predicates/detail/exact_stages.h"
#include "certimesh/predicates/detail/expansion.h"
#include "certimesh/predicates/filter_constants.h"
#include "certimesh/predicates/point.h"
#include "certimesh/predicates/sign.h"

namespace certimesh_bench::prototype {

using certimesh::predicates::Point2;
using certimesh::predicates::Point3;
using certimesh::predicates::Sign;
namespace k = certimesh::predicates::filter_constants;
namespace cd = certimesh::predicates::detail;

// Branch-free certify: +1 / -1 when |det| > bound, 0 otherwise; NaN gives 0.
inline int certify_bits(double det, double bound) {
  return static_cast<int>(det > bound) - static_cast<int>(det < -bound);
}

inline Sign orient2d(const Point2& a, const Point2& b, const Point2& c) {
  const double acx = a.x - c.x, bcx = b.x - c.x;
  const double acy = a.y - c.y, bcy = b.y - c.y;
  const double det = acx * bcy - acy * bcx;
  const double maxx = std::max(std::fabs(acx), std::fabs(bcx));
  const double maxy = std::max(std::fabs(acy), std::fabs(bcy));
  const double lo = std::min(maxx, maxy), hi = std::max(maxx, maxy);
  const int s = certify_bits(det, k::orient2d_error_bound * maxx * maxy);
  const bool ok = (lo >= k::orient2d_lower_guard) & (hi <= k::orient2d_upper_guard) & (s != 0);
  if (ok) [[likely]] return static_cast<Sign>(s);
  return cd::orient2d_exact_stage(a, b, c);
}

// The Ozaki-style filter alone: positive / negative when certain, zero when uncertain.
inline Sign orient2d_ozaki_filter(const Point2& a, const Point2& b, const Point2& c) {
  constexpr double theta = 3.3306690621773724e-16;  // Ozaki et al.'s theta, rounded up
  constexpr double underflow_allowance = 0x1p-1022;  // DBL_MIN
  const double dl = (a.x - c.x) * (b.y - c.y);
  const double dr = (a.y - c.y) * (b.x - c.x);
  const double det = dl - dr;
  return static_cast<Sign>(certify_bits(det, theta * std::fabs(dl + dr) + underflow_allowance));
}

inline Sign orient2d_ozaki(const Point2& a, const Point2& b, const Point2& c) {
  const Sign f = orient2d_ozaki_filter(a, b, c);
  if (f != Sign::zero) [[likely]] return f;
  return cd::orient2d_exact_stage(a, b, c);
}

inline Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double adz = a.z - d.z, bdz = b.z - d.z, cdz = c.z - d.z;
  const double det = adx * (bdy * cdz - bdz * cdy) + bdx * (cdy * adz - cdz * ady) +
                     cdx * (ady * bdz - adz * bdy);
  const double maxx = std::max(std::max(std::fabs(adx), std::fabs(bdx)), std::fabs(cdx));
  const double maxy = std::max(std::max(std::fabs(ady), std::fabs(bdy)), std::fabs(cdy));
  const double maxz = std::max(std::max(std::fabs(adz), std::fabs(bdz)), std::fabs(cdz));
  const double lo = std::min(std::min(maxx, maxy), maxz);
  const double hi = std::max(std::max(maxx, maxy), maxz);
  const int s = certify_bits(det, k::orient3d_error_bound * maxx * maxy * maxz);
  const bool ok = (lo >= k::orient3d_lower_guard) & (hi <= k::orient3d_upper_guard) & (s != 0);
  if (ok) [[likely]] return static_cast<Sign>(s);
  return cd::orient3d_exact_stage(a, b, c, d);
}

inline Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const double adx = a.x - d.x, bdx = b.x - d.x, cdx = c.x - d.x;
  const double ady = a.y - d.y, bdy = b.y - d.y, cdy = c.y - d.y;
  const double alift = adx * adx + ady * ady;
  const double blift = bdx * bdx + bdy * bdy;
  const double clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) +
                     clift * (adx * bdy - bdx * ady);
  const double maxx = std::max(std::max(std::fabs(adx), std::fabs(bdx)), std::fabs(cdx));
  const double maxy = std::max(std::max(std::fabs(ady), std::fabs(bdy)), std::fabs(cdy));
  const double m = std::max(maxx, maxy);
  const double m2 = m * m;
  const int s = certify_bits(det, k::incircle_error_bound * m2 * m2);
  const bool ok = (m >= k::incircle_lower_guard) & (m <= k::incircle_upper_guard) & (s != 0);
  if (ok) [[likely]] return static_cast<Sign>(s);
  return cd::incircle_exact_stage(a, b, c, d);
}

inline Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                     const Point3& e) {
  const double aex = a.x - e.x, bex = b.x - e.x, cex = c.x - e.x, dex = d.x - e.x;
  const double aey = a.y - e.y, bey = b.y - e.y, cey = c.y - e.y, dey = d.y - e.y;
  const double aez = a.z - e.z, bez = b.z - e.z, cez = c.z - e.z, dez = d.z - e.z;
  const double ab = aex * bey - bex * aey;
  const double bc = bex * cey - cex * bey;
  const double cd = cex * dey - dex * cey;
  const double da = dex * aey - aex * dey;
  const double ac = aex * cey - cex * aey;
  const double bd = bex * dey - dex * bey;
  const double abc = aez * bc - bez * ac + cez * ab;
  const double bcd = bez * cd - cez * bd + dez * bc;
  const double cda = cez * da + dez * ac + aez * cd;
  const double dab = dez * ab + aez * bd + bez * da;
  const double alift = aex * aex + aey * aey + aez * aez;
  const double blift = bex * bex + bey * bey + bez * bez;
  const double clift = cex * cex + cey * cey + cez * cez;
  const double dlift = dex * dex + dey * dey + dez * dez;
  const double det = (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  const double mx = std::max(std::max(std::fabs(aex), std::fabs(bex)),
                             std::max(std::fabs(cex), std::fabs(dex)));
  const double my = std::max(std::max(std::fabs(aey), std::fabs(bey)),
                             std::max(std::fabs(cey), std::fabs(dey)));
  const double mz = std::max(std::max(std::fabs(aez), std::fabs(bez)),
                             std::max(std::fabs(cez), std::fabs(dez)));
  const double m = std::max(std::max(mx, my), mz);
  const double m2 = m * m;
  const int s = certify_bits(det, k::insphere_error_bound * m2 * m2 * m);
  const bool ok = (m >= k::insphere_lower_guard) & (m <= k::insphere_upper_guard) & (s != 0);
  if (ok) [[likely]] return static_cast<Sign>(s);
  return cd::insphere_exact_stage(a, b, c, d, e);
}

// Exact difference x = a - b (tail zero) with |x| zero or in [2^-480, 2^500].
inline bool exact_in_range(double a, double b, double& x) {
  double tail;
  cd::two_diff(a, b, x, tail);
  const double m = std::fabs(x);
  return (tail == 0.0) & ((m == 0.0) | ((m >= 0x1p-480) & (m <= 0x1p500)));
}

// Sign of p*q - r*s, exact for doubles whose non-zero magnitudes lie in [2^-480, 2^500].
inline int product_difference_sign(double p, double q, double r, double s) {
  double x1, y1, x2, y2;
  cd::two_product(p, q, x1, y1);
  cd::two_product(r, s, x2, y2);
  if (x1 != x2) return x1 > x2 ? 1 : -1;
  const double t = y1 - y2;
  return static_cast<int>(t > 0.0) - static_cast<int>(t < 0.0);
}

inline Sign orient2d_fastexact(const Point2& a, const Point2& b, const Point2& c) {
  const Sign f = orient2d_ozaki_filter(a, b, c);
  if (f != Sign::zero) [[likely]] return f;
  double acx, bcx, acy, bcy;
  const bool fast = exact_in_range(a.x, c.x, acx) & exact_in_range(b.x, c.x, bcx) &
                    exact_in_range(a.y, c.y, acy) & exact_in_range(b.y, c.y, bcy);
  if (fast) return static_cast<Sign>(product_difference_sign(acx, bcy, acy, bcx));
  return cd::orient2d_exact_stage(a, b, c);
}

}  // namespace certimesh_bench::prototype
