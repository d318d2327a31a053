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

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <span>

namespace certimesh::predicates::detail {

/// The biased binary exponent field of a finite double (0 for zero and subnormals).
inline int biased_exponent(double v) noexcept {
  return static_cast<int>((std::bit_cast<std::uint64_t>(v) >> 52) & 0x7ff);
}

inline bool expansion_safe(std::span<const double> values, int degree) noexcept {
  // Biased exponents: a normal v has 2^(b-1023) <= |v| < 2^(b-1022) and ulp 2^(b-1075);
  // a subnormal (b == 0) has ulp 2^-1074.
  int max_biased = -1;
  int min_biased = 4096;
  for (double v : values) {
    if (v == 0.0) continue;
    const int b = biased_exponent(v);
    max_biased = std::max(max_biased, b);
    min_biased = std::min(min_biased, b);
  }
  if (max_biased < 0) return true;  // all zero
  const int max_exponent = max_biased == 0 ? -1023 : max_biased - 1023;
  const int min_ulp_exponent = min_biased == 0 ? -1074 : min_biased - 1075;
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
