#include "certimesh/predicates/insphere.h"

#include <array>

#include "certimesh/predicates/fp_environment.h"
#include "certimesh/predicates/non_finite_input.h"
#include "exact_range.h"
#include "expansion_determinants.h"
#include "integer_matrix.h"

namespace certimesh::predicates {
namespace detail {

FilteredSign insphere_filter_out_of_line(const Point3& a, const Point3& b, const Point3& c,
                                         const Point3& d, const Point3& e) noexcept {
  return insphere_filter(a, b, c, d, e);
}

namespace {

// The translated lifted determinant from exact differences, as in the filter.
Sign translated_insphere(const std::array<double, 12>& t) {
  const double aex = t[0], aey = t[1], aez = t[2], bex = t[3], bey = t[4], bez = t[5];
  const double cex = t[6], cey = t[7], cez = t[8], dex = t[9], dey = t[10], dez = t[11];
  const auto ab = minor2(aex, aey, bex, bey);
  const auto bc = minor2(bex, bey, cex, cey);
  const auto cd = minor2(cex, cey, dex, dey);
  const auto da = minor2(dex, dey, aex, aey);
  const auto ac = minor2(aex, aey, cex, cey);
  const auto bd = minor2(bex, bey, dex, dey);
  const auto abc = (scale(bc, aez) - scale(ac, bez)) + scale(ab, cez);
  const auto bcd = (scale(cd, bez) - scale(bd, cez)) + scale(bc, dez);
  const auto cda = (scale(da, cez) + scale(ac, dez)) + scale(cd, aez);
  const auto dab = (scale(ab, dez) + scale(bd, aez)) + scale(da, bez);
  return ((lift3(dex, dey, dez) * abc - lift3(cex, cey, cez) * dab) +
          (lift3(bex, bey, bez) * cda - lift3(aex, aey, aez) * bcd))
      .sign();
}

// det[x y z |p|^2 1] of the raw points, expanded along the lifted column.
Sign raw_insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                  const Point3& e) {
  const Raw3 ra{a.x, a.y, a.z}, rb{b.x, b.y, b.z}, rc{c.x, c.y, c.z}, rd{d.x, d.y, d.z},
      re{e.x, e.y, e.z};
  const auto la = lift3(a.x, a.y, a.z), lb = lift3(b.x, b.y, b.z), lc = lift3(c.x, c.y, c.z),
             ld = lift3(d.x, d.y, d.z), le = lift3(e.x, e.y, e.z);
  const auto sum = ((lb * det4_xyz1(ra, rc, rd, re) - la * det4_xyz1(rb, rc, rd, re)) +
                    (ld * det4_xyz1(ra, rb, rc, re) - lc * det4_xyz1(ra, rb, rd, re))) -
                   le * det4_xyz1(ra, rb, rc, rd);
  return sum.sign();
}

}  // namespace

Sign insphere_exact_stage(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                          const Point3& e) {
  const std::array<double, 15> raw{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y,
                                   c.z, d.x, d.y, d.z, e.x, e.y, e.z};
  if (!all_finite(raw)) throw NonFiniteInput("insphere");
  require_proven_fp_mode("insphere");
  std::array<double, 12> diffs;
  bool exact_diffs = true;
  for (std::size_t i = 0; i < 12; ++i) {
    double tail;
    two_diff(raw[i], raw[12 + i % 3], diffs[i], tail);
    exact_diffs = exact_diffs && tail == 0.0;
  }
  if (exact_diffs && expansion_safe(diffs, 5)) return translated_insphere(diffs);
  if (expansion_safe(raw, 5)) return raw_insphere(a, b, c, d, e);
  return integer_determinant_sign(raw, 3, true);
}

}  // namespace detail

Sign insphere_sos(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                  const Point3& e) {
  const Sign s = insphere(a, b, c, d, e);
  if (s != Sign::zero) return s;
  const std::array<Point3, 5> p{a, b, c, d, e};
  for (std::size_t i = 0; i < 5; ++i)
    for (std::size_t j = i + 1; j < 5; ++j)
      if (p[i] == p[j]) return Sign::zero;
  const std::array<double, 15> raw{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y,
                                   c.z, d.x, d.y, d.z, e.x, e.y, e.z};
  return detail::perturbed_sign(raw, 3, true);
}

}  // namespace certimesh::predicates
