// The desired element size: the monograph's s(x, y) (§3.3.3 mode A) or automatic growth by
// a factor γ ≥ 1 from the boundary step (mode B). Sizes are lengths (triangle sides), not
// areas; they steer the generators but decide nothing about validity.
#pragma once

#include <functional>

#include "certimesh/predicates/point.h"

namespace certimesh::generators {

using predicates::Point2;

/// A user size function: a positive finite length at every point of the domain.
using SizeFunction2 = std::function<double(const Point2&)>;

struct SizePolicy {
  /// s(x, y); when empty, `uniform_size` is used if positive, otherwise automatic growth.
  SizeFunction2 size_function;
  /// A constant size (the CLI's --size H); 0 = none.
  double uniform_size = 0.0;
  /// γ of mode B: the new side is γ times the front edge; ≥ 1. Used when no size is given,
  /// and as a limit on how fast sizes may grow away from the boundary when one is.
  double growth = 1.0;

  bool automatic() const { return !size_function && !(uniform_size > 0.0); }
  /// The size at p, or 0 in automatic mode.
  double at(const Point2& p) const {
    if (size_function) return size_function(p);
    return uniform_size > 0.0 ? uniform_size : 0.0;
  }
};

}  // namespace certimesh::generators
