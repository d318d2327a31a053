// Stage 2 of the pipeline: the boundary at the requested size. A long segment is split into
// pieces whose lengths follow the size policy; its Steiner points are roundings of exact
// points of it (point_on_segment.h), so the certificate finds every one on its segment. In
// automatic mode (no size) the segments stay whole: the front grows from the given step.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/generators/size_policy.h"

namespace certimesh::generators::detail {

struct DiscretizedBoundary {
  std::vector<Point2> points;                 // the domain's points, then the Steiner points
  std::vector<DomainSegment> subsegments;     // each with its original segment's label
  std::vector<std::uint32_t> origin;          // the original segment of each subsegment
};

/// Splits every segment not marked in `keep_whole` (indexed by segment; may be empty).
/// Throws std::invalid_argument when the size policy gives a non-positive or non-finite
/// size, or would need more than `max_points` boundary points.
DiscretizedBoundary discretize_boundary(const PlanarDomain& domain, const SizePolicy& size,
                                        std::span<const std::uint8_t> keep_whole,
                                        std::uint64_t max_points = 100'000'000);

}  // namespace certimesh::generators::detail
