#include "certimesh/predicates/incircle.h"

#include <array>

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

}  // namespace

Sign incircle_exact_stage(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const std::array<double, 8> raw{a.x, a.y, b.x, b.y, c.x, c.y, d.x, d.y};
  if (!all_finite(raw)) throw NonFiniteInput("incircle");
  std::array<double, 6> diffs;
  bool exact_diffs = true;
  for (std::size_t i = 0; i < 6; ++i) {
    double tail;
    two_diff(raw[i], raw[6 + i % 2], diffs[i], tail);
    exact_diffs = exact_diffs && tail == 0.0;
  }
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
