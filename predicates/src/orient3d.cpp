#include "certimesh/predicates/orient3d.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "certimesh/predicates/non_finite_input.h"
#include "exact_range.h"
#include "expansion_determinants.h"
#include "integer_matrix.h"

namespace certimesh::predicates {
namespace detail {

FilteredSign orient3d_filter_out_of_line(const Point3& a, const Point3& b, const Point3& c,
                                         const Point3& d) noexcept {
  return orient3d_filter(a, b, c, d);
}

namespace {

// det[a-d; b-d; c-d] of the differences h (exact for the given doubles), expanded along
// the x column.
Expansion<24> translated_orient3d(const std::array<double, 9>& h) {
  const double adx = h[0], ady = h[1], adz = h[2], bdx = h[3], bdy = h[4], bdz = h[5],
               cdx = h[6], cdy = h[7], cdz = h[8];
  return (scale(minor2(bdy, bdz, cdy, cdz), adx) + scale(minor2(cdy, cdz, ady, adz), bdx)) +
         scale(minor2(ady, adz, bdy, bdz), cdx);
}

// The first-order change of det(h) when every entry h_i moves by its tail t_i: the sum of
// t_i times the cofactor of h_i, in double, in the order proofs/gappa/orient3d_stage2.g
// models.
double first_order_correction(const std::array<double, 9>& h, const std::array<double, 9>& t) {
  const double adx = h[0], ady = h[1], adz = h[2], bdx = h[3], bdy = h[4], bdz = h[5],
               cdx = h[6], cdy = h[7], cdz = h[8];
  const double cax = bdy * cdz - bdz * cdy, cay = bdz * cdx - bdx * cdz,
               caz = bdx * cdy - bdy * cdx;
  const double cbx = cdy * adz - cdz * ady, cby = cdz * adx - cdx * adz,
               cbz = cdx * ady - cdy * adx;
  const double ccx = ady * bdz - adz * bdy, ccy = adz * bdx - adx * bdz,
               ccz = adx * bdy - ady * bdx;
  return (((t[0] * cax + t[1] * cay) + t[2] * caz) + ((t[3] * cbx + t[4] * cby) + t[5] * cbz)) +
         ((t[6] * ccx + t[7] * ccy) + t[8] * ccz);
}

// The second stage: exact det(h) plus the first-order tail correction; the neglected
// remainder is at most E2 * maxx * maxy * maxz, which the computed bound
// orient3d_stage2_bound * maxx * maxy * maxz covers (proofs/gappa/orient3d_stage2.g,
// proofs/README.md section 9). Zero when it cannot decide.
Sign second_stage(const std::array<double, 9>& h, const std::array<double, 9>& t) {
  namespace k = filter_constants;
  const double maxx = std::max(std::max(std::fabs(h[0]), std::fabs(h[3])), std::fabs(h[6]));
  const double maxy = std::max(std::max(std::fabs(h[1]), std::fabs(h[4])), std::fabs(h[7]));
  const double maxz = std::max(std::max(std::fabs(h[2]), std::fabs(h[5])), std::fabs(h[8]));
  const double lo = std::min(std::min(maxx, maxy), maxz);
  const double hi = std::max(std::max(maxx, maxy), maxz);
  if (!(lo >= k::orient3d_lower_guard && hi <= k::orient3d_upper_guard)) return Sign::zero;
  if (!expansion_safe(h, 3)) return Sign::zero;
  const auto estimate = translated_orient3d(h) + expansion_of(first_order_correction(h, t));
  return sign_beyond(estimate, k::orient3d_stage2_bound * maxx * maxy * maxz);
}

}  // namespace

Sign orient3d_exact_stage(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const std::array<double, 12> raw{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  if (!all_finite(raw)) throw NonFiniteInput("orient3d");
  std::array<double, 9> diffs, tails;
  bool exact_diffs = true;
  for (std::size_t i = 0; i < 9; ++i) {
    two_diff(raw[i], raw[9 + i % 3], diffs[i], tails[i]);
    exact_diffs = exact_diffs && tails[i] == 0.0;
  }
  // Exact differences (nearby points): the translated determinant is already exact.
  if (exact_diffs && expansion_safe(diffs, 3)) return translated_orient3d(diffs).sign();
  const Sign second = second_stage(diffs, tails);
  if (second != Sign::zero) return second;
  if (expansion_safe(raw, 3))
    return det4_xyz1({a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}, {d.x, d.y, d.z}).sign();
  return integer_determinant_sign(raw, 3, false);
}

}  // namespace detail

Sign orient3d_sos(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const Sign s = orient3d(a, b, c, d);
  if (s != Sign::zero || a == b || a == c || a == d || b == c || b == d || c == d) return s;
  const std::array<double, 12> raw{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  return detail::perturbed_sign(raw, 3, false);
}

}  // namespace certimesh::predicates
