// orient3d(a, b, c, d): the sign of det[a - d; b - d; c - d].
// Positive when d lies below the plane through a, b, c seen counterclockwise from above
// (Shewchuk's convention). A tetrahedron (a, b, c, d) of positive volume in the Medit/Gmsh
// sense has orient3d(a, b, c, d) < 0: use volume_sign() (volume_sign.h) for that meaning.
//
// Properties (each one a test in tests/predicates/algebraic_properties_test.cpp):
//   (O3.1) antisymmetry: swapping any two arguments negates the sign.
//   (O3.2) even permutations leave the sign unchanged.
//   (O3.3) translation by a common vector, every sum exact, leaves the sign unchanged.
//   (O3.4) scaling every coordinate by 2^k (no overflow or underflow) leaves it unchanged;
//          negating one axis negates it.
//   (O3.5) exact zero exactly when the four points are coplanar.
//   (O3.6) orient3d_filtered is uncertain or equal to orient3d.
//   (O3.7) SoS: orient3d_sos is never zero for distinct points, equals orient3d when that is
//          non-zero, and obeys (O3.1) and (O3.2).
#pragma once

#include "certimesh/predicates/detail/exact_stages.h"
#include "certimesh/predicates/detail/filters.h"
#include "certimesh/predicates/point.h"
#include "certimesh/predicates/sign.h"
#include "certimesh/predicates/symbolic_perturbation.h"

namespace certimesh::predicates {

/// The monograph's conservative sign d(): positive or negative only when that is the
/// exact sign, uncertain otherwise. Never throws; NaN or infinite input is uncertain.
inline FilteredSign orient3d_filtered(const Point3& a, const Point3& b, const Point3& c, const Point3& d) noexcept {
#if CERTIMESH_FILTERS_OUT_OF_LINE
  return detail::orient3d_filter_out_of_line(a, b, c, d);
#else
  return detail::orient3d_filter(a, b, c, d);
#endif
}

/// The exact sign: the filter, then the exact stage when the filter is uncertain.
/// Throws NonFiniteInput for NaN or infinite coordinates.
inline Sign orient3d(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const FilteredSign s = orient3d_filtered(a, b, c, d);
  if (is_certain(s)) return certain_sign(s);
  return detail::orient3d_exact_stage(a, b, c, d);
}

/// The symbolically perturbed sign (simulation of simplicity, symbolic_perturbation.h):
/// the exact sign when it is not zero; otherwise the sign after an infinitesimal,
/// input-independent perturbation of the points. Zero only when two arguments are the
/// same point. Throws NonFiniteInput for NaN or infinite coordinates.
Sign orient3d_sos(const Point3& a, const Point3& b, const Point3& c, const Point3& d);

}  // namespace certimesh::predicates
