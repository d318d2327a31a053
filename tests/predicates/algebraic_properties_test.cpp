// RapidCheck properties of the four predicates on the adversarial generators of
// fuzz/generators (40 % exactly degenerate, 40 % near-degenerate, 20 % generic inputs at
// every scale): the exact sign equals the rational oracle; the filter never contradicts
// it; the numbered algebraic properties of each header (X.1-X.4, X.7); and the
// generators' own claims (every "exactly degenerate" construction is zero for the oracle,
// and at least 30 % of the cases are exactly degenerate and 30 % near-degenerate).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>

#include "support.h"

namespace certimesh::test {
namespace {

constexpr int kCases = 25000;  // per property (CERTIMESH_RC_SCALE multiplies it)

template <class T>
std::string kind_tag(const typename T::Input& c, int oracle) {
  if (oracle == 0) return "exactly-degenerate";
  return c.kind == fz::Kind::near_degenerate ? "near-degenerate" : "generic";
}

/// Prints the marginal distribution of the tags that start with `prefix`.
inline void print_marginals(const std::string& id, const rc::detail::Distribution& dist) {
  std::map<std::string, long> counts;
  long total = 0;
  for (const auto& [tags, n] : dist) {
    total += n;
    for (const auto& t : tags) counts[t] += n;
  }
  std::cout << "[distribution " << id << "] " << total << " cases\n";
  for (const auto& [tag, n] : counts)
    std::cout << "    " << tag << ": " << n << " (" << 100.0 * static_cast<double>(n) / static_cast<double>(total) << " %)\n";
  std::cout << std::flush;
}

// (X.5 / the exact stage) exact == oracle, and the generator's degeneracy claims.
template <class T>
void exact_matches_oracle() {
  const std::string id = std::string(T::name) + ".exact_matches_oracle";
  const auto result = run_property(id, kCases, [] {
    const auto c = *T::gen();
    const int o = T::oracle(c.p);
    // The generator's claim: an exactly degenerate construction is degenerate.
    RC_ASSERT(c.kind != fz::Kind::exact_degenerate || o == 0);
    RC_ASSERT(T::exact(c.p) == o);
    RC_ASSERT(T::exact_stage(c.p) == o);
    RC_TAG(kind_tag<T>(c, o), std::string("binade:") + fz::binade_name(c.binade),
           std::string("family:") + c.family);
  });
  ASSERT_TRUE(result.template is<rc::detail::SuccessResult>());
  const auto& dist = result.template get<rc::detail::SuccessResult>().distribution;
  print_marginals(id, dist);
  EXPECT_GE(tag_share(dist, "exactly-degenerate"), 0.30) << "generator lost its degenerate share";
  EXPECT_GE(tag_share(dist, "near-degenerate"), 0.30) << "generator lost its near-degenerate share";
  EXPECT_GE(tag_share(dist, "binade:subnormal"), 0.02);
  EXPECT_GE(tag_share(dist, "binade:huge"), 0.02);
  EXPECT_GE(tag_share(dist, "binade:overflow-threshold"), 0.02);
  EXPECT_GE(tag_share(dist, "binade:tiny"), 0.02);
}

// (X.6) the filter is uncertain or right: zero second-type errors.
template <class T>
void filter_never_contradicts() {
  const std::string id = std::string(T::name) + ".filter_never_contradicts_oracle";
  const auto result = run_property(id, kCases, [] {
    const auto c = *T::gen();
    const int o = T::oracle(c.p);
    const int f = T::filtered(c.p);
    RC_ASSERT(f == 0 || f == o);
    RC_TAG(kind_tag<T>(c, o), f == 0 ? "filter:uncertain" : "filter:certain");
  });
  if (result.template is<rc::detail::SuccessResult>())
    print_marginals(id, result.template get<rc::detail::SuccessResult>().distribution);
}

template <class Pts>
std::pair<std::size_t, std::size_t> draw_pair() {
  const auto n = std::tuple_size_v<Pts>;
  const std::size_t i = fz::rcgen::pick<std::size_t>(0, n);
  std::size_t j = fz::rcgen::pick<std::size_t>(0, n - 1);
  if (j >= i) ++j;
  return {i, j};
}

// (X.1) antisymmetry: a transposition negates the sign.
template <class T>
void antisymmetry() {
  run_property(std::string(T::name) + ".antisymmetry", kCases, [] {
    const auto c = *T::gen();
    const auto [i, j] = draw_pair<typename T::Pts>();
    auto q = c.p;
    std::swap(q[i], q[j]);
    RC_ASSERT(T::exact(q) == -T::exact(c.p));
  });
}

// (X.2) even permutations (cyclic shifts for orient2d) keep the sign.
template <class T>
void even_permutations() {
  run_property(std::string(T::name) + ".even_permutations", kCases, [] {
    const auto c = *T::gen();
    std::array<std::size_t, T::N> perm{};
    std::iota(perm.begin(), perm.end(), std::size_t{0});
    int parity = 0;
    for (std::size_t i = T::N - 1; i > 0; --i) {
      const std::size_t j = fz::rcgen::pick<std::size_t>(0, i + 1);
      if (j != i) {
        std::swap(perm[i], perm[j]);
        parity ^= 1;
      }
    }
    if (parity) std::swap(perm[0], perm[1]);
    auto q = c.p;
    for (std::size_t i = 0; i < T::N; ++i) q[i] = c.p[perm[i]];
    RC_ASSERT(T::exact(q) == T::exact(c.p));
  });
}

/// The largest power of two that divides x (x != 0, finite): its lowest set bit.
inline double lowest_bit(double x) {
  int e = 0;
  const double f = std::frexp(std::fabs(x), &e);  // x = f 2^e, f in [0.5, 1)
  const auto m = static_cast<std::uint64_t>(std::ldexp(f, 53));
  return std::ldexp(1.0, e - 53 + std::countr_zero(m));
}

// (X.3) translation by a vector whose every sum is exact: offsets k * q with q the
// common grid of the coordinates (the smallest lowest-set-bit; every coordinate is a
// multiple of it). Offsets that
// would round are not used; the translated share must stay above 35 %.
template <class T>
void translation() {
  const std::string id = std::string(T::name) + ".translation_exact_offsets";
  const auto result = run_property(id, kCases, [] {
    const auto c = *T::gen();
    double q = std::numeric_limits<double>::infinity();
    for (const auto& p : c.p)
      for (double v : p)
        if (v != 0.0) q = std::min(q, lowest_bit(v));
    if (!std::isfinite(q)) q = std::numeric_limits<double>::denorm_min();
    std::array<double, T::Dim> t{};
    for (auto& v : t)
      v = static_cast<double>(fz::rcgen::pick<std::int64_t>(-1024, 1025)) * q;
    auto moved = c.p;
    bool exact = true;
    for (auto& p : moved)
      for (std::size_t k = 0; k < T::Dim; ++k) {
        exact = exact && fz::sum_is_exact(p[k], t[k]);
        p[k] += t[k];
      }
    if (!exact) {
      RC_TAG("offset-would-round:skipped");
      return;
    }
    RC_TAG("translated");
    RC_ASSERT(T::exact(moved) == T::exact(c.p));
  });
  ASSERT_TRUE(result.template is<rc::detail::SuccessResult>());
  const auto& dist = result.template get<rc::detail::SuccessResult>().distribution;
  print_marginals(id, dist);
  EXPECT_GE(tag_share(dist, "translated"), 0.35);
}

// (X.4) scaling by 2^k (exact, no overflow or underflow) keeps the sign; negating one axis
// negates it.
template <class T>
void scaling_and_negation() {
  const std::string id = std::string(T::name) + ".power_of_two_scaling_and_axis_negation";
  const auto result = run_property(id, kCases, [] {
    const auto c = *T::gen();
    int k = fz::rcgen::pick(1, 65);
    if (fz::rcgen::pick(0, 2)) k = -k;
    auto scaled_pts = c.p;
    bool ok = true;
    for (auto& p : scaled_pts)
      for (auto& v : p) v = fz::scale2(v, k, ok);
    if (!ok) {  // try the other direction
      ok = true;
      k = -k;
      scaled_pts = c.p;
      for (auto& p : scaled_pts)
        for (auto& v : p) v = fz::scale2(v, k, ok);
    }
    const int s = T::exact(c.p);
    if (ok) {
      RC_TAG("scaled");
      RC_ASSERT(T::exact(scaled_pts) == s);
    } else {
      RC_TAG("scale-would-round:skipped");
    }
    const std::size_t axis = fz::rcgen::pick<std::size_t>(0, T::Dim);
    auto mirrored = c.p;
    for (auto& p : mirrored) p[axis] = -p[axis];
    RC_ASSERT(T::exact(mirrored) == -s);
  });
  ASSERT_TRUE(result.template is<rc::detail::SuccessResult>());
  const auto& dist = result.template get<rc::detail::SuccessResult>().distribution;
  print_marginals(id, dist);
  EXPECT_GE(tag_share(dist, "scaled"), 0.6);
}

// (X.7) SoS: never zero for distinct points, equal to the exact sign when that is not zero.
template <class T>
void sos_nonzero_and_consistent() {
  const std::string id = std::string(T::name) + ".sos_nonzero_and_equals_exact";
  const auto result = run_property(id, kCases, [] {
    const auto c = *T::gen();
    const int e = T::exact(c.p);
    const int s = T::sos(c.p);
    if (e != 0) RC_ASSERT(s == e);
    if (has_duplicate(c.p)) {
      RC_TAG("duplicate-points");
      return;
    }
    RC_TAG(e == 0 ? "exact-zero-resolved" : "exact-nonzero");
    RC_ASSERT(s != 0);
  });
  if (result.template is<rc::detail::SuccessResult>())
    print_marginals(id, result.template get<rc::detail::SuccessResult>().distribution);
}

// (X.7) SoS obeys X.1 and X.2: any permutation multiplies the sign by its parity.
template <class T>
void sos_permutations() {
  const std::string id = std::string(T::name) + ".sos_antisymmetry_and_even_permutations";
  run_property(id, kCases, [] {
    const auto c = *T::exact_gen();  // exact zeros: the perturbation decides every sign
    RC_PRE(!has_duplicate(c.p));
    std::array<std::size_t, T::N> perm{};
    std::iota(perm.begin(), perm.end(), std::size_t{0});
    int parity = 0;
    for (std::size_t i = T::N - 1; i > 0; --i) {
      const std::size_t j = fz::rcgen::pick<std::size_t>(0, i + 1);
      if (j != i) {
        std::swap(perm[i], perm[j]);
        parity ^= 1;
      }
    }
    auto q = c.p;
    for (std::size_t i = 0; i < T::N; ++i) q[i] = c.p[perm[i]];
    const int s = T::sos(c.p);
    RC_ASSERT(s != 0);
    RC_ASSERT(T::sos(q) == (parity ? -s : s));
    RC_TAG(parity ? "odd-permutation" : "even-permutation");
  });
}

#define CERTIMESH_PREDICATE_PROPERTIES(Traits, Suite)                                   \
  TEST(Suite, ExactMatchesOracleAndDegenerateShare) { exact_matches_oracle<Traits>(); } \
  TEST(Suite, FilterNeverContradictsOracle) { filter_never_contradicts<Traits>(); }     \
  TEST(Suite, Antisymmetry) { antisymmetry<Traits>(); }                                 \
  TEST(Suite, EvenPermutations) { even_permutations<Traits>(); }                        \
  TEST(Suite, TranslationByExactOffsets) { translation<Traits>(); }                     \
  TEST(Suite, PowerOfTwoScalingAndAxisNegation) { scaling_and_negation<Traits>(); }     \
  TEST(Suite, SosNonZeroAndEqualsExact) { sos_nonzero_and_consistent<Traits>(); }       \
  TEST(Suite, SosPermutations) { sos_permutations<Traits>(); }

CERTIMESH_PREDICATE_PROPERTIES(Orient2d, Orient2dProperties)
CERTIMESH_PREDICATE_PROPERTIES(Orient3d, Orient3dProperties)
CERTIMESH_PREDICATE_PROPERTIES(Incircle, IncircleProperties)
CERTIMESH_PREDICATE_PROPERTIES(Insphere, InsphereProperties)

}  // namespace
}  // namespace certimesh::test
