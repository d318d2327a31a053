// When expansion arithmetic is exact for a polynomial of the input (private to the kernel).
//
// Expansion arithmetic (detail/expansion.h) is exact as long as no product overflows and
// no product's low-order part falls below the smallest subnormal. For a determinant that
// is a sum of at most 2^12 monomials, each a product of `degree` inputs:
//  - every component of every intermediate expansion is a multiple of q^degree, where q is
//    the smallest ulp of a non-zero input; the rounding errors of all products are exact
//    multiples of it, hence representable, while q^degree >= 2^-1074;
//  - every component is bounded by the sum of |monomials| <= 2^12 M^degree, M the largest
//    |input|, and Dekker's split multiplies by 2^27 + 1; 2^(12 + 27 + 1) M^degree < 2^1023
//    keeps everything finite.
#pragma once

#include <cmath>
#include <span>

namespace certimesh::predicates::detail {

inline bool expansion_safe(std::span<const double> values, int degree) noexcept {
  int max_exponent = -1100;  // of the largest |value|
  int min_ulp_exponent = 2000;
  for (double v : values) {
    if (v == 0.0) continue;
    const int e = std::ilogb(v);
    if (e > max_exponent) max_exponent = e;
    const int ulp_exponent = e - 52 < -1074 ? -1074 : e - 52;
    if (ulp_exponent < min_ulp_exponent) min_ulp_exponent = ulp_exponent;
  }
  if (max_exponent == -1100) return true;  // all zero
  const bool no_overflow = degree * (max_exponent + 1) <= 1023 - 40;
  const bool no_underflow = min_ulp_exponent >= 0 || degree * min_ulp_exponent >= -1074;
  return no_overflow && no_underflow;
}

inline bool all_finite(std::span<const double> values) noexcept {
  for (double v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace certimesh::predicates::detail
