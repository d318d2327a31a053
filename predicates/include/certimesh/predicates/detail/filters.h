// The semi-static filters behind the monograph's d(): one formula per predicate, evaluated
// in double, and a proven bound (filter_constants.h, proofs/gappa/). Each returns
// `uncertain` unless its certified answer is the exact sign; NaN and infinities make every
// comparison false, so they come out `uncertain` too.
//
// The evaluation order written here is the one the Gappa scripts model: change one and
// the other together. Each body starts with CERTIMESH_FILTER_FP_STRICT, and a consumer whose
// flags could still rewrite them calls the kernel-compiled copies (fp_requirements.h).
#pragma once

#include <algorithm>
#include <cmath>

#include "certimesh/predicates/detail/fp_requirements.h"
#include "certimesh/predicates/filter_constants.h"
#include "certimesh/predicates/point.h"
#include "certimesh/predicates/sign.h"

namespace certimesh::predicates::detail {

// Branch-free on purpose: on random input the sign of det is a coin flip, and a branch on
// it mispredicts every other call (bench/RESULTS.md measured it as most of the filter's
// cost). Comparisons with NaN are false, so NaN gives `uncertain`.
inline FilteredSign certify(bool in_range, double det, double error_bound) noexcept {
  const int s = static_cast<int>(det > error_bound) - static_cast<int>(det < -error_bound);
  return static_cast<FilteredSign>(s * static_cast<int>(in_range));
}

// Ozaki, Buenger, Ogita, Oishi and Rump's filter (BIT 56, 2016): the bound is relative to
// |dl + dr|, which needs no per-axis maxima. When dl and dr have opposite signs there is no
// cancellation and any bound is sound; when they have the same sign |dl + dr| = |dl| + |dr|
// bounds the rounding errors (proofs/gappa/orient2d_ozaki.g, proofs/README.md section 10).
// The additive underflow bound covers the absolute error of products that underflow; an
// overflow leaves an infinity or NaN in det or in the bound, and every comparison false.
inline FilteredSign orient2d_filter(const Point2& a, const Point2& b, const Point2& c) noexcept {
  CERTIMESH_FILTER_FP_STRICT
  namespace k = filter_constants;
  const double dl = (a.x - c.x) * (b.y - c.y);
  const double dr = (a.y - c.y) * (b.x - c.x);
  const double det = dl - dr;
  const double bound = k::orient2d_theta * std::fabs(dl + dr) + k::orient2d_underflow_bound;
  return certify(true, det, bound);
}

inline FilteredSign orient3d_filter(const Point3& a, const Point3& b, const Point3& c,
                                    const Point3& d) noexcept {
  CERTIMESH_FILTER_FP_STRICT
  namespace k = filter_constants;
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
  const bool in_range = (lo >= k::orient3d_lower_guard) & (hi <= k::orient3d_upper_guard);
  return certify(in_range, det, k::orient3d_error_bound * maxx * maxy * maxz);
}

inline FilteredSign incircle_filter(const Point2& a, const Point2& b, const Point2& c,
                                    const Point2& d) noexcept {
  CERTIMESH_FILTER_FP_STRICT
  namespace k = filter_constants;
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
  const bool in_range = (m >= k::incircle_lower_guard) & (m <= k::incircle_upper_guard);
  const double m2 = m * m;
  return certify(in_range, det, k::incircle_error_bound * m2 * m2);
}

inline FilteredSign insphere_filter(const Point3& a, const Point3& b, const Point3& c,
                                    const Point3& d, const Point3& e) noexcept {
  CERTIMESH_FILTER_FP_STRICT
  namespace k = filter_constants;
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
  const bool in_range = (m >= k::insphere_lower_guard) & (m <= k::insphere_upper_guard);
  const double m2 = m * m;
  return certify(in_range, det, k::insphere_error_bound * m2 * m2 * m);
}

}  // namespace certimesh::predicates::detail
