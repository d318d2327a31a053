// The regional maximum area of a Triangle .poly (the last column of the regions section),
// as a guarantee: every triangle of such a region ends with area at most the bound. The last
// stage of the pipeline (after the improvement, whose collapses could grow a triangle again)
// bisects the longest edge of every triangle above its bound, and the triangle across that
// edge with it (so the mesh stays conforming), until none is. A new point on a boundary or
// cut edge is the rounding of an exact point of its input segment (design decision 2). Each
// bisection halves an area, so a triangle of area S needs O(S / bound) splits: the cost is
// linear in the output.
#pragma once

#include <span>

#include "boundary_discretization.h"
#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/generators/size_policy.h"
#include "improvement_region.h"

namespace certimesh::generators::detail {

/// The size policy that makes the generators aim at the regions' maximum areas: inside a
/// region with bound A at most 0.8 times the side of an equilateral triangle of area A, elsewhere
/// `size` (or, when `size` is automatic, twice the largest such side, at most the longest
/// input segment: then the whole mesh is sized, so that sizes grade across region interfaces). `size` itself when no region has a bound. The region of
/// a point comes from a walk in the constrained Delaunay triangulation of `domain` (regions
/// labelled by their 1-based index, as inside the pipeline), from where the previous query
/// ended: a few steps for the generators' nearby queries, O(number of input vertices) per query
/// in the worst case.
SizePolicy size_for_max_areas(const SizePolicy& size, const PlanarDomain& domain, std::span<const double> max_area);

/// Whether the area of triangle (a, b, c) is certainly at most `bound` (> 0): the doubled area
/// from orient2d's determinant, with its rounding error bound and a relative margin of 1e-12
/// (so the answer holds whether the bound means the double or the decimal it was read from).
bool area_within(const Point2& a, const Point2& b, const Point2& c, double bound);

/// Splits until every triangle t with max_area[mesh.labels[t]] > 0 (labels index the span;
/// others have no bound) is area_within it. `boundary` gains the new subsegments; `domain`
/// gives the input segments (boundary.origin). Returns the number of bisections.
std::uint64_t enforce_max_areas(TriangleSoup& mesh, DiscretizedBoundary& boundary, const PlanarDomain& domain,
                                std::span<const double> max_area);

}  // namespace certimesh::generators::detail
