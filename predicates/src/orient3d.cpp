#include "certimesh/predicates/orient3d.h"

#include <array>

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

// det[a-d; b-d; c-d] from exact differences, expanded along the x column.
Sign translated_orient3d(const std::array<double, 9>& t) {
  const double adx = t[0], ady = t[1], adz = t[2], bdx = t[3], bdy = t[4], bdz = t[5],
               cdx = t[6], cdy = t[7], cdz = t[8];
  return ((scale(minor2(bdy, bdz, cdy, cdz), adx) + scale(minor2(cdy, cdz, ady, adz), bdx)) +
          scale(minor2(ady, adz, bdy, bdz), cdx))
      .sign();
}

}  // namespace

Sign orient3d_exact_stage(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const std::array<double, 12> raw{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  if (!all_finite(raw)) throw NonFiniteInput("orient3d");
  std::array<double, 9> diffs;
  bool exact_diffs = true;
  for (int p = 0; p < 3; ++p)
    for (int k = 0; k < 3; ++k) {
      double tail;
      two_diff(raw[static_cast<std::size_t>(3 * p + k)], raw[static_cast<std::size_t>(9 + k)],
               diffs[static_cast<std::size_t>(3 * p + k)], tail);
      exact_diffs = exact_diffs && tail == 0.0;
    }
  if (exact_diffs && expansion_safe(diffs, 3)) return translated_orient3d(diffs);
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
