// Triangle's -c for a planar domain: the convex hull of all its points becomes its outer
// boundary. The hull is Andrew's monotone chain with exact orient2d, every input point on the
// hull kept as a hull vertex (a point inside a hull edge would otherwise be a T-junction); each
// hull edge that is not already a segment is added, with marker 1 (Triangle's marker for
// boundary segments that have none). Then the domain is meshed as usual: holes still eat, and
// what lay outside the old segments but inside the hull is now domain.
#pragma once

#include <cstddef>

#include "certimesh/generators/domain/planar_domain.h"

namespace certimesh::generators {

/// `domain` with its convex hull's edges added as segments; `added`, when given, receives
/// their number. Fewer than three non-collinear points: the domain unchanged.
PlanarDomain with_convex_hull(const PlanarDomain& domain, std::size_t* added = nullptr);

}  // namespace certimesh::generators
