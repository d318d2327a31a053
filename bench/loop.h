// The one timed loop every variant runs (certimesh_loops.cpp and cgal_peer.cpp both
// instantiate it), so all implementations pay exactly the same loop and call overhead:
// one out-of-line call per pass over the data set, the predicate itself inlined into
// the loop body whenever its implementation allows it.
#pragma once

#include <cstddef>
#include <cstdint>

namespace certimesh_bench {

/// Sum of f(tuple) over `ntuples` consecutive tuples of K points each.
template <std::size_t K, class P, class F>
inline long long sum_signs(const P* points, std::size_t ntuples, F f) {
  long long sum = 0;
  for (std::size_t i = 0; i < ntuples; ++i) sum += f(points + K * i);
  return sum;
}

/// The same loop, storing each sign instead of summing (for the start-up cross-check).
template <std::size_t K, class P, class F>
inline void store_signs(const P* points, std::size_t ntuples, std::int8_t* out, F f) {
  for (std::size_t i = 0; i < ntuples; ++i) out[i] = static_cast<std::int8_t>(f(points + K * i));
}

}  // namespace certimesh_bench
