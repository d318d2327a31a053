// The initial front, checked and measured: what the bound (3.3.4) needs (front_sizing_2.h),
// and the refusal of fronts Algorithm 10 cannot take, each naming the edge or vertices.
#pragma once

#include <span>

#include "certimesh/generators/advancing_front/advancing_front_2.h"
#include "front_sizing_2.h"

namespace certimesh::generators::advancing_front_detail {

/// Throws std::invalid_argument when an edge names a missing vertex or the same vertex
/// twice, an edge is listed twice, a coordinate is not finite, a vertex has in-degree !=
/// out-degree (the front is not closed), two front vertices coincide, or the signed area
/// is not positive (an outer loop clockwise).
FrontMeasure measure_front(std::span<const Point2> points, std::span<const FrontEdge> front);

/// The median length of the front edges (the grids' natural cell size); 0 for no edges.
double median_edge_length(std::span<const Point2> points, std::span<const FrontEdge> front);

}  // namespace certimesh::generators::advancing_front_detail
