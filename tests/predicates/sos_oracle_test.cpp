// X_sos against an independent oracle of the scheme of symbolic_perturbation.h: the sign
// of the perturbed determinant itself, computed exactly with GMP integers for a concrete
// small eps = 2^-b, with no monomial search.
//
// The perturbed matrix has rows (x + e(p, x), y + e(p, y), [|p|^2 + e(p, lift),] 1), one
// per argument in argument order, with e(p, j) = eps^(2^i), i the entry's significance index:
// lifted entries by lexicographic rank first, then the coordinates by rank and axis.
// Multiplying every entry by 2^(b 2^(S-1)) (S perturbed entries) keeps the sign and makes
// all entries integers. On integer coordinates |x| <= 8 every coefficient of the
// perturbation polynomial is an integer minor, below 2^18 in magnitude, and there are at
// most 2^12 monomials of distinct degree; the first non-zero one therefore dominates the
// rest when eps = 2^-64 (orient2d) or 2^-40 (orient3d, incircle: 12 entries, 81,920-bit
// integers, ~20 ms a determinant, so a sample). Insphere (20 entries, ~2^25-bit integers)
// is out of reach this way; for it, and for every case of the others, a second oracle
// expands the perturbation polynomial itself (perturbation_polynomial_sign).
//
// Coordinates are scaled by a power of two before the kernel sees them (positive column
// scaling keeps every minor's sign), over the whole exponent range.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <map>
#include <numeric>
#include <vector>

#include "support.h"

namespace certimesh::test {
namespace {

using IntMatrix = std::vector<std::vector<mpz_class>>;

mpz_class det(const IntMatrix& m, unsigned rows, unsigned cols) {  // Laplace, first kept row
  if (rows == 0) return 1;
  const int r = std::countr_zero(rows);
  mpz_class sum = 0;
  bool plus = true;
  for (unsigned cs = cols; cs != 0; cs &= cs - 1) {
    const int c = std::countr_zero(cs);
    const mpz_class& e = m[static_cast<std::size_t>(r)][static_cast<std::size_t>(c)];
    if (e != 0) {
      const mpz_class t = e * det(m, rows & (rows - 1), cols & ~(1u << c));
      if (plus) sum += t; else sum -= t;
    }
    plus = !plus;
  }
  return sum;
}

/// Sign of the perturbed determinant for integer points (N points, dimension Dim).
template <std::size_t N, std::size_t Dim>
int perturbed_determinant_sign(const std::array<std::array<long, Dim>, N>& p, bool lifted,
                               unsigned b) {
  const std::size_t n_cols = Dim + (lifted ? 1 : 0) + 1;
  EXPECT_EQ(n_cols, N);
  std::array<std::size_t, N> order{};
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return p[i] < p[j]; });
  std::vector<std::pair<std::size_t, std::size_t>> symbols;  // (row, column), by significance
  if (lifted)
    for (std::size_t r : order) symbols.push_back({r, Dim});
  for (std::size_t r : order)
    for (std::size_t c = 0; c < Dim; ++c) symbols.push_back({r, c});
  const std::size_t S = symbols.size();
  const unsigned long top = 1ul << (S - 1);  // eps^(2^(S-1)) is the smallest infinitesimal
  IntMatrix m(N, std::vector<mpz_class>(N));
  for (std::size_t r = 0; r < N; ++r) {
    long lift = 0;
    for (std::size_t c = 0; c < Dim; ++c) {
      m[r][c] = p[r][c];
      lift += p[r][c] * p[r][c];
    }
    if (lifted) m[r][Dim] = lift;
    m[r][N - 1] = 1;
    for (auto& v : m[r]) v <<= static_cast<mp_bitcnt_t>(b * top);
  }
  for (std::size_t i = 0; i < S; ++i) {
    mpz_class e = 1;
    e <<= static_cast<mp_bitcnt_t>(b * (top - (1ul << i)));
    m[symbols[i].first][symbols[i].second] += e;
  }
  return sgn(det(m, (1u << N) - 1, (1u << N) - 1));
}

