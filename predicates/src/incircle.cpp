#include "certimesh/predicates/incircle.h"

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

FilteredSign incircle_filter_out_of_line(const Point2& a, const Point2& b, const Point2& c,
                                         const Point2& d) noexcept {
  return incircle_filter(a, b, c, d);
}

namespace {

// The translated lifted determinant from exact differences (t = adx, ady, bdx, ...).
Sign translated_incircle(const std::array<double, 6>& t) {
  const double adx = t[0], ady = t[1], bdx = t[2], bdy = t[3], cdx = t[4], cdy = t[5];
  return ((lift2(adx, ady) * minor2(bdx, bdy, cdx, cdy) +
           lift2(bdx, bdy) * minor2(cdx, cdy, adx, ady)) +
          lift2(cdx, cdy) * minor2(adx, ady, bdx, bdy))
      .sign();
}

// det[x y |p|^2 1] of the raw points, expanded along the lifted column.
Sign raw_incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const auto m_bcd = minor3_with_ones(b.x, b.y, c.x, c.y, d.x, d.y);
  const auto m_acd = minor3_with_ones(a.x, a.y, c.x, c.y, d.x, d.y);
  const auto m_abd = minor3_with_ones(a.x, a.y, b.x, b.y, d.x, d.y);
  const auto m_abc = minor3_with_ones(a.x, a.y, b.x, b.y, c.x, c.y);
  return ((lift2(a.x, a.y) * m_bcd - lift2(b.x, b.y) * m_acd) +
          (lift2(c.x, c.y) * m_abd - lift2(d.x, d.y) * m_abc))
      .sign();
}

// The lifted determinant of h = (adx, ady, bdx, bdy, cdx, cdy) is the sum over (p, q, r)
// cyclic in (a, b, c) of plift * pm, plift = pdx^2 + pdy^2, pm = qdx * rdy - rdx * qdy.
// Indices of p's differences in h: 2 * p and 2 * p + 1.
struct Cycle {
  std::size_t p, q, r;
};
constexpr std::array<Cycle, 3> cycles{{{0, 1, 2}, {1, 2, 0}, {2, 0, 1}}};

// Lifts and minors carry the error-free tails of their computation (detail/expansion.h).
using Split = Compensated;

// plift = fl(fl(pdx^2) + fl(pdy^2)) (two_product, two_sum), lo = fl(se + fl(xxe + yye)).
Split lift_of(double x, double y) {
  double xx, xxe, yy, yye, l, le;
  two_product(x, x, xx, xxe);
  two_product(y, y, yy, yye);
  two_sum(xx, yy, l, le);
  return {l, le + (xxe + yye)};
}

// The first-order change of det(h) when every h_i moves by its tail t_i, in double, per
// cycle plift * ((qdx * rdy_t + rdy * qdx_t) - (qdy * rdx_t + rdx * qdy_t))
// + 2 (pdx * pdx_t + pdy * pdy_t) * pm, in the order proofs/gappa/incircle_compensated.g
// models.
double incircle_first_order_correction(const std::array<double, 6>& h, const std::array<double, 6>& t,
                              const std::array<Split, 3>& lift,
                              const std::array<Split, 3>& minor) {
  std::array<double, 3> corr;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t p = 2 * cycles[i].p, q = 2 * cycles[i].q, r = 2 * cycles[i].r;
    const double cm = (h[q] * t[r + 1] + h[r + 1] * t[q]) - (h[q + 1] * t[r] + h[r] * t[q + 1]);
    const double e = h[p] * t[p] + h[p + 1] * t[p + 1];
    corr[i] = lift[i].value * cm + (e + e) * minor[i].value;
  }
  return (corr[0] + corr[1]) + corr[2];
}

// The compensated stage: det(h) in double-double (lifts and minors with their tails, each
// term plift * pm split by two_product, the three terms added by two_sum), the tails, the
// cross terms plift * pm_lo + plift_lo * pm and the first-order correction gathered in
// lo, and est = fl(y + lo). Its distance to the true determinant is at most E * m^4 +
// 2^-53 |est|, which |est| > incircle_compensated_bound * m2 * m2 covers
// (proofs/gappa/incircle_compensated.g, proofs/README.md section 12). Branch-free and
// without expansions: on near-cocircular input it decides where the filter cannot. The
// evaluation order is the one the proof models. Zero when it cannot decide.
Sign incircle_compensated_stage(const std::array<double, 6>& h, const std::array<double, 6>& t,
                       double m) {
  namespace k = filter_constants;
  std::array<Split, 3> lift, minor;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t p = 2 * cycles[i].p, q = 2 * cycles[i].q, r = 2 * cycles[i].r;
    lift[i] = lift_of(h[p], h[p + 1]);
    minor[i] = compensated_minor(h[q], h[r + 1], h[r], h[q + 1]);  // pm = qdx rdy - rdx qdy
  }
  const double correction = incircle_first_order_correction(h, t, lift, minor);
  std::array<double, 3> s, lo_term;
  for (std::size_t i = 0; i < 3; ++i) {
    double se;
    two_product(lift[i].value, minor[i].value, s[i], se);
    lo_term[i] = se + (lift[i].value * minor[i].lo + lift[i].lo * minor[i].value);
  }
  double x, x_e, y, y_e;
  two_sum(s[0], s[1], x, x_e);
  two_sum(x, s[2], y, y_e);
  const double lo = ((x_e + y_e) + ((lo_term[0] + lo_term[1]) + lo_term[2])) + correction;
  const double est = y + lo;
  const double m2 = m * m;
  const double bound = k::incircle_compensated_bound * m2 * m2;
  return static_cast<Sign>(static_cast<int>(est > bound) - static_cast<int>(est < -bound));
}

