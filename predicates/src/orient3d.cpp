#include "certimesh/predicates/orient3d.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "certimesh/predicates/fp_environment.h"
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
double orient3d_first_order_correction(const std::array<double, 9>& h, const std::array<double, 9>& t) {
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

// The compensated stage: det(h) in double-double along the x column (cofactors with their
// tails from compensated_minor, each term h * m split by two_product, the three terms added
// by two_sum), the tails and the first-order correction gathered in lo, and est =
// fl(y + lo). Its distance to the true determinant is at most
// E3 * maxx * maxy * maxz + 2^-53 |est|, which
// |est| > orient3d_compensated_bound * maxx * maxy * maxz covers
// (proofs/gappa/orient3d_compensated.g, proofs/README.md section 11). Branch-free and
// without expansions: on near-coplanar input it decides where the filter cannot. The
// evaluation order is the one the proof models. Zero when it cannot decide.
Sign orient3d_compensated_stage(const std::array<double, 9>& h, double correction, double maxx,
                       double maxy, double maxz) {
  namespace k = filter_constants;
  const Compensated ca = compensated_minor(h[4], h[8], h[5], h[7]);  // bdy * cdz - bdz * cdy
  const Compensated cb = compensated_minor(h[7], h[2], h[8], h[1]);  // cdy * adz - cdz * ady
  const Compensated cc = compensated_minor(h[1], h[5], h[2], h[4]);  // ady * bdz - adz * bdy
  double sa, sa_e, sb, sb_e, sc, sc_e;
  two_product(h[0], ca.value, sa, sa_e);
  two_product(h[3], cb.value, sb, sb_e);
  two_product(h[6], cc.value, sc, sc_e);
  const double lo_a = sa_e + h[0] * ca.lo;
  const double lo_b = sb_e + h[3] * cb.lo;
  const double lo_c = sc_e + h[6] * cc.lo;
  double x, x_e, y, y_e;
  two_sum(sa, sb, x, x_e);
  two_sum(x, sc, y, y_e);
  const double lo = ((x_e + y_e) + ((lo_a + lo_b) + lo_c)) + correction;
  const double est = y + lo;
  const double bound = k::orient3d_compensated_bound * maxx * maxy * maxz;
  return static_cast<Sign>(static_cast<int>(est > bound) - static_cast<int>(est < -bound));
}

// Per axis, the largest |h|; false unless they lie in the filter's guards and expansion
// arithmetic is exact for h (which also makes every two_product tail of the compensated
// stage exact: proofs/README.md section 11).
bool stage_maxima(const std::array<double, 9>& h, double& maxx, double& maxy, double& maxz) {
  namespace k = filter_constants;
  maxx = std::max(std::max(std::fabs(h[0]), std::fabs(h[3])), std::fabs(h[6]));
  maxy = std::max(std::max(std::fabs(h[1]), std::fabs(h[4])), std::fabs(h[7]));
  maxz = std::max(std::max(std::fabs(h[2]), std::fabs(h[5])), std::fabs(h[8]));
  const double lo = std::min(std::min(maxx, maxy), maxz);
  const double hi = std::max(std::max(maxx, maxy), maxz);
  return lo >= k::orient3d_lower_guard && hi <= k::orient3d_upper_guard && expansion_safe(h, 3);
}

// The compensated stage where its preconditions hold; zero otherwise or when undecided.
Sign orient3d_compensated_sign(const std::array<double, 9>& h, const std::array<double, 9>& t) {
  double maxx, maxy, maxz;
  if (!stage_maxima(h, maxx, maxy, maxz)) return Sign::zero;
  return orient3d_compensated_stage(h, orient3d_first_order_correction(h, t), maxx, maxy, maxz);
}

// The second stage: exact det(h) plus the first-order tail correction; the neglected
// remainder is at most E2 * maxx * maxy * maxz, which the computed bound
// orient3d_stage2_bound * maxx * maxy * maxz covers (proofs/gappa/orient3d_stage2.g,
// proofs/README.md section 9). Zero when it cannot decide.
Sign second_stage(const std::array<double, 9>& h, const std::array<double, 9>& t) {
  namespace k = filter_constants;
  double maxx, maxy, maxz;
  if (!stage_maxima(h, maxx, maxy, maxz)) return Sign::zero;
  const auto estimate = translated_orient3d(h) + expansion_of(orient3d_first_order_correction(h, t));
  return sign_beyond(estimate, k::orient3d_stage2_bound * maxx * maxy * maxz);
}

}  // namespace

Sign orient3d_exact_stage(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const std::array<double, 12> raw{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  if (!all_finite(raw)) throw NonFiniteInput("orient3d");
  require_proven_fp_mode("orient3d");
  std::array<double, 9> diffs, tails;
  bool exact_diffs = true;
  for (std::size_t i = 0; i < 9; ++i) {
    two_diff(raw[i], raw[9 + i % 3], diffs[i], tails[i]);
    exact_diffs = exact_diffs && tails[i] == 0.0;
  }
  // Near-degenerate input mostly ends here, without expansions.
  const Sign compensated = orient3d_compensated_sign(diffs, tails);
  if (compensated != Sign::zero) return compensated;
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
