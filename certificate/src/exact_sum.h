// Internal: the exact sum of many products of two doubles, without a rational per term. Each
// double is m 2^e with an integer m < 2^53; the sum is kept as one integer in units of the
// smallest product exponent seen so far (shifted up when a smaller one arrives), so adding a
// term costs a 106-bit product and one shifted addition: linear in the terms, with no gcd.
#pragma once

#include <gmpxx.h>

#include <climits>
#include <cmath>
#include <cstdint>

namespace certimesh::certificate::detail {

/// Also sums integers times powers of two (m 2^e), in the same units.
class ExactProductSum {
 public:
  /// Adds sign * a * b exactly (a, b finite).
  void add(double a, double b, int sign = 1) {
    if (a == 0 || b == 0 || sign == 0) return;
    int ea = 0, eb = 0;
    const auto ma = static_cast<std::int64_t>(std::ldexp(std::frexp(a, &ea), 53));  // a = ma 2^(ea - 53)
    const auto mb = static_cast<std::int64_t>(std::ldexp(std::frexp(b, &eb), 53));
    term_ = static_cast<long>(ma);
    term_ *= static_cast<long>(mb);
    if (sign < 0) term_ = -term_;
    add_term(static_cast<long>(ea) + eb - 106);
  }
  /// Adds m * 2^exponent exactly.
  void add(const mpz_class& m, long exponent) {
    if (m == 0) return;
    term_ = m;
    add_term(exponent);
  }
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

}  // namespace certimesh::certificate::detail
