// Floating-point expansion arithmetic: exact sums and products of doubles represented as
// unevaluated sums of non-overlapping doubles (Priest; Shewchuk, DCG 18(3), 1997).
//
// This is the exact stage's number type. It is exact only when no intermediate result
// overflows or underflows; `exact_range.h` decides when that is guaranteed, and the
// GMP stage takes every other input. Requires round-to-nearest-even and no FMA
// contraction (see cmake/CertimeshFloatingPoint.cmake): the error-free transformations
// below are wrong under contraction.
//
// Capacities are compile-time: an Expansion<N> holds at most N components, and every
// operation's result type is sized for its worst case, so nothing allocates.
#pragma once

#include <array>
#include <cstddef>

#include "certimesh/predicates/sign.h"

namespace certimesh::predicates::detail {

// ---- error-free transformations -------------------------------------------------------

/// a + b = x + y exactly, x = fl(a + b).
inline void two_sum(double a, double b, double& x, double& y) noexcept {
  x = a + b;
  const double b_virtual = x - a;
  const double a_virtual = x - b_virtual;
  y = (a - a_virtual) + (b - b_virtual);
}

/// a - b = x + y exactly, x = fl(a - b).
inline void two_diff(double a, double b, double& x, double& y) noexcept {
  x = a - b;
  const double b_virtual = a - x;
  const double a_virtual = x + b_virtual;
  y = (a - a_virtual) + (b_virtual - b);
}

/// Dekker's split: a = hi + lo, each with at most 26 significant bits.
inline void split(double a, double& hi, double& lo) noexcept {
  constexpr double splitter = 134217729.0;  // 2^27 + 1
  const double c = splitter * a;
  const double a_big = c - a;
  hi = c - a_big;
  lo = a - hi;
}

/// a * b = x + y exactly, x = fl(a * b) (Dekker/Veltkamp, no FMA needed).
inline void two_product(double a, double b, double& x, double& y) noexcept {
  x = a * b;
  double ahi, alo, bhi, blo;
  split(a, ahi, alo);
  split(b, bhi, blo);
  const double err1 = x - ahi * bhi;
  const double err2 = err1 - alo * bhi;
  const double err3 = err2 - ahi * blo;
  y = alo * blo - err3;
}

// ---- double-double terms of the compensated stages -----------------------------------

/// A rounded value with the error-free tails of its computation gathered in lo: value + lo
/// is within a rounding of lo of the exact result.
struct Compensated {
  double value, lo;
};

/// The 2x2 minor a*d - b*c: value = fl(fl(a*d) - fl(b*c)), lo = fl(me + fl(pe - qe)) from
/// the error-free tails of the two products (pe, qe) and of the difference (me), in the
/// order the compensated stages' Gappa scripts model (orient3d's cofactors, incircle's
/// minors; proofs/README.md sections 11-12).
inline Compensated compensated_minor(double a, double d, double b, double c) noexcept {
  double p, pe, q, qe, m, me;
  two_product(a, d, p, pe);
  two_product(b, c, q, qe);
  two_diff(p, q, m, me);
  return {m, me + (pe - qe)};
}

// ---- expansions -----------------------------------------------------------------------

/// An exact value sum(c[0..n)), components non-overlapping and increasing in magnitude.
/// The operations below eliminate zero components from their results.
template <std::size_t N>
struct Expansion {
  static constexpr std::size_t capacity = N;
  std::array<double, N> c;
  std::size_t n = 0;

