#include "integer_matrix.h"

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>

namespace certimesh::predicates::detail {

namespace {

struct Dyadic {
  long long mantissa = 0;  // |mantissa| < 2^53
  int exponent = 0;        // value = mantissa * 2^exponent
};

Dyadic decompose(double v) {
  Dyadic d;
  if (v == 0.0) return d;
  int e = 0;
  const double f = std::frexp(v, &e);  // v = f * 2^e, 0.5 <= |f| < 1, exact
  d.mantissa = static_cast<long long>(std::ldexp(f, 53));
  d.exponent = e - 53;
  return d;
}

constexpr int kMaxSize = 5;

}  // namespace

struct IntegerMatrix::Entries {
  std::array<std::array<mpz_class, kMaxSize>, kMaxSize> a;
};

IntegerMatrix::IntegerMatrix(std::span<const double> coordinates, int dim, bool lifted)
    : size_(static_cast<int>(coordinates.size()) / dim), entries_(std::make_unique<Entries>()) {
  int min_exponent = std::numeric_limits<int>::max();
  for (double v : coordinates)
    if (v != 0.0) min_exponent = std::min(min_exponent, decompose(v).exponent);
  for (int r = 0; r < size_; ++r) {
    mpz_class lift = 0;
    for (int c = 0; c < dim; ++c) {
      const Dyadic d = decompose(coordinates[static_cast<std::size_t>(r * dim + c)]);
      mpz_class x(static_cast<signed long>(d.mantissa));
      if (d.mantissa != 0)
        mpz_mul_2exp(x.get_mpz_t(), x.get_mpz_t(),
                     static_cast<mp_bitcnt_t>(d.exponent - min_exponent));
      lift += x * x;
      entries_->a[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = std::move(x);
    }
    int c = dim;
    if (lifted) entries_->a[static_cast<std::size_t>(r)][static_cast<std::size_t>(c++)] = lift;
    entries_->a[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)] = 1;
  }
}

IntegerMatrix::~IntegerMatrix() = default;

namespace {

// Laplace expansion along the first kept row; the matrices have at most 5 rows.
mpz_class minor_value(const std::array<std::array<mpz_class, kMaxSize>, kMaxSize>& a,
                      unsigned rows, unsigned cols) {
  if (rows == 0) return 1;
  const int r = std::countr_zero(rows);
  const unsigned other_rows = rows & (rows - 1);
  mpz_class sum = 0;
  int parity = 0;
  for (unsigned cs = cols; cs != 0; cs &= cs - 1) {
    const int c = std::countr_zero(cs);
    const mpz_class& entry = a[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
    if (entry != 0) {
      const mpz_class term = entry * minor_value(a, other_rows, cols & ~(1u << c));
      if (parity == 0) sum += term; else sum -= term;
    }
    parity ^= 1;
  }
  return sum;
}

}  // namespace

Sign IntegerMatrix::minor_sign(unsigned row_mask, unsigned column_mask) const {
  return sign_of_int(sgn(minor_value(entries_->a, row_mask, column_mask)));
}

}  // namespace certimesh::predicates::detail
