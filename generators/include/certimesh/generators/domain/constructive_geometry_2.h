// Constructive geometry of planar regions: rectangles, discs (discretized with a step) and
// simple polygons, combined by union, difference and intersection, then turned into a
// PlanarDomain. The boolean operations are Boost.Geometry's (in the .cpp only: Boost is a
// private dependency); their output coordinates are Boost's double constructions, so the
// result is a polygon through those points, and to_planar_domain validates it exactly.
#pragma once

#include <vector>

#include "certimesh/generators/domain/planar_domain.h"

namespace certimesh::generators {

/// A polygon with holes: the outer ring counterclockwise, inner rings clockwise; rings are
/// open (the first point is not repeated at the end).
struct PolygonWithHoles2 {
  std::vector<Point2> outer;
  std::vector<std::vector<Point2>> inners;
};

/// A region: polygons with pairwise disjoint interiors (Boost's multi-polygon).
struct Region2 {
  std::vector<PolygonWithHoles2> polygons;
};

/// [x0, x1] x [y0, y1]; throws std::invalid_argument unless x0 < x1 and y0 < y1, finite.
Region2 rectangle_region(double x0, double y0, double x1, double y1);

/// The disc as the polygon of discretize_circle(centre, radius, step) (curves_2.h).
Region2 disc_region(Point2 centre, double radius, double step);

/// A simple polygon through `vertices` (either orientation, >= 3 points, not closed);
/// throws std::invalid_argument naming Boost's reason when it is not simple.
Region2 polygon_region(const std::vector<Point2>& vertices);

Region2 region_union(const Region2& a, const Region2& b);
Region2 region_difference(const Region2& a, const Region2& b);
Region2 region_intersection(const Region2& a, const Region2& b);

/// The area (Boost's, in double).
double region_area(const Region2& region);

/// The region as a domain: every ring's points (bit-identical points merged into one vertex),
/// its edges as segments labelled `label`, and a hole point strictly inside every inner ring
/// (checked exactly). Throws InvalidDomain (domain_problem.h) when the region is empty or the
/// result fails validate_domain (e.g. rings Boost left touching).
PlanarDomain to_planar_domain(const Region2& region, io::Label label = 1);

}  // namespace certimesh::generators
