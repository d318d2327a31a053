// The insertion order of the incremental Delaunay triangulation: a biased randomized
// insertion order (BRIO, Amenta, Choi and Rote 2003) with each round sorted along a Hilbert
// curve over the bounding box (a cube: one scale for every axis). Each point index goes to a round by a fixed hash (splitmix64's
// finaliser): the last round holds about 3/4 of the points, the one before 3/16, and so on,
// floor(log4(n / 64)) rounds before the last. Consecutive insertions are close, so the walk
// from the last triangle is short, and each round fills in a triangulation of a random
// sample, so the cavities stay as small as a random order's: on 10^6 uniform points 9.2
// in-circle tests per insertion against 12.6 for the Hilbert order alone, on the 1000 x 1000
// grid 9.2 against 22.6. Deterministic: ties (same round and curve cell) keep index order.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "certimesh/generators/delaunay/large_array.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators::detail {

/// The indices of `points` (all finite) in insertion order (rounds, each along the curve).
std::vector<std::uint32_t, LargeArrayAllocator<std::uint32_t>> hilbert_order(std::span<const predicates::Point2> points);

/// The same in 3D (Delaunay3): rounds as above, each along a 3D Hilbert curve.
std::vector<std::uint32_t, LargeArrayAllocator<std::uint32_t>> hilbert_order_3(std::span<const predicates::Point3> points);

}  // namespace certimesh::generators::detail
