// A fast exact oracle for the predicate signs, independent of the kernel and of the rational
// oracle: every finite double is m * 2^e (m an integer of at most 53 bits), so scaling all
// coordinates by 2^-emin (emin the least exponent among them) makes them integers without
// changing the sign of the translated determinant (each column is scaled by a positive
// constant: 2^-emin, the lifted column by 2^-2emin). The determinant is then an integer
// polynomial, evaluated by cofactor expansion: in __int128 when the bit lengths prove that
// nothing overflows, else in GMP mpz. No rationals, hence no gcd: the rational oracle
// (rational_oracle.h) stays the referee for disagreements.
//
// The matrix is the rational oracle's: rows p_i - p_last (, |p_i - p_last|^2), i < last.
#pragma once

#include <gmp.h>

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>

namespace certimesh::testing {

namespace scaled_integer_detail {

__extension__ typedef __int128 Int128;

// x = mantissa * 2^exponent with an odd mantissa (0 for x == 0); x finite.
struct Dyadic {
  std::int64_t mantissa = 0;
  int exponent = 0;
};

inline Dyadic dyadic(double x) {
  if (x == 0.0) return {};
  int e = 0;
  const double f = std::frexp(x, &e);  // |f| in [0.5, 1)
  auto m = static_cast<std::int64_t>(std::ldexp(f, 53));
  e -= 53;
  const int tz = std::countr_zero(static_cast<std::uint64_t>(m < 0 ? -m : m));
  return {m >> tz, e + tz};
}

inline int bit_length(std::int64_t m) {
  return static_cast<int>(std::bit_width(static_cast<std::uint64_t>(m < 0 ? -m : m)));
}

template <class T>
T det2(const T& a, const T& b, const T& c, const T& d) { return a * d - b * c; }

template <class T, class M>
T det3(const M& m, int r0, int r1, int r2, int c0, int c1, int c2) {
  return m[r0][c0] * det2<T>(m[r1][c1], m[r1][c2], m[r2][c1], m[r2][c2]) -
         m[r0][c1] * det2<T>(m[r1][c0], m[r1][c2], m[r2][c0], m[r2][c2]) +
         m[r0][c2] * det2<T>(m[r1][c0], m[r1][c1], m[r2][c0], m[r2][c1]);
}

// det of the leading n x n block (n = 2, 3, 4) by cofactor expansion along the last column.
template <class T, class M>
T determinant(const M& m, int n) {
  if (n == 2) return det2<T>(m[0][0], m[0][1], m[1][0], m[1][1]);
  if (n == 3) return det3<T>(m, 0, 1, 2, 0, 1, 2);
  return -m[0][3] * det3<T>(m, 1, 2, 3, 0, 1, 2) + m[1][3] * det3<T>(m, 0, 2, 3, 0, 1, 2) -
         m[2][3] * det3<T>(m, 0, 1, 3, 0, 1, 2) + m[3][3] * det3<T>(m, 0, 1, 2, 0, 1, 2);
}

template <class T>
int sign_of(const T& v) { return v > 0 ? 1 : (v < 0 ? -1 : 0); }

// The same cofactor expansion as determinant() in mpz, into preallocated integers.
struct MpzWorkspace {
  mpz_t m[4][4];
  mpz_t a, b, lift, minor, acc, t;
  MpzWorkspace() {
    for (auto& row : m)
      for (auto& v : row) mpz_init(v);
    for (mpz_ptr v : {a, b, lift, minor, acc, t}) mpz_init(v);
  }
  ~MpzWorkspace() {
    for (auto& row : m)
      for (auto& v : row) mpz_clear(v);
    for (mpz_ptr v : {a, b, lift, minor, acc, t}) mpz_clear(v);
  }
  MpzWorkspace(const MpzWorkspace&) = delete;
  MpzWorkspace& operator=(const MpzWorkspace&) = delete;

