// incircle(a, b, c, d): the sign of the lifted determinant
//   det[a - d, |a - d|^2; b - d, |b - d|^2; c - d, |c - d|^2].
// With a, b, c counterclockwise: positive when d lies inside their circumcircle, negative
// outside, zero on it. With a, b, c clockwise every sign is reversed.
//
// Properties (each one a test in tests/predicates/algebraic_properties_test.cpp):
//   (IC.1) antisymmetry: swapping any two arguments negates the sign.
//   (IC.2) even permutations leave the sign unchanged.
//   (IC.3) translation by a common vector, every sum exact, leaves the sign unchanged.
//   (IC.4) scaling every coordinate by 2^k (no overflow or underflow) leaves it unchanged;
//          negating one axis negates it.
//   (IC.5) exact zero exactly when the four points are cocircular or collinear.
//   (IC.6) incircle_filtered is uncertain or equal to incircle.
//   (IC.7) SoS: incircle_sos is never zero for distinct points, equals incircle when that is
//          non-zero, and obeys (IC.1) and (IC.2).
#pragma once

#include "certimesh/predicates/detail/exact_stages.h"
#include "certimesh/predicates/detail/filters.h"
#include "certimesh/predicates/point.h"
#include "certimesh/predicates/sign.h"
#include "certimesh/predicates/symbolic_perturbation.h"

namespace certimesh::predicates {

/// The monograph's conservative sign d(): positive or negative only when that is the
/// exact sign, uncertain otherwise. Never throws; NaN or infinite input is uncertain.
inline FilteredSign incircle_filtered(const Point2& a, const Point2& b, const Point2& c, const Point2& d) noexcept {
#if CERTIMESH_FILTERS_OUT_OF_LINE
  return detail::incircle_filter_out_of_line(a, b, c, d);
#else
  return detail::incircle_filter(a, b, c, d);
#endif
}

/// The exact sign: the filter, then the exact stage when the filter is uncertain.
/// Throws NonFiniteInput for NaN or infinite coordinates.
inline Sign incircle(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const FilteredSign s = incircle_filtered(a, b, c, d);
  if (is_certain(s)) return certain_sign(s);
  return detail::incircle_exact_stage(a, b, c, d);
}

/// The symbolically perturbed sign (simulation of simplicity, symbolic_perturbation.h):
/// the exact sign when it is not zero; otherwise the sign after an infinitesimal,
/// input-independent perturbation of the points. Zero only when two arguments are the
/// same point. Throws NonFiniteInput for NaN or infinite coordinates.
Sign incircle_sos(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

}  // namespace certimesh::predicates