/// The same sign as the limit eps -> 0+, from the perturbation polynomial itself: the
/// Leibniz expansion of det(M + E) with every entry a polynomial in eps (a + eps^(2^i) or
/// a), accumulated by degree; the sign of the lowest-degree non-zero coefficient. Exact
/// (int64 coefficients: |entries| <= 200, at most 5 factors), independent of the kernel's
/// monomial search, and cheap enough for insphere (120 permutations x 32 monomials).
template <std::size_t N, std::size_t Dim>
int perturbation_polynomial_sign(const std::array<std::array<long, Dim>, N>& p, bool lifted) {
  std::array<std::size_t, N> order{};
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) { return p[i] < p[j]; });
  std::array<std::array<long, N>, N> m{};
  std::array<std::array<int, N>, N> index{};  // significance index, -1 = not perturbed
  for (auto& row : index) row.fill(-1);
  int next = 0;
  if (lifted)
    for (std::size_t r : order) index[r][Dim] = next++;
  for (std::size_t r : order)
    for (std::size_t c = 0; c < Dim; ++c) index[r][c] = next++;
  for (std::size_t r = 0; r < N; ++r) {
    long lift = 0;
    for (std::size_t c = 0; c < Dim; ++c) {
      m[r][c] = p[r][c];
      lift += p[r][c] * p[r][c];
    }
    if (lifted) m[r][Dim] = lift;
    m[r][N - 1] = 1;
  }
  std::map<std::uint64_t, long long> poly;  // degree in eps -> coefficient
  std::array<std::size_t, N> perm{};
  std::iota(perm.begin(), perm.end(), std::size_t{0});
  do {
    int inversions = 0;
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = i + 1; j < N; ++j) inversions += perm[i] > perm[j];
    // Expand prod_r (m[r][perm r] + eps^(2^index)) over the choice mask.
    for (unsigned mask = 0; mask < (1u << N); ++mask) {
      long long coeff = (inversions & 1) ? -1 : 1;
      std::uint64_t degree = 0;
      bool vanishes = false;
      for (std::size_t r = 0; r < N && !vanishes; ++r) {
        const int idx = index[r][perm[r]];
        if ((mask >> r) & 1u) {  // the infinitesimal of this entry
          if (idx < 0) vanishes = true;
          else degree += std::uint64_t{1} << idx;
        } else {
          coeff *= m[r][perm[r]];
          vanishes = coeff == 0;
        }
      }
      if (!vanishes) poly[degree] += coeff;
    }
  } while (std::next_permutation(perm.begin(), perm.end()));
  for (const auto& [degree, coeff] : poly)
    if (coeff != 0) return coeff > 0 ? 1 : -1;
  return 0;
}

/// N distinct small integer points: half the time any points of [-R, R]^Dim (R in 1..3),
/// half the time degenerate by construction -- collinear a + t d (orient2d), coplanar
/// a + s u + t v (orient3d), on one circle of squared radius 1, 2, 5 or 25 (incircle), on one
/// sphere of squared radius 2, 3 or 9 or on one plane (insphere). Shrinkable.
template <std::size_t N, std::size_t Dim>
std::array<std::array<long, Dim>, N> draw_small_config(bool lifted) {
  using fz::rcgen::pick;
  std::array<std::array<long, Dim>, N> p{};
  const bool degenerate = pick(0, 2) == 1;
  std::vector<std::array<long, Dim>> pool;
  std::array<long, Dim> centre{};
  if (degenerate) {
    for (auto& v : centre) v = pick(-3L, 4L);
    if (!lifted && Dim == 2) {  // collinear
      std::array<long, Dim> d{};
      for (auto& v : d) v = pick(-2L, 3L);
      if (d == std::array<long, Dim>{}) d[0] = 1;
      for (long t = -2; t <= 2; ++t) {
        std::array<long, Dim> q{};
        for (std::size_t k = 0; k < Dim; ++k) q[k] = t * d[k];
        pool.push_back(q);
      }
    } else if (!lifted) {  // coplanar
      std::array<long, Dim> u{}, v{};
      for (auto& x : u) x = pick(-2L, 3L);
      for (auto& x : v) x = pick(-2L, 3L);
      for (long s = -1; s <= 1; ++s)
        for (long t = -1; t <= 1; ++t) {
          std::array<long, Dim> q{};
          for (std::size_t k = 0; k < Dim; ++k) q[k] = s * u[k] + t * v[k];
          pool.push_back(q);
        }
    } else {
      static constexpr long r2_2d[] = {1, 2, 5, 25};
      static constexpr long r2_3d[] = {2, 3, 9, -1};  // -1: the plane z = 0
      const long r2 = Dim == 2 ? r2_2d[pick(0, 4)] : r2_3d[pick(0, 4)];
      if constexpr (Dim == 2) {
        for (long x = -5; x <= 5; ++x)
          for (long y = -5; y <= 5; ++y)
            if (x * x + y * y == r2) pool.push_back({x, y});
      } else {
        for (long x = -3; x <= 3; ++x)
          for (long y = -3; y <= 3; ++y)
            for (long z = -3; z <= 3; ++z)
              if (r2 < 0 ? (z == 0 && x * x + y * y <= 2) : x * x + y * y + z * z == r2)
                pool.push_back({x, y, z});
      }
    }
  }
  std::sort(pool.begin(), pool.end());
  pool.erase(std::unique(pool.begin(), pool.end()), pool.end());  // u, v may be parallel
  const long R = pick(1L, 4L);
  for (std::size_t i = 0; i < N; ++i) {
    for (;;) {
      if (degenerate && pool.size() >= N) {
        p[i] = pool[pick<std::size_t>(0, pool.size())];
        for (std::size_t k = 0; k < Dim; ++k) p[i][k] += centre[k];
      } else {
        for (auto& v : p[i]) v = pick(-R, R + 1);
      }
      bool fresh = true;
      for (std::size_t j = 0; j < i; ++j) fresh = fresh && p[j] != p[i];
      if (fresh) break;
    }
  }
  return p;
}

