// orient2d(a, b, c): the sign of det[a - c; b - c] = (ax-cx)(by-cy) - (ay-cy)(bx-cx).
// Positive when a, b, c turn counterclockwise, negative when clockwise, zero when collinear.
//
// Properties (each one a test in tests/predicates/algebraic_properties_test.cpp):
//   (O2.1) antisymmetry: swapping any two arguments negates the sign.
//   (O2.2) cyclic invariance: orient2d(a, b, c) == orient2d(b, c, a) == orient2d(c, a, b).
//   (O2.3) translation: adding the same vector t to a, b and c leaves the sign unchanged
//          whenever every sum is exact in double.
//   (O2.4) scaling: multiplying every coordinate by 2^k (no overflow or underflow) leaves
//          the sign unchanged; multiplying one axis by -1 negates it.
//   (O2.5) exact zero: orient2d is zero exactly when the points are collinear.
//   (O2.6) the filter never contradicts the exact sign: orient2d_filtered is uncertain or
//          equal to orient2d.
//   (O2.7) SoS: orient2d_sos is never zero for distinct points, equals orient2d when that is
//          non-zero, and obeys (O2.1) and (O2.2).
#pragma once

#include "certimesh/predicates/detail/exact_stages.h"
#include "certimesh/predicates/detail/filters.h"
#include "certimesh/predicates/point.h"
#include "certimesh/predicates/sign.h"
#include "certimesh/predicates/symbolic_perturbation.h"

namespace certimesh::predicates {

/// The monograph's conservative sign d(): positive or negative only when that is the
/// exact sign, uncertain otherwise. Never throws; NaN or infinite input is uncertain.
inline FilteredSign orient2d_filtered(const Point2& a, const Point2& b, const Point2& c) noexcept {
#if CERTIMESH_FILTERS_OUT_OF_LINE
  return detail::orient2d_filter_out_of_line(a, b, c);
#else
  return detail::orient2d_filter(a, b, c);
#endif
}

/// The exact sign: the filter, then the exact stage when the filter is uncertain.
/// Throws NonFiniteInput for NaN or infinite coordinates.
inline Sign orient2d(const Point2& a, const Point2& b, const Point2& c) {
  const FilteredSign s = orient2d_filtered(a, b, c);
  if (is_certain(s)) return certain_sign(s);
  return detail::orient2d_exact_stage(a, b, c);
}

/// The symbolically perturbed sign (simulation of simplicity, symbolic_perturbation.h):
/// the exact sign when it is not zero; otherwise the sign after an infinitesimal,
/// input-independent perturbation of the points. Zero only when two arguments are the
/// same point. Throws NonFiniteInput for NaN or infinite coordinates.
Sign orient2d_sos(const Point2& a, const Point2& b, const Point2& c);

}  // namespace certimesh::predicates
