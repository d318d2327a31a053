// Seeds and random draws of a campaign. Case i of a campaign with seed K draws from
// splitmix64(K ^ splitmix64(i)): any case can be re-run alone from (K, i), and a shard of
// indices gives the same cases whatever thread runs it.
#pragma once

#include <cstdint>

namespace certimesh::fuzz::campaign {

/// Vigna's SplitMix64 step: the golden-ratio increment, then the finaliser.
constexpr std::uint64_t splitmix64(std::uint64_t x) noexcept {
  std::uint64_t z = x + 0x9e3779b97f4a7c15ull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

constexpr std::uint64_t case_seed(std::uint64_t campaign_seed, std::uint64_t case_index) noexcept {
  return splitmix64(campaign_seed ^ splitmix64(case_index));
}

/// The draw source recipes.h asks for (below(n), bits()), as a SplitMix64 stream.
class SplitMixSource {
 public:
  explicit SplitMixSource(std::uint64_t seed) noexcept : state_(seed) {}

  std::uint64_t bits() noexcept {
    state_ += 0x9e3779b97f4a7c15ull;
    std::uint64_t z = state_;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }

  /// Uniform in [0, n) by rejection (no modulo bias: the recipes' rare branches keep their
  /// stated odds); 0 for n <= 1.
  std::uint64_t below(std::uint64_t n) noexcept {
    if (n <= 1) return 0;
    const std::uint64_t limit = ~std::uint64_t{0} - (~std::uint64_t{0} % n);
    std::uint64_t v = bits();
    while (v >= limit) v = bits();
    return v % n;
  }

 private:
  std::uint64_t state_;
};

}  // namespace certimesh::fuzz::campaign
