#include "certimesh/predicates/orient2d.h"

#include <array>

#include "certimesh/predicates/non_finite_input.h"
#include "exact_range.h"
#include "expansion_determinants.h"
#include "integer_matrix.h"

namespace certimesh::predicates {
namespace detail {

FilteredSign orient2d_filter_out_of_line(const Point2& a, const Point2& b, const Point2& c) noexcept {
  return orient2d_filter(a, b, c);
}

Sign orient2d_exact_stage(const Point2& a, const Point2& b, const Point2& c) {
  const std::array<double, 6> raw{a.x, a.y, b.x, b.y, c.x, c.y};
  if (!all_finite(raw)) throw NonFiniteInput("orient2d");
  // Translated form when the four differences are exact (nearby points, the usual case
  // for a near-degenerate triple).
  double acx, acx_tail, bcx, bcx_tail, acy, acy_tail, bcy, bcy_tail;
  two_diff(a.x, c.x, acx, acx_tail);
  two_diff(b.x, c.x, bcx, bcx_tail);
  two_diff(a.y, c.y, acy, acy_tail);
  two_diff(b.y, c.y, bcy, bcy_tail);
  const std::array<double, 4> diffs{acx, bcx, acy, bcy};
  if (acx_tail == 0.0 && bcx_tail == 0.0 && acy_tail == 0.0 && bcy_tail == 0.0 &&
      expansion_safe(diffs, 2))
    return minor2(acx, acy, bcx, bcy).sign();
  if (expansion_safe(raw, 2))
    return minor3_with_ones(a.x, a.y, b.x, b.y, c.x, c.y).sign();
  return integer_determinant_sign(raw, 2, false);
}

}  // namespace detail

Sign orient2d_sos(const Point2& a, const Point2& b, const Point2& c) {
  const Sign s = orient2d(a, b, c);
  if (s != Sign::zero || a == b || b == c || a == c) return s;
  const std::array<double, 6> raw{a.x, a.y, b.x, b.y, c.x, c.y};
  return detail::perturbed_sign(raw, 2, false);
}

}  // namespace certimesh::predicates
