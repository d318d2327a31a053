// Do two segments of the plane intersect beyond their shared vertices (mode.h)?
//
// Disjoint certificates: a line through one segment with both ends of the other strictly
// on one side; a coordinate line strictly between their bounding boxes; with one shared
// vertex v, a line through v (the other segment's line, or a coordinate line) with the
// two free ends strictly on opposite sides.
#pragma once

#include <array>

#include "certimesh/predicates/intersection/mode.h"
#include "certimesh/predicates/intersection/vertex.h"

namespace certimesh::predicates {

Overlap segment_segment_2d(const std::array<Vertex2, 2>& s, const std::array<Vertex2, 2>& t,
                           IntersectionMode mode);

}  // namespace certimesh::predicates
