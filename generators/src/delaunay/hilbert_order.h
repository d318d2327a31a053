// The insertion order of the incremental Delaunay triangulation: points sorted along a
// Hilbert curve over their bounding box, so consecutive insertions are close and the walk
// from the last triangle is short. Deterministic: ties (same curve cell) keep index order.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "certimesh/generators/delaunay/large_array.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators::detail {

/// The indices of `points` (all finite) in Hilbert-curve order.
std::vector<std::uint32_t, LargeArrayAllocator<std::uint32_t>> hilbert_order(std::span<const predicates::Point2> points);

}  // namespace certimesh::generators::detail
