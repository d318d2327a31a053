// TetGen's hole and region points applied to the tetrahedralization of a solid (issue 13):
// the region of a point -- the tetrahedra reachable from the one that holds it without
// crossing a surface triangle -- is removed (a hole point) or labelled with the point's
// attribute (a region point, TetGen's -A). Holes first, then regions in input order (a later
// region point in the same region relabels it). Every decision is an exact orient3d.
//
// Cost (decision 9): O(T) for the face adjacency and the fills, plus O(T) per point to locate
// it (a box test, then exact signs) -- O((H + R) T) in the worst case, T tetrahedra, H hole
// and R region points.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>

#include "certimesh/generators/delaunay/tetrahedralization_3.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators {

/// A hole or region point the regions cannot take: on the surface (no side is its
/// region), in no tetrahedron (outside the solid, or in a hole already removed), or a region
/// attribute that is not an integer label; or hole points that remove the whole solid. The
/// message names the point and says which.
class SolidRegionsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct SolidRegionCounts {
  std::size_t hole_tetrahedra = 0;   // removed
  std::size_t labelled_tetrahedra = 0;
};

/// Applies the points to `solid` (its tetrahedra and labels; `surface` indexes solid.points,
/// the input points first as boundary recovery leaves them). Every surface triangle must be a
/// face of the tetrahedralization (boundary recovery's default mode).
SolidRegionCounts apply_holes_and_regions_3(Tetrahedralization3& solid,
                                            std::span<const std::array<std::uint32_t, 3>> surface,
                                            std::span<const predicates::Point3> holes,
                                            std::span<const predicates::Point3> region_points,
                                            std::span<const double> region_attributes);

}  // namespace certimesh::generators
