// Does a triangle of the plane intersect a segment beyond their shared vertices (mode.h)?
// The monograph's Algorithm 11 (digest B §3.4), in either orientation of the triangle,
// with its one-shared-vertex case fixed: only the two sides incident to the shared vertex
// may certify "disjoint" (the printed rule also tries the opposite side, whose uncertain
// zero can hide a real crossing). A disjoint verdict in conservative mode needs the
// triangle's own orientation to be certain.
#pragma once

#include <array>

#include "certimesh/predicates/intersection/mode.h"
#include "certimesh/predicates/intersection/vertex.h"

namespace certimesh::predicates {

Overlap triangle_segment_2d(const std::array<Vertex2, 3>& tri, const std::array<Vertex2, 2>& seg,
                            IntersectionMode mode);

}  // namespace certimesh::predicates