  /// The sign of the value is the sign of its largest non-zero component. (Results of
  /// the sums and scalings have no zero components; minor2 in the kernel keeps them.)
  Sign sign() const noexcept {
    for (std::size_t i = n; i > 0; --i)
      if (c[i - 1] != 0.0) return c[i - 1] > 0 ? Sign::positive : Sign::negative;
    return Sign::zero;
  }
  /// Approximation of the value (the largest component carries it to within an ulp).
  double estimate() const noexcept {
    double s = 0;
    for (std::size_t i = 0; i < n; ++i) s += c[i];
    return s;
  }
};

inline Expansion<1> expansion_of(double a) noexcept {
  Expansion<1> e;
  e.c[0] = a;
  e.n = a != 0.0 ? 1 : 0;
  return e;
}

/// The exact product a * b.
inline Expansion<2> exact_product(double a, double b) noexcept {
  Expansion<2> e;
  double x, y;
  two_product(a, b, x, y);
  if (y != 0.0) e.c[e.n++] = y;
  if (x != 0.0) e.c[e.n++] = x;
  return e;
}

/// The exact difference a - b.
inline Expansion<2> exact_difference(double a, double b) noexcept {
  Expansion<2> e;
  double x, y;
  two_diff(a, b, x, y);
  if (y != 0.0) e.c[e.n++] = y;
  if (x != 0.0) e.c[e.n++] = x;
  return e;
}

template <std::size_t N>
Expansion<N> negate(Expansion<N> e) noexcept {
  for (std::size_t i = 0; i < e.n; ++i) e.c[i] = -e.c[i];
  return e;
}

/// e + f (Shewchuk's fast_expansion_sum_zeroelim; needs round-to-nearest-even).
template <std::size_t N, std::size_t M>
Expansion<N + M> operator+(const Expansion<N>& e, const Expansion<M>& f) noexcept {
  Expansion<N + M> h;
  if (e.n == 0) {
    for (std::size_t i = 0; i < f.n; ++i) h.c[i] = f.c[i];
    h.n = f.n;
    return h;
  }
  if (f.n == 0) {
    for (std::size_t i = 0; i < e.n; ++i) h.c[i] = e.c[i];
    h.n = e.n;
    return h;
  }
  std::size_t ei = 0, fi = 0;
  double enow = e.c[0], fnow = f.c[0];
  double q, hh;
  auto take_smaller = [&]() {
    double v;
    if ((fnow > enow) == (fnow > -enow)) {
      v = enow;
      ++ei;
      enow = ei < e.n ? e.c[ei] : 0.0;
    } else {
      v = fnow;
      ++fi;
      fnow = fi < f.n ? f.c[fi] : 0.0;
    }
    return v;
  };
  q = take_smaller();
  std::size_t hn = 0;
  if (ei < e.n && fi < f.n) {
    const double next = take_smaller();
    // fast_two_sum(next, q): |next| >= |q| holds by the merge order.
    const double x = next + q;
    hh = q - (x - next);
    q = x;
    if (hh != 0.0) h.c[hn++] = hh;
    while (ei < e.n && fi < f.n) {
      const double v = take_smaller();
      double x2;
      two_sum(q, v, x2, hh);
      q = x2;
      if (hh != 0.0) h.c[hn++] = hh;
    }
  }
  while (ei < e.n) {
    double x2;
    two_sum(q, enow, x2, hh);
    q = x2;
    ++ei;
    enow = ei < e.n ? e.c[ei] : 0.0;
    if (hh != 0.0) h.c[hn++] = hh;
  }
  while (fi < f.n) {
    double x2;
    two_sum(q, fnow, x2, hh);
    q = x2;
    ++fi;
    fnow = fi < f.n ? f.c[fi] : 0.0;
    if (hh != 0.0) h.c[hn++] = hh;
  }
  if (q != 0.0 || hn == 0) h.c[hn++] = q;
  if (hn == 1 && h.c[0] == 0.0) hn = 0;
  h.n = hn;
  return h;
}

template <std::size_t N, std::size_t M>
Expansion<N + M> operator-(const Expansion<N>& e, const Expansion<M>& f) noexcept {
  return e + negate(f);
}

/// e * b (Shewchuk's scale_expansion_zeroelim).
template <std::size_t N>
Expansion<2 * N> scale(const Expansion<N>& e, double b) noexcept {
  Expansion<2 * N> h;
  if (e.n == 0 || b == 0.0) return h;
  double bhi, blo;
  split(b, bhi, blo);
  std::size_t hn = 0;
  auto product = [&](double a, double& x, double& y) {
    x = a * b;
    double ahi, alo;
    split(a, ahi, alo);
    const double err1 = x - ahi * bhi;
    const double err2 = err1 - alo * bhi;
    const double err3 = err2 - ahi * blo;
    y = alo * blo - err3;
  };
  double q, hh;
  product(e.c[0], q, hh);
  if (hh != 0.0) h.c[hn++] = hh;
  for (std::size_t i = 1; i < e.n; ++i) {
    double p1, p0, sum;
    product(e.c[i], p1, p0);
    two_sum(q, p0, sum, hh);
    if (hh != 0.0) h.c[hn++] = hh;
    // fast_two_sum(p1, sum)
    q = p1 + sum;
    hh = sum - (q - p1);
    if (hh != 0.0) h.c[hn++] = hh;
  }
  if (q != 0.0 || hn == 0) h.c[hn++] = q;
  if (hn == 1 && h.c[0] == 0.0) hn = 0;
  h.n = hn;
  return h;
}

/// e * f, as the sum over f's components of e scaled by each.
template <std::size_t N, std::size_t M>
Expansion<2 * N * M> operator*(const Expansion<N>& e, const Expansion<M>& f) noexcept {
  Expansion<2 * N * M> acc;
  for (std::size_t j = 0; j < f.n; ++j) {
    const Expansion<2 * N> term = scale(e, f.c[j]);
    const Expansion<2 * N * M + 2 * N> next = acc + term;
    // The running sum never exceeds the final capacity: after j+1 terms it has at
    // most 2*N*(j+1) components.
    for (std::size_t i = 0; i < next.n; ++i) acc.c[i] = next.c[i];
    acc.n = next.n;
  }
  return acc;
}

}  // namespace certimesh::predicates::detail
