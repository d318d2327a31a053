// A degenerate element as non-degenerate simplices (exact_fallback.h).
//
// The element is the hull of its distinct points. The pieces triangulate that hull using
// every point as a vertex, and have the shared simplex sigma (one point, or a segment
// with no element point strictly inside it: such points are dropped first, the hull does
// not change) as a face. So each piece meets sigma in the face spanned by its vertices in
// sigma, and that is what lets shared vertices be handled piece by piece.
#pragma once

#include <algorithm>
#include <span>
#include <vector>

#include "certimesh/predicates/point.h"

namespace certimesh::predicates::intersection_detail {

using Simplex = std::vector<Point3>;

/// Whether p is one of the points of `set` (exact coordinates); simplex_pieces.cpp and
/// exact_fallback.cpp both ask it.
inline bool contains_point(std::span<const Point3> set, const Point3& p) {
  return std::find(set.begin(), set.end(), p) != set.end();
}

/// `points`: the element's distinct points (at most 4); `sigma`: the distinct shared
/// points (at most 2), all among `points`.
std::vector<Simplex> simplex_pieces(std::vector<Point3> points, std::span<const Point3> sigma);

}  // namespace certimesh::predicates::intersection_detail
