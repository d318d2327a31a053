// Exact rational helpers (rational.h).
#include "rational.h"

#include <cmath>

namespace certimesh::certificate::detail {

double sqrt_of(const Q& r) {
  if (sgn(r) <= 0) return 0.0;
  // r = r' * 4^k with r' near 1: the square root of r' is taken in double, k restored by ldexp.
  const long bits = static_cast<long>(mpz_sizeinbase(r.get_num_mpz_t(), 2)) - static_cast<long>(mpz_sizeinbase(r.get_den_mpz_t(), 2));
  const long k = bits / 2;
  Q scaled = r;
  if (k > 0) mpq_div_2exp(scaled.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(2 * k));
  if (k < 0) mpq_mul_2exp(scaled.get_mpq_t(), r.get_mpq_t(), static_cast<mp_bitcnt_t>(-2 * k));
  return std::ldexp(std::sqrt(scaled.get_d()), static_cast<int>(std::max(-100000L, std::min(100000L, k))));
}

}  // namespace certimesh::certificate::detail
