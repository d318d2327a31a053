// Exact: do the convex hulls of two finite point sets meet? Any points: repeated,
// collinear, coplanar. The exact fallback's base test (exact_fallback.h).
//
// Method: work in a frame where the union is full-dimensional (affine_frame.h). Two
// hulls there are disjoint iff some hyperplane spanned by points of the union weakly
// separates them with disjoint touching parts (the weakly separating hyperplanes form a
// pointed cone whose extreme rays touch d affinely independent points; and for any weakly
// separating H, hull(P) n hull(Q) = hull(P n H) n hull(Q n H)). So the first weakly
// separating hyperplane found decides, by recursion one dimension down; if none exists the
// hulls meet.
#pragma once

#include <span>

#include "affine_frame.h"

namespace certimesh::predicates::intersection_detail {

bool hulls_intersect(std::span<const Point3> p, std::span<const Point3> q,
                     const Frame& ambient = space_frame);

}  // namespace certimesh::predicates::intersection_detail
