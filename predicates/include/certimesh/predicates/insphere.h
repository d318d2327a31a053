// insphere(a, b, c, d, e): the sign of the lifted determinant
//   det[a - e, |a - e|^2; b - e, |b - e|^2; c - e, |c - e|^2; d - e, |d - e|^2].
// With orient3d(a, b, c, d) > 0: positive when e lies inside the sphere through a, b, c, d,
// negative outside, zero on it. With orient3d(a, b, c, d) < 0 every sign is reversed.
//
// Properties (each one a test in tests/predicates/algebraic_properties_test.cpp):
//   (IS.1) antisymmetry: swapping any two arguments negates the sign.
//   (IS.2) even permutations leave the sign unchanged.
//   (IS.3) translation by a common vector, every sum exact, leaves the sign unchanged.
//   (IS.4) scaling every coordinate by 2^k (no overflow or underflow) leaves it unchanged;
//          negating one axis negates it.
//   (IS.5) exact zero exactly when the five points are cospherical or coplanar.
//   (IS.6) insphere_filtered is uncertain or equal to insphere.
//   (IS.7) SoS: insphere_sos is never zero for distinct points, equals insphere when that is
//          non-zero, and obeys (IS.1) and (IS.2).
#pragma once

#include "certimesh/predicates/detail/exact_stages.h"
#include "certimesh/predicates/detail/filters.h"
#include "certimesh/predicates/point.h"
#include "certimesh/predicates/sign.h"
#include "certimesh/predicates/symbolic_perturbation.h"

namespace certimesh::predicates {

/// The monograph's conservative sign d(): positive or negative only when that is the
/// exact sign, uncertain otherwise. Never throws; NaN or infinite input is uncertain.
inline FilteredSign insphere_filtered(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) noexcept {
#if CERTIMESH_FILTERS_OUT_OF_LINE
  return detail::insphere_filter_out_of_line(a, b, c, d, e);
#else
  return detail::insphere_filter(a, b, c, d, e);
#endif
}

/// The exact sign: the filter, then the exact stage when the filter is uncertain.
/// Throws NonFiniteInput for NaN or infinite coordinates.
inline Sign insphere(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
  const FilteredSign s = insphere_filtered(a, b, c, d, e);
  if (is_certain(s)) return certain_sign(s);
  return detail::insphere_exact_stage(a, b, c, d, e);
}

/// The symbolically perturbed sign (simulation of simplicity, symbolic_perturbation.h):
/// the exact sign when it is not zero; otherwise the sign after an infinitesimal,
/// input-independent perturbation of the points. Zero only when two arguments are the
/// same point. Throws NonFiniteInput for NaN or infinite coordinates.
Sign insphere_sos(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e);

}  // namespace certimesh::predicates
