// Golden-section search for the best star quality over a one-parameter family of positions:
// a node moved along a direction (node shift) or along its input segment (boundary slide).
// Positions only steer: every candidate the search returns is still checked exactly by the
// caller before it is committed.
#pragma once

#include <numbers>
#include <utility>

namespace certimesh::topology::local {

inline constexpr int golden_section_steps = 40;

/// Searches (lo, hi) for the parameter of greatest quality(x) by golden-section steps and
/// returns the best parameter evaluated with its quality, or {no_move, q0} when none beats q0
/// (the quality along a line need not be unimodal: the best point seen is kept, not the
/// final bracket).
template <class Quality>
std::pair<double, double> golden_section_best(Quality&& quality, double lo, double hi, double q0, double no_move) {
  constexpr double ratio = std::numbers::phi - 1.0;
  double x1 = hi - ratio * (hi - lo), x2 = lo + ratio * (hi - lo);
  double f1 = quality(x1), f2 = quality(x2);
  double best_x = no_move, best_q = q0;
  const auto consider = [&](double x, double q) {
    if (q > best_q) best_x = x, best_q = q;
  };
  consider(x1, f1);
  consider(x2, f2);
  for (int step = 0; step < golden_section_steps; ++step) {
    if (f1 < f2) {
      lo = x1, x1 = x2, f1 = f2;
      x2 = lo + ratio * (hi - lo);
      f2 = quality(x2);
      consider(x2, f2);
    } else {
      hi = x2, x2 = x1, f2 = f1;
      x1 = hi - ratio * (hi - lo);
      f1 = quality(x1);
      consider(x1, f1);
    }
  }
  return {best_x, best_q};
}

}  // namespace certimesh::topology::local