  void set_scaled(mpz_ptr out, const Dyadic& c, int emin) {
    mpz_set_si(out, static_cast<long>(c.mantissa));
    if (c.mantissa != 0) mpz_mul_2exp(out, out, static_cast<mp_bitcnt_t>(c.exponent - emin));
  }
  // out = det of rows r0, r1, r2 and columns 0, 1, 2 (expansion along the first row).
  void det3(mpz_ptr out, int r0, int r1, int r2) {
    mpz_set_ui(out, 0);
    const int cols[3][3] = {{0, 1, 2}, {1, 0, 2}, {2, 0, 1}};
    for (int j = 0; j < 3; ++j) {
      const int c0 = cols[j][0], c1 = cols[j][1], c2 = cols[j][2];
      mpz_mul(t, m[r1][c1], m[r2][c2]);
      mpz_submul(t, m[r1][c2], m[r2][c1]);
      if (j == 1) mpz_submul(out, m[r0][c0], t);
      else mpz_addmul(out, m[r0][c0], t);
    }
  }
  int determinant_sign(int n) {
    if (n == 2) {
      mpz_mul(acc, m[0][0], m[1][1]);
      mpz_submul(acc, m[0][1], m[1][0]);
    } else if (n == 3) {
      det3(acc, 0, 1, 2);
    } else {  // along the last column: signs -, +, -, + for rows 0..3
      mpz_set_ui(acc, 0);
      const int rows[4][3] = {{1, 2, 3}, {0, 2, 3}, {0, 1, 3}, {0, 1, 2}};
      for (int i = 0; i < 4; ++i) {
        det3(minor, rows[i][0], rows[i][1], rows[i][2]);
        if (i % 2 == 0) mpz_submul(acc, m[i][3], minor);
        else mpz_addmul(acc, m[i][3], minor);
      }
    }
    return mpz_sgn(acc);
  }
};

}  // namespace scaled_integer_detail

/// The largest |difference| bit length for which the __int128 evaluation cannot overflow,
/// by predicate (the degree and the number of terms bound every intermediate):
///   orient2d: |d| < 2^62, products < 2^124;         orient3d: |d| < 2^40, terms < 2^120;
///   incircle: |d| < 2^29, lift < 2^59, terms < 2^118; insphere: |d| < 2^22, terms < 2^115.
constexpr int int128_difference_bits(std::size_t dim, bool lifted) {
  return lifted ? (dim == 2 ? 29 : 22) : (dim == 2 ? 62 : 40);
}

/// Sign of det[p_i - p_last (, |p_i - p_last|^2)], i < last, for finite coordinates.
/// `used_int128` (optional) tells which arithmetic answered.
template <std::size_t D, std::size_t N>
int scaled_integer_sign(const std::array<std::array<double, D>, N>& p, bool lifted,
                        bool* used_int128 = nullptr) {
  namespace sd = scaled_integer_detail;
  static_assert(N >= 2 && N <= 5);
  std::array<std::array<sd::Dyadic, D>, N> q{};
  int emin = 1 << 20;
  for (std::size_t i = 0; i < N; ++i)
    for (std::size_t k = 0; k < D; ++k) {
      q[i][k] = sd::dyadic(p[i][k]);
      if (q[i][k].mantissa != 0) emin = std::min(emin, q[i][k].exponent);
    }
  int bits = 0;  // bit length of the largest scaled coordinate
  for (const auto& row : q)
    for (const auto& c : row)
      if (c.mantissa != 0) bits = std::max(bits, sd::bit_length(c.mantissa) + c.exponent - emin);
  const int n = static_cast<int>(N) - 1;
  const bool small = bits + 1 <= int128_difference_bits(D, lifted);
  if (used_int128) *used_int128 = small;
  if (bits == 0) return 0;  // every coordinate zero

  if (small) {
    std::array<std::array<sd::Int128, 4>, 4> m{};
    const auto scaled = [&](const sd::Dyadic& c) {
      return c.mantissa == 0 ? sd::Int128{0} : sd::Int128{c.mantissa} * (sd::Int128{1} << (c.exponent - emin));
    };
    for (int i = 0; i < n; ++i) {
      sd::Int128 lift = 0;
      for (std::size_t k = 0; k < D; ++k) {
        const sd::Int128 d = scaled(q[i][k]) - scaled(q[N - 1][k]);
        m[i][k] = d;
        lift += d * d;
      }
      if (lifted) m[i][D] = lift;
    }
    return sd::sign_of(sd::determinant<sd::Int128>(m, n));
  }

  // GMP path: one workspace per thread, so that after the first calls no evaluation
  // allocates (allocation was most of the cost of mpz_class temporaries).
  thread_local sd::MpzWorkspace w;
  for (int i = 0; i < n; ++i) {
    mpz_set_ui(w.lift, 0);
    for (std::size_t k = 0; k < D; ++k) {
      w.set_scaled(w.a, q[i][k], emin);
      w.set_scaled(w.b, q[N - 1][k], emin);
      mpz_sub(w.m[i][k], w.a, w.b);
      mpz_addmul(w.lift, w.m[i][k], w.m[i][k]);
    }
    if (lifted) mpz_set(w.m[i][D], w.lift);
  }
  return w.determinant_sign(n);
}

}  // namespace certimesh::testing
