// The one way every public test chooses between its sign sources and the fallback.
#pragma once

#include "certimesh/predicates/intersection/mode.h"
#include "degenerate.h"
#include "exact_fallback.h"
#include "sign_source.h"

namespace certimesh::predicates::intersection_detail {

/// `Rules` is a class template's static member call: Rules<Signs>::run(a, b).
template <template <class> class Rules, class A, class B>
Overlap dispatch(const A& a, const B& b, IntersectionMode mode, const char* name) {
  if (mode == IntersectionMode::conservative) {
    // NaN compares false everywhere, but max/min would still hand out a number.
    if (!all_finite(a) || !all_finite(b)) return Overlap::intersect;
    return Rules<FilteredSigns>::run(a, b);
  }
  require_finite(a, b, name);
  if (degenerate(a) || degenerate(b))
    return exact_overlap(lift(a), lift(b)) ? Overlap::intersect : Overlap::disjoint;
  return Rules<ExactSigns>::run(a, b);
}

}  // namespace certimesh::predicates::intersection_detail
