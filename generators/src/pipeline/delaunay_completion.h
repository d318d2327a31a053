// The reliable completion (monograph §3.7's idea in 2D): whatever region the advancing front
// leaves is a polygon bounded by the remaining front, whose edges do not cross (the front's
// triangles were accepted by exact or conservative tests that never err towards "disjoint").
// Its constrained Delaunay triangulation, with the front edges as constraints and no Steiner
// points, always exists (every polygon has a triangulation by diagonals) and fills it.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "certimesh/generators/advancing_front/advancing_front_2.h"

namespace certimesh::generators::detail {

/// Triangles (counterclockwise, ids into `points`) filling the region left of `front`, a
/// closed front, with the points `interior` (ids strictly inside that region, on no front
/// edge) as vertices too. Throws DelaunayError if the front's edges cross (an internal error).
std::vector<std::array<std::uint32_t, 3>> complete_by_delaunay(std::span<const Point2> points,
                                                               std::span<const FrontEdge> front,
                                                               std::span<const std::uint32_t> interior = {});

}  // namespace certimesh::generators::detail
