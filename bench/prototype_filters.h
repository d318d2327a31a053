// Bench-only prototypes: NOT certimesh's predicates, and not part of certimesh's
// proofs. Every prototype falls back to certimesh's own exact stage, and the start-up
// cross-check (bench_predicates.cpp) compares each one with the exact stage on every
// data set.
//
// (The branch-free BM_<p>_prototype of all four filters, measured in the first runs of
// RESULTS.md, became certimesh's own filter in 77660d1 and was then removed from here.)
//
// BM_orient2d_prototype_ozaki: an Ozaki-style filter (Ozaki, Buenger, Ogita, Oishi,
// Rump, BIT 56, 2016; the filter GEOS adopted), also branch-free:
// dl = acx*bcy, dr = acy*bcx, det = dl - dr, certain when |det| > theta*|dl + dr| +
// DBL_MIN. No maxima, no guards: overflow gives inf/NaN and every comparison false
// (uncertain); the DBL_MIN term is a deliberately generous allowance for underflow in
// the two products. theta is the JTS/GEOS literal (3u rounded up). Since ea3e953 the
// kernel's own orient2d filter has this shape with its proven constants (theta = 3u +
// 20u^2, 2^-1073; proofs/README.md section 10): this prototype stays as a reference.
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
