// The plain byte decoder of fuzz/generators (the libFuzzer target's input path), run on
// seeded random byte strings so that the regular suite covers it without clang: the same
// differential checks as fuzz/targets/predicates_fuzz.cpp.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "certimesh/predicates/non_finite_input.h"
#include "support.h"

namespace certimesh::test {
namespace {

template <class T>
void check(const typename T::Pts& p, long& non_finite, long& zeros) {
  bool finite = true;
  for (const auto& q : p)
    for (double v : q) finite = finite && std::isfinite(v);
  if (!finite) {
    ++non_finite;
    EXPECT_EQ(T::filtered(p), 0);
    EXPECT_THROW(T::exact(p), pr::NonFiniteInput);
    EXPECT_THROW(T::sos(p), pr::NonFiniteInput);
    return;
  }
  const int o = T::oracle(p);
  zeros += o == 0;
  const int f = T::filtered(p);
  ASSERT_TRUE(f == 0 || f == o) << T::name;
  ASSERT_EQ(T::exact(p), o) << T::name;
  const int s = T::sos(p);
  if (o != 0) {
    ASSERT_EQ(s, o) << T::name;
  }
  if (!has_duplicate(p)) {
    ASSERT_NE(s, 0) << T::name;
  }
}

TEST(FuzzDecoder, SeededRandomBytes) {
  const std::uint64_t seed = base_seed();
  std::cout << "[fuzz decoder] seed=" << seed << std::endl;
  std::mt19937_64 rng(seed);
  long per_predicate[4] = {}, non_finite = 0, zeros = 0;
  const int inputs = scaled(20000);
  for (int n = 0; n < inputs; ++n) {
    std::vector<std::uint8_t> bytes(rng() % 256);
    for (auto& b : bytes) b = static_cast<std::uint8_t>(rng());
    const fz::DecodedInput in = fz::decode(bytes.data(), bytes.size());
    ++per_predicate[in.predicate];
    switch (in.predicate) {
      case 0: check<Orient2d>(in.o2.p, non_finite, zeros); break;
      case 1: check<Orient3d>(in.o3.p, non_finite, zeros); break;
      case 2: check<Incircle>(in.ic.p, non_finite, zeros); break;
      default: check<Insphere>(in.is.p, non_finite, zeros); break;
    }
    if (HasFatalFailure()) return;
  }
  std::cout << "[fuzz decoder] " << inputs << " inputs: orient2d " << per_predicate[0]
            << ", orient3d " << per_predicate[1] << ", incircle " << per_predicate[2]
            << ", insphere " << per_predicate[3] << "; exact zeros " << zeros
            << ", non-finite " << non_finite << std::endl;
  for (long c : per_predicate) EXPECT_GT(c, 0);
  EXPECT_GT(non_finite, 0);
  EXPECT_GT(zeros, inputs / 5);
}

TEST(FuzzDecoder, EmptyAndShortInputsDecode) {
  const std::uint8_t one = 3;
  const fz::DecodedInput a = fz::decode(nullptr, 0);
  const fz::DecodedInput b = fz::decode(&one, 1);
  EXPECT_EQ(a.predicate, 0);
  EXPECT_EQ(b.predicate, 3);
  long nf = 0, z = 0;
  check<Orient2d>(a.o2.p, nf, z);
  check<Insphere>(b.is.p, nf, z);
}

}  // namespace
}  // namespace certimesh::test
