// Internal: whether a mesh vertex lies on a domain segment / triangle (design decision 2): the
// simplex meets the vertex's rounding box (the reals that round to it), or the wider box a
// boundary tolerance allows; every decision exact.
#pragma once

#include <array>

#include "mesh_view.h"

namespace certimesh::certificate::detail {

/// Whether p lies exactly on the segment (s[2] null) or triangle `s`.
bool lies_exactly_on(const std::array<const double*, 3>& s, int dim, const double* p);

/// Whether the segment / triangle `s` meets p's rounding box, widened by `tol`, for a point
/// already tested with lies_exactly_on (a point exactly on `s` is on it by this rule too; the
/// callers report exactness apart, so it is decided once).
bool meets_accepted_box(const std::array<const double*, 3>& s, int dim, const double* p, const BoundaryTolerance& tol);

/// A double box that contains every point meets_accepted_box accepts for p (for the broad phase).
Box accepted_bounds(const double* p, int dim, const BoundaryTolerance& tol);

}  // namespace certimesh::certificate::detail
