// Internal: the exact sum of many products of two doubles, without a rational per term. Each
// double is m 2^e with an integer m < 2^53; the sum is kept as one integer in units of the
// smallest product exponent seen so far (shifted up when a smaller one arrives), so adding a
// term costs a 106-bit product and one shifted addition: linear in the terms, with no gcd.
#pragma once

#include <gmpxx.h>

#include <bit>
#include <climits>
#include <cmath>
#include <cstdint>
#include <utility>

namespace certimesh::certificate::detail {

/// m 2^e, exactly: what sums and products of doubles are.
struct Dyadic {
  mpz_class m = 0;
  long e = 0;
};
inline Dyadic operator*(const Dyadic& a, const Dyadic& b) { return {a.m * b.m, a.e + b.e}; }
inline Dyadic operator+(Dyadic a, Dyadic b) {
  if (a.m == 0) return b;
  if (b.m == 0) return a;
  if (a.e > b.e) std::swap(a, b);
  b.m <<= static_cast<mp_bitcnt_t>(b.e - a.e);
  return {a.m + b.m, a.e};
}
inline Dyadic abs(Dyadic a) {
  mpz_abs(a.m.get_mpz_t(), a.m.get_mpz_t());
  return a;
}
/// The nearest double to |a| / sqrt(b), b > 0, with no overflow or underflow on the way (a
/// statistic: mantissas to 53 bits, the exponents apart).
inline double ratio_to_root(const Dyadic& a, const Dyadic& b) {
  if (a.m == 0) return 0.0;
  long ea = 0, eb = 0;
  const double ma = std::fabs(mpz_get_d_2exp(&ea, a.m.get_mpz_t()));  // |a| = ma 2^(ea + a.e)
  double mb = mpz_get_d_2exp(&eb, b.m.get_mpz_t());
  long exponent_b = eb + b.e;
  if (exponent_b % 2 != 0) mb *= 2, exponent_b -= 1;
  return std::ldexp(ma / std::sqrt(mb), static_cast<int>(ea + a.e - exponent_b / 2));
}

/// Also sums integers times powers of two (m 2^e), in the same units.
class ExactProductSum {
 public:
  /// Adds sign * a * b exactly (a, b finite).
  void add(double a, double b, int sign = 1) {
    if (a == 0 || b == 0 || sign == 0) return;
    long ea = 0, eb = 0;
    const std::int64_t ma = decompose(a, ea), mb = decompose(b, eb);  // a = ma 2^ea, |ma| < 2^53
    term_ = static_cast<long>(ma);
    term_ *= static_cast<long>(mb);
    if (sign < 0) term_ = -term_;
    add_term(ea + eb);
  }
  /// Adds m * 2^exponent exactly.
  void add(const mpz_class& m, long exponent) {
    if (m == 0) return;
    term_ = m;
    add_term(exponent);
  }
  /// The sum as m 2^e.
  Dyadic dyadic() const { return {sum_, unit_ == LONG_MAX ? 0 : unit_}; }
  /// The sign of the sum: -1, 0 or +1.
  int sign() const { return sgn(sum_); }
  /// The sum, exactly.
  mpq_class value() const {
    mpq_class q(sum_);
    if (unit_ == LONG_MAX || unit_ == 0) return q;
    if (unit_ > 0) mpz_mul_2exp(q.get_num_mpz_t(), q.get_num_mpz_t(), static_cast<mp_bitcnt_t>(unit_));
    else mpz_mul_2exp(q.get_den_mpz_t(), q.get_den_mpz_t(), static_cast<mp_bitcnt_t>(-unit_));
    q.canonicalize();
    return q;
  }

 private:
  // A finite double as m 2^e with an integer |m| < 2^53, from its bits (IEEE binary64).
  static std::int64_t decompose(double a, long& e) {
    const auto bits = std::bit_cast<std::uint64_t>(a);
    const auto biased = static_cast<long>((bits >> 52) & 0x7ff);
    std::int64_t m = static_cast<std::int64_t>(bits & ((std::uint64_t{1} << 52) - 1));
    if (biased == 0) e = -1074;  // subnormal (or zero)
    else m |= std::int64_t{1} << 52, e = biased - 1075;
    return bits >> 63 ? -m : m;
  }
  void add_term(long exponent) {
    if (exponent < unit_) {
      if (unit_ != LONG_MAX) sum_ <<= static_cast<mp_bitcnt_t>(unit_ - exponent);
      unit_ = exponent;
    }
    if (exponent > unit_) term_ <<= static_cast<mp_bitcnt_t>(exponent - unit_);
    sum_ += term_;
  }

  mpz_class sum_ = 0, term_ = 0;
  long unit_ = LONG_MAX;  // the sum is sum_ * 2^unit_
};

/// (b - a) x (p - a), exactly (2D points: x, y).
inline Dyadic cross_from(const double* a, const double* b, const double* p) {
  ExactProductSum s;
  s.add(b[0], p[1]), s.add(b[0], a[1], -1), s.add(a[0], p[1], -1);
  s.add(b[1], p[0], -1), s.add(b[1], a[0]), s.add(a[1], p[0]);
  return s.dyadic();
}
/// (q - p) . (b - a), exactly (2D).
inline Dyadic dot_of_differences(const double* p, const double* q, const double* a, const double* b) {
  ExactProductSum s;
  for (int k = 0; k < 2; ++k) s.add(q[k], b[k]), s.add(q[k], a[k], -1), s.add(p[k], b[k], -1), s.add(p[k], a[k]);
  return s.dyadic();
}

}  // namespace certimesh::certificate::detail