// The compensated stage where its preconditions hold (m, the largest |h|, inside the
// incircle filter's guards; expansion arithmetic exact for h, which also makes every
// two_product tail of the stage exact: proofs/README.md section 12); zero otherwise or
// when undecided.
Sign incircle_compensated_sign(const std::array<double, 6>& h, const std::array<double, 6>& t) {
  namespace k = filter_constants;
  double m = 0.0;
  for (double v : h) m = std::max(m, std::fabs(v));
  if (!(m >= k::incircle_lower_guard && m <= k::incircle_upper_guard)) return Sign::zero;
  if (!expansion_safe(h, 4)) return Sign::zero;
  return incircle_compensated_stage(h, t, m);
}

// The small-integer stage (proofs/README.md section 13). When every coordinate is an
// integer of magnitude at most 2^51 and every difference to d at most 2^12, the lifted
// determinant evaluated in double is exact: with |h| <= M = 2^12 every lift and every minor
// is an integer of magnitude at most 2 M^2, every product plift * pm at most 4 M^4 and the
// partial sums at most 12 M^4 < 2^52, so every intermediate is an integer below 2^53, each
// operation's exact result is representable and round-to-nearest returns it (a fused
// multiply-add, rounding once, returns it too). The differences themselves are exact: two
// integers of magnitude <= 2^51 differ by an integer of magnitude <= 2^52. The integer test
// x == (x + 1.5 * 2^52) - 1.5 * 2^52 holds exactly for the integers among the x of
// magnitude <= 2^51: the sum lies in [2^52, 2^53], where the doubles are integers, so it is
// x + 1.5 * 2^52 exactly when x is an integer and an integer otherwise, and the
// subtraction is exact (Sterbenz), giving x back only for an integer. The grid's exactly
// cocircular tuples end here instead of in the compensated and expansion stages. Sets
// *decided to false when the preconditions fail.
Sign small_integer_incircle(const std::array<double, 8>& raw, bool* decided) {
  constexpr double magic = 0x1.8p52, coordinate_limit = 0x1p51, difference_limit = 0x1p12;
  *decided = false;
  // Early exits: on input that is not small integers (the common case of this stage's
  // callers) the first coordinate usually ends it.
  for (double v : raw)
    if (!(std::fabs(v) <= coordinate_limit) || (v + magic) - magic != v) return Sign::zero;
  std::array<double, 6> h;
  for (std::size_t i = 0; i < 6; ++i) {
    h[i] = raw[i] - raw[6 + i % 2];
    if (!(std::fabs(h[i]) <= difference_limit)) return Sign::zero;
  }
  *decided = true;
  double det = 0.0;
  for (const Cycle& cyc : cycles) {
    const std::size_t p = 2 * cyc.p, q = 2 * cyc.q, r = 2 * cyc.r;
    const double lift = h[p] * h[p] + h[p + 1] * h[p + 1];
    const double minor = h[q] * h[r + 1] - h[r] * h[q + 1];
    det += lift * minor;
  }
  return static_cast<Sign>(static_cast<int>(det > 0.0) - static_cast<int>(det < 0.0));
}

}  // namespace

Sign incircle_exact_stage(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const std::array<double, 8> raw{a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y};
  if (!all_finite(raw)) throw NonFiniteInput("incircle");
  require_proven_fp_mode("incircle");
  bool small_integers = false;
  const Sign small = small_integer_incircle(raw, &small_integers);
  if (small_integers) return small;
  std::array<double, 6> diffs, tails;
  bool exact_diffs = true;
  for (std::size_t i = 0; i < 6; ++i) {
    two_diff(raw[i], raw[6 + i % 2], diffs[i], tails[i]);
    exact_diffs = exact_diffs && tails[i] == 0.0;
  }
  // Near-degenerate input mostly ends here, without expansions.
  const Sign compensated = incircle_compensated_sign(diffs, tails);
  if (compensated != Sign::zero) return compensated;
  if (exact_diffs && expansion_safe(diffs, 4)) return translated_incircle(diffs);
  if (expansion_safe(raw, 4)) return raw_incircle(a, b, c, d);
  return integer_determinant_sign(raw, 2, true);
}

}  // namespace detail

Sign incircle_sos(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const Sign s = incircle(a, b, c, d);
  if (s != Sign::zero || a == b || a == c || a == d || b == c || b == d || c == d) return s;
  // The generic search (detail::perturbed_sign) would give the same answer with GMP minors.
  return detail::cocircular_incircle_sos(a, b, c, d);
}

}  // namespace certimesh::predicates
