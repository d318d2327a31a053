// The perturbed (SoS) orientation and in-circle signs the Delaunay triangulation decides
// with, as ints. The filter is inline here, on the hot path; when it is uncertain the
// kernel's orient2d_sos / incircle_sos decide (their exact stage once, then the perturbation
// only for an exact zero; before, an exact zero ran the exact stage twice), GMP-free for
// these 2D predicates (predicates/src/sos_2d.cpp; tests/predicates/sos_2d_test.cpp checks them
// against the generic perturbation on every degenerate ordering of small grids).
#pragma once

#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/orient2d.h"

namespace certimesh::generators::detail {

using predicates::Point2;

/// The perturbed orientation: 0 only for equal points.
inline int orient_perturbed(const Point2& a, const Point2& b, const Point2& c) {
  const predicates::FilteredSign f = predicates::orient2d_filtered(a, b, c);
  if (predicates::is_certain(f)) [[likely]]
    return predicates::to_int(f);
  return predicates::to_int(predicates::orient2d_sos(a, b, c));
}

/// The perturbed in-circle sign of d against (a, b, c): 0 only when d equals one of them.
inline int incircle_perturbed(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const predicates::FilteredSign f = predicates::incircle_filtered(a, b, c, d);
  if (predicates::is_certain(f)) [[likely]]
    return predicates::to_int(f);
  return predicates::to_int(predicates::incircle_sos(a, b, c, d));
}

}  // namespace certimesh::generators::detail
