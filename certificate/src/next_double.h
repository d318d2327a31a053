// Internal: the neighbouring double, from the bits. std::nextafter is a library call with
// branches for every case; the rounding-box tests take it several times per vertex.
#pragma once

#include <bit>
#include <cmath>
#include <cstdint>

namespace certimesh::certificate::detail {

/// std::nextafter(x, +inf) for x not NaN: the least double above x (+inf stays +inf, -inf gives
/// -DBL_MAX, both zeros give the smallest subnormal).
inline double next_up(double x) {
  if (x == 0) return std::bit_cast<double>(std::uint64_t{1});
  if (x == INFINITY) return x;
  const auto bits = std::bit_cast<std::uint64_t>(x);
  return std::bit_cast<double>(x > 0 ? bits + 1 : bits - 1);  // the magnitude's bits are monotone
}
/// std::nextafter(x, -inf) for x not NaN.
inline double next_down(double x) { return -next_up(-x); }
/// next_up (direction > 0) or next_down (direction < 0).
inline double next_double(double x, int direction) { return direction > 0 ? next_up(x) : next_down(x); }

}  // namespace certimesh::certificate::detail
