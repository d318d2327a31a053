// The desired element size: the monograph's s(x, y) (§3.3.3 mode A) or automatic growth by
// a factor γ ≥ 1 from the boundary step (mode B). Sizes are lengths (triangle sides), not
// areas; they steer the generators but decide nothing about validity.
//
// The 2D pipeline (mesh_domain_2.h) adds a third reading, its default: the boundary-adapted
// size. Without a size function it builds
//     h(x) = min(H, min_i (lfs_i + g·|x − p_i|))
// over the domain's points p_i, where lfs_i is p_i's local feature size (the distance to its
// nearest neighbour in the constrained Delaunay triangulation of the domain -- its own
// segments' lengths included -- and to the nearest segment opposite it there), g = `grading`
// and H = `uniform_size` when given, else `default_maximum_fraction` of the domain's
// bounding-box diagonal (generators/src/pipeline/boundary_size_field.h). Short segments then
// force small sizes only near themselves, long ones are split to the local size, and the
// size grows away from the boundary by at most g per unit of distance.
#pragma once

#include <functional>

#include "certimesh/predicates/point.h"

namespace certimesh::generators {

using predicates::Point2;

/// A user size function: a positive finite length at every point of the domain.
using SizeFunction2 = std::function<double(const Point2&)>;

/// g of the boundary-adapted size: how much the size may grow per unit of distance from the
/// boundary. 0.25 gives layers whose sides grow by about 25 % of their height per layer.
inline constexpr double default_grading = 0.25;
/// The boundary-adapted size's maximum when no --size is given: this fraction of the diagonal
/// of the domain's bounding box (Gmsh's default characteristic length is of the same order).
inline constexpr double default_maximum_fraction = 0.1;

struct SizePolicy {
  /// s(x, y); when empty, `uniform_size` is used if positive, otherwise automatic growth.
  SizeFunction2 size_function;
  /// A constant size (the CLI's --size H); 0 = none. In the pipeline with grading > 0 it is
  /// the largest size of the boundary-adapted size instead.
  double uniform_size = 0.0;
  /// γ of mode B: the new side is γ times the front edge; ≥ 1. Used when no size is given,
  /// and as a limit on how fast sizes may grow away from the boundary when one is.
  double growth = 1.0;
  /// g of the boundary-adapted size (see above), read by mesh_domain_2 only, when no
  /// size_function is given; 0 = off (then `uniform_size` everywhere, or mode B without it).
  double grading = default_grading;

  bool automatic() const { return !size_function && !(uniform_size > 0.0); }
  /// The size at p, or 0 in automatic mode.
  double at(const Point2& p) const {
    if (size_function) return size_function(p);
    return uniform_size > 0.0 ? uniform_size : 0.0;
  }
};

}  // namespace certimesh::generators
