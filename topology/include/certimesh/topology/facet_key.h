// The identity of a facet independent of orientation and of the element that holds it: its
// vertex indices sorted. Two elements share a facet exactly when their keys are equal, which
// is what the facet table and the brute-force checks pair on.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace certimesh::topology {

template <int VerticesPerFacet>
using FacetKey = std::array<std::uint32_t, VerticesPerFacet>;

template <int VerticesPerFacet>
constexpr FacetKey<VerticesPerFacet> sorted_key(FacetKey<VerticesPerFacet> key) noexcept {
  std::sort(key.begin(), key.end());
  return key;
}

/// A value hash (no pointers, no per-process seed): iteration order of a table keyed by it
/// never leaks into results anyway, but the probe counts the tests read stay reproducible.
struct FacetKeyHash {
  template <std::size_t N>
  std::size_t operator()(const std::array<std::uint32_t, N>& key) const noexcept {
    std::uint64_t h = 0x9E3779B97F4A7C15ull;
    for (const std::uint32_t v : key) {
      h ^= v;
      h *= 0xFF51AFD7ED558CCDull;  // murmur3 finaliser constant: mixes low bits upward
      h ^= h >> 33;
    }
    return static_cast<std::size_t>(h);
  }
};

/// Key equality that counts how often it is asked: the number of stored keys a lookup
/// compares against, which is the work measure the tests bound (no timing in unit tests).
/// The count lives in the functor, so it moves and copies with the table that owns it.
struct CountingFacetKeyEqual {
  mutable std::uint64_t comparisons = 0;
  template <std::size_t N>
  bool operator()(const std::array<std::uint32_t, N>& a, const std::array<std::uint32_t, N>& b) const noexcept {
    ++comparisons;
    // Element by element: std::array's == becomes an out-of-line memcmp call here.
    for (std::size_t k = 0; k < N; ++k)
      if (a[k] != b[k]) return false;
    return true;
  }
};

}  // namespace certimesh::topology
