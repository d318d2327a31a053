// The answers a predicate gives.
//
// Three answers, not two (design decision 3): a floating-point filter answers
// positive, negative or *uncertain*; only an exact stage answers zero; a symbolically
// perturbed predicate never answers zero for distinct points.
#pragma once

#include <cstdint>

namespace certimesh::predicates {

/// Exact sign of a determinant.
enum class Sign : std::int8_t { negative = -1, zero = 0, positive = 1 };

/// What a conservative filter (the monograph's d()) knows about a sign: it answers
/// `positive` or `negative` only when that is the exact sign, `uncertain` otherwise.
enum class FilteredSign : std::int8_t { negative = -1, uncertain = 0, positive = 1 };

constexpr int to_int(Sign s) noexcept { return static_cast<int>(s); }
constexpr int to_int(FilteredSign s) noexcept { return static_cast<int>(s); }

constexpr Sign operator-(Sign s) noexcept { return static_cast<Sign>(-to_int(s)); }
constexpr FilteredSign operator-(FilteredSign s) noexcept {
  return static_cast<FilteredSign>(-to_int(s));
}
constexpr Sign operator*(Sign a, Sign b) noexcept {
  return static_cast<Sign>(to_int(a) * to_int(b));
}

constexpr Sign sign_of_int(int v) noexcept {
  return v > 0 ? Sign::positive : (v < 0 ? Sign::negative : Sign::zero);
}

/// A certain filter answer as an exact sign; `uncertain` has none.
constexpr bool is_certain(FilteredSign s) noexcept { return s != FilteredSign::uncertain; }
constexpr Sign certain_sign(FilteredSign s) noexcept { return static_cast<Sign>(to_int(s)); }

}  // namespace certimesh::predicates
