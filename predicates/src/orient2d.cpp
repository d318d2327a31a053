#include "certimesh/predicates/orient2d.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "certimesh/predicates/fp_environment.h"
#include "certimesh/predicates/non_finite_input.h"
#include "exact_range.h"
#include "expansion_determinants.h"
#include "integer_matrix.h"
#include "sos_2d.h"

namespace certimesh::predicates {
namespace detail {

FilteredSign orient2d_filter_out_of_line(const Point2& a, const Point2& b, const Point2& c) noexcept {
  return orient2d_filter(a, b, c);
}

namespace {

// The second stage: the exact determinant of the rounded differences plus the
// first-order correction from their tails, in double. The neglected remainder (the
// rounding of the correction and the second-order term) is at most E2 * maxx * maxy,
// which the computed bound orient2d_stage2_bound * maxx * maxy covers
// (proofs/gappa/orient2d_stage2.g, proofs/README.md section 9). Zero when it cannot
// decide. The evaluation order is the one the proof models.
Sign orient2d_second_stage(double acx, double acx_t, double bcx, double bcx_t, double acy,
                           double acy_t, double bcy, double bcy_t) {
  namespace k = filter_constants;
  const double maxx = std::max(std::fabs(acx), std::fabs(bcx));
  const double maxy = std::max(std::fabs(acy), std::fabs(bcy));
  const double lo = std::min(maxx, maxy), hi = std::max(maxx, maxy);
  if (!(lo >= k::orient2d_lower_guard && hi <= k::orient2d_upper_guard)) return Sign::zero;
  const std::array<double, 4> diffs{acx, bcx, acy, bcy};
  if (!expansion_safe(diffs, 2)) return Sign::zero;
  const double correction = (acx * bcy_t + bcy * acx_t) - (acy * bcx_t + bcx * acy_t);
  const auto estimate = minor2(acx, acy, bcx, bcy) + expansion_of(correction);
  return sign_beyond(estimate, k::orient2d_stage2_bound * maxx * maxy);
}

}  // namespace

Sign orient2d_exact_stage(const Point2& a, const Point2& b, const Point2& c) {
  const std::array<double, 6> raw{a.x, a.y, b.x, b.y, c.x, c.y};
  if (!all_finite(raw)) throw NonFiniteInput("orient2d");
  require_proven_fp_mode("orient2d");
  double acx, acx_tail, bcx, bcx_tail, acy, acy_tail, bcy, bcy_tail;
  two_diff(a.x, c.x, acx, acx_tail);
  two_diff(b.x, c.x, bcx, bcx_tail);
  two_diff(a.y, c.y, acy, acy_tail);
  two_diff(b.y, c.y, bcy, bcy_tail);
  const std::array<double, 4> diffs{acx, bcx, acy, bcy};
  // Exact differences (nearby points): the translated determinant is already exact.
  if (acx_tail == 0.0 && bcx_tail == 0.0 && acy_tail == 0.0 && bcy_tail == 0.0 &&
      expansion_safe(diffs, 2))
    return minor2(acx, acy, bcx, bcy).sign();
  const Sign second = orient2d_second_stage(acx, acx_tail, bcx, bcx_tail, acy, acy_tail, bcy, bcy_tail);
  if (second != Sign::zero) return second;
  if (expansion_safe(raw, 2))
    return minor3_with_ones(a.x, a.y, b.x, b.y, c.x, c.y).sign();
  return integer_determinant_sign(raw, 2, false);
}

}  // namespace detail

Sign orient2d_sos(const Point2& a, const Point2& b, const Point2& c) {
  const Sign s = orient2d(a, b, c);
  if (s != Sign::zero || a == b || b == c || a == c) return s;
  // The generic search (detail::perturbed_sign) would give the same answer with GMP minors.
  return detail::collinear_orient2d_sos(a, b, c);
}

}  // namespace certimesh::predicates