template <class T>
typename T::Pts to_doubles(const std::array<std::array<long, T::Dim>, T::N>& ip, int k) {
  typename T::Pts p{};
  for (std::size_t i = 0; i < T::N; ++i)
    for (std::size_t c = 0; c < T::Dim; ++c) p[i][c] = std::ldexp(static_cast<double>(ip[i][c]), k);
  return p;
}

/// X_sos == the perturbation polynomial's sign (all four predicates), and, when
/// `concrete_eps_bits` > 0, == the sign of the perturbed determinant at eps = 2^-bits.
template <class T>
void sos_matches_oracle(int cases, unsigned concrete_eps_bits) {
  const std::string id = std::string(T::name) + (concrete_eps_bits
                                                     ? ".sos_matches_perturbed_determinant_at_eps"
                                                     : ".sos_matches_perturbation_polynomial");
  const auto result = run_property(id, cases, [concrete_eps_bits] {
    const auto ip = draw_small_config<T::N, T::Dim>(T::lifted);
    const int k = fz::rcgen::pick(-1070, 1000);  // positive scaling keeps every minor's sign
    const auto p = to_doubles<T>(ip, k);
    const int expected = perturbation_polynomial_sign<T::N, T::Dim>(ip, T::lifted);  // NOLINT
    RC_ASSERT(expected != 0);
    if (concrete_eps_bits) {
      const int at_eps = perturbed_determinant_sign<T::N, T::Dim>(ip, T::lifted, concrete_eps_bits);
      RC_ASSERT(at_eps == expected);
    }
    RC_ASSERT(T::sos(p) == expected);
    RC_TAG(T::oracle(p) == 0 ? "exactly-degenerate" : "non-degenerate");
  });
  ASSERT_TRUE(result.template is<rc::detail::SuccessResult>());
  EXPECT_GE(tag_share(result.template get<rc::detail::SuccessResult>().distribution,
                      "exactly-degenerate"),
            0.30);
}

// eps = 2^-64 on 6 entries: 2,048-bit integers, cheap: every case.
TEST(SosOracle, Orient2dMatchesPerturbedDeterminantAtEps) { sos_matches_oracle<Orient2d>(10000, 64); }
// eps = 2^-40 on 12 entries: 81,920-bit integers, ~20 ms a determinant: a sample.
TEST(SosOracle, Orient3dMatchesPerturbedDeterminantAtEps) { sos_matches_oracle<Orient3d>(400, 40); }
TEST(SosOracle, IncircleMatchesPerturbedDeterminantAtEps) { sos_matches_oracle<Incircle>(400, 40); }
// The perturbation polynomial, every case.
TEST(SosOracle, Orient2dMatchesPerturbationPolynomial) { sos_matches_oracle<Orient2d>(10000, 0); }
TEST(SosOracle, Orient3dMatchesPerturbationPolynomial) { sos_matches_oracle<Orient3d>(10000, 0); }
TEST(SosOracle, IncircleMatchesPerturbationPolynomial) { sos_matches_oracle<Incircle>(10000, 0); }
TEST(SosOracle, InsphereMatchesPerturbationPolynomial) { sos_matches_oracle<Insphere>(10000, 0); }

TEST(SosOracle, OracleSeparatesPermutations) {
  const std::array<std::array<long, 2>, 3> p{{{0, 0}, {1, 1}, {2, 2}}};
  const std::array<std::array<long, 2>, 3> q{{{1, 1}, {0, 0}, {2, 2}}};
  const int a = perturbed_determinant_sign<3, 2>(p, false, 64);
  const int c = perturbed_determinant_sign<3, 2>(q, false, 64);
  EXPECT_NE(a, 0);
  EXPECT_EQ(a, -c);
  EXPECT_EQ((perturbation_polynomial_sign<3, 2>(p, false)), a);
  EXPECT_EQ((perturbation_polynomial_sign<3, 2>(q, false)), c);
}

}  // namespace
}  // namespace certimesh::test
