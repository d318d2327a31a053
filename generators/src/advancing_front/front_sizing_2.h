// The sizes of Algorithm 10 (digest B §3.6.4) and the packing bound they imply (§3.6.5).
//
// Modes, decided once from the SizePolicy:
//   A  (a size s(x,y) or a uniform size, growth == 1): s = max(l, s(midpoint of e12)),
//      r = s/2 ((3.3.2) with mu = 1/2, s0 = 0, sigma = 0), delta = min(d0, (sqrt3/4) s_min).
//   A' (a size and growth > 1): as A, but s <= growth * l -- our decision: the user's size
//      is the target and growth limits how fast the front may coarsen towards it (a size
//      function that jumps from the boundary step to 100x gives graded elements, not
//      slivers). s >= l still holds, but s no longer has the lower bound s_min, so r takes
//      mode B's parameters with s0 = min(d0, s_min): delta = (sqrt3/8) s0.
//   B  (no size): s = growth * l, r by (3.3.2) with mu = 1/2, s0 = d0, sigma = 2 d0,
//      delta = (sqrt3/8) d0.
// In every mode h = hc/2 with hc = sqrt(s^2 - l^2/4) the apex height, and s >= l.
//
// s_min is the smallest size the user function returned so far (a function is only known
// where it is evaluated): the bound is recomputed whenever it falls, so it is valid for the
// run as it happened. d0 is the least distance between two initial front vertices.
#pragma once

#include <cstdint>

#include "certimesh/generators/size_policy.h"

namespace certimesh::generators::advancing_front_detail {

/// What the bound (3.3.4) needs of the initial front.
struct FrontMeasure {
  double area = 0.0;             // S(P), the shoelace sum over the directed edges
  double perimeter = 0.0;        // p(P), cuts counted twice (still an upper bound)
  std::uint64_t components = 0;  // connected components of the front graph (>= K(P))
  double least_distance = 0.0;   // d0
};

/// (3.3.4): N_f <= 8 S/(pi delta^2) + 4 p/(pi delta) + 2 K - 5, saturated to 2^63.
std::uint64_t triangle_bound(const FrontMeasure& front, double delta);

struct ApexSize {
  double s;  // the desired side
  double h;  // no front point within h of the apex
  double r;  // no front vertex within r of the apex
};

class FrontSizing2 {
 public:
  /// Throws std::invalid_argument for growth < 1 or not finite, or a non-positive size.
  FrontSizing2(const SizePolicy& policy, double least_distance);

  /// The sizes for a front edge of length l with midpoint `mid`. Throws
  /// std::invalid_argument when the size function returns a non-positive or non-finite value.
  ApexSize at(double l, const Point2& mid);

  /// The current lower bound delta on the distance between mesh nodes.
  double delta() const;
  /// Whether delta() fell since the last call (then the bound must be recomputed).
  bool take_delta_change();

 private:
  double spacing_r(double s) const;

  SizePolicy policy_;
  bool user_size_ = false;
  bool growth_limited_ = false;
  double d0_ = 0.0;
  double s_min_ = 0.0;  // 0 until the first evaluation
  double s0_ = 0.0, sigma_ = 0.0;
  bool delta_changed_ = false;
};

}  // namespace certimesh::generators::advancing_front_detail
