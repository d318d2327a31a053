// exact_sum.h (certificate-internal): ExactProductSum against GMP rationals, the oracle. Its
// fixed 384-bit path (terms within 192 bits of the first one's exponent) and its GMP path (after
// a term outside that window, or an integer term) must both give the exact sum: sums that
// cancel to zero, to one product's last bit, with subnormal factors, and spread over the whole
// exponent range, each read by sign(), value() and dyadic().
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "exact_sum.h"
#include "next_double.h"

namespace {

using certimesh::certificate::detail::Dyadic;
using certimesh::certificate::detail::ExactProductSum;
using certimesh::certificate::detail::next_down;
using certimesh::certificate::detail::next_up;

mpq_class of_dyadic(const Dyadic& d) {
  mpq_class q(d.m);
  if (d.e > 0) mpz_mul_2exp(q.get_num_mpz_t(), q.get_num_mpz_t(), static_cast<mp_bitcnt_t>(d.e));
  if (d.e < 0) mpz_mul_2exp(q.get_den_mpz_t(), q.get_den_mpz_t(), static_cast<mp_bitcnt_t>(-d.e));
  q.canonicalize();
  return q;
}

int sign_of(const mpq_class& q) { return sgn(q); }

// Random doubles with exponents in [lo, hi] (subnormals when lo is below -1022).
double random_double(std::mt19937_64& rng, int lo, int hi) {
  std::uniform_int_distribution<int> exponent(lo, hi);
  std::uniform_int_distribution<std::uint64_t> mantissa(0, (std::uint64_t{1} << 53) - 1);
  const double x = std::ldexp(static_cast<double>(mantissa(rng)), exponent(rng) - 53);
  return (rng() & 1) ? -x : x;
}

void expect_exact(const ExactProductSum& s, const mpq_class& want) {
  EXPECT_EQ(s.sign(), sign_of(want));
  EXPECT_EQ(s.value(), want);
  EXPECT_EQ(of_dyadic(s.dyadic()), want);
}

TEST(ExactProductSum, MatchesRationalsNarrowAndWide) {
  std::mt19937_64 rng(12);
  for (int trial = 0; trial < 3000; ++trial) {
    // Narrow windows stay on the fixed path; wide ones leave it mid-way.
    const int width = trial % 3 == 0 ? 20 : (trial % 3 == 1 ? 150 : 2000);
    const int lo = std::uniform_int_distribution<int>(-1100, 1000 - std::min(width, 2000))(rng);
    const int hi = std::min(1000, lo + width);
    ExactProductSum s;
    mpq_class want = 0;
    const int terms = 1 + trial % 17;
    for (int t = 0; t < terms; ++t) {
      const double a = random_double(rng, lo, (lo + hi) / 2), b = random_double(rng, lo, hi - (hi - lo) / 2);
      const int factor = (t + trial) % 4 == 0 ? -1 : ((t + trial) % 4 == 1 ? 2 : ((t + trial) % 4 == 2 ? -2 : 1));
      s.add(a, b, factor);
      want += mpq_class(a) * mpq_class(b) * factor;
    }
    expect_exact(s, want);
  }
}

TEST(ExactProductSum, CancellationToZeroAndToTheLastBit) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 2000; ++trial) {
    const int lo = std::uniform_int_distribution<int>(-1100, 900)(rng);
    std::vector<std::pair<double, double>> products;
    for (int t = 0; t < 6; ++t) products.push_back({random_double(rng, lo, lo + 60), random_double(rng, lo, lo + 60)});
    ExactProductSum s;
    mpq_class want = 0;
    for (const auto& [a, b] : products) s.add(a, b), want += mpq_class(a) * mpq_class(b);
    for (const auto& [a, b] : products) s.add(a, b, -1), want -= mpq_class(a) * mpq_class(b);
    expect_exact(s, want);  // zero
    ASSERT_EQ(s.sign(), 0);
    // One unit in the last place of a product, added after the cancellation.
    const double tiny = std::ldexp(1.0, lo - 53);
    s.add(tiny, trial % 2 ? 1.0 : -1.0);
    want += mpq_class(tiny) * (trial % 2 ? 1 : -1);
    expect_exact(s, want);
  }
}

TEST(ExactProductSum, IntegerTermsAfterProducts) {
  std::mt19937_64 rng(3);
  for (int trial = 0; trial < 500; ++trial) {
    ExactProductSum s;
    mpq_class want = 0;
    const double a = random_double(rng, -30, 30), b = random_double(rng, -30, 30);
    s.add(a, b);
    want += mpq_class(a) * mpq_class(b);
    mpz_class m = static_cast<long>(rng() % 2000001) - 1000000;
    const long e = static_cast<long>(rng() % 400) - 200;
    s.add(m, e);
    mpq_class term(m);
    if (e > 0) term *= mpq_class(mpz_class(1) << static_cast<mp_bitcnt_t>(e));
    if (e < 0) term /= mpq_class(mpz_class(1) << static_cast<mp_bitcnt_t>(-e));
    want += term;
    const double c = random_double(rng, -30, 30);
    s.add(c, c);
    want += mpq_class(c) * mpq_class(c);
    expect_exact(s, want);
  }
}

TEST(ExactProductSum, EmptyIsZero) {
  ExactProductSum s;
  expect_exact(s, 0);
  s.add(0.0, 5.0);
  s.add(3.0, 0.0, -1);
  expect_exact(s, 0);
}

// A copy (which copies GMP state only once the sum has spilled there) is an independent sum:
// copied after 3 terms (the 128-bit stage), after 20 (the fixed limbs) and after a far term
// (GMP), then both the copy and the original take different further terms.
TEST(ExactProductSum, CopiesAtEveryStageAreIndependent) {
  std::mt19937_64 rng(11);
  for (int stage = 0; stage < 3; ++stage)
    for (int trial = 0; trial < 100; ++trial) {
      ExactProductSum s;
      mpq_class want = 0;
      const int terms = stage == 0 ? 3 : 20;
      for (int i = 0; i < terms; ++i) {
        const double a = random_double(rng, -20, 20), b = random_double(rng, -20, 20);
        s.add(a, b);
        want += mpq_class(a) * mpq_class(b);
      }
      if (stage == 2) {
        s.add(0x1p-600, 0x1p-300);
        want += mpq_class(0x1p-600) * mpq_class(0x1p-300);
      }
      ExactProductSum copy = s;
      ExactProductSum assigned;
      assigned.add(1.0, 1.0);
      assigned = s;
      mpq_class want_copy = want, want_assigned = want;
      const double a = random_double(rng, -20, 20), b = random_double(rng, -20, 20);
      s.add(a, b);
      want += mpq_class(a) * mpq_class(b);
      copy.add(b, b, -2);
      want_copy -= 2 * mpq_class(b) * mpq_class(b);
      assigned.add(a, a);
      want_assigned += mpq_class(a) * mpq_class(a);
      expect_exact(s, want);
      expect_exact(copy, want_copy);
      expect_exact(assigned, want_assigned);
    }
}

// next_up / next_down against std::nextafter, the oracle: zeros, subnormals, the normal range's
// ends, the infinities, powers of two (where the step changes), and random bit patterns.
TEST(NextDouble, MatchesNextafter) {
  std::vector<double> xs = {0.0, -0.0, 0x1p-1074, -0x1p-1074, 0x1p-1022, -0x1p-1022, 0x1.fffffffffffffp-1023,
                            1.0, -1.0, 0x1p52, DBL_MAX, -DBL_MAX, INFINITY, -INFINITY, 0.1, -3.5};
  std::mt19937_64 rng(5);
  for (int i = 0; i < 100000; ++i) {
    const double x = std::bit_cast<double>(rng());
    if (!std::isnan(x)) xs.push_back(x);
  }
  for (double x : xs) {
    const double up = std::nextafter(x, INFINITY), down = std::nextafter(x, -INFINITY);
    EXPECT_EQ(std::bit_cast<std::uint64_t>(next_up(x)), std::bit_cast<std::uint64_t>(up)) << x;
    EXPECT_EQ(std::bit_cast<std::uint64_t>(next_down(x)), std::bit_cast<std::uint64_t>(down)) << x;
  }
}

}  // namespace
