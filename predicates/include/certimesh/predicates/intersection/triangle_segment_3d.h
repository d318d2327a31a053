// Does a triangle in space intersect a segment beyond their shared vertices (mode.h)?
// The monograph's Algorithm 16 (digest C §1.4). Its coplanar and mixed (one endpoint in
// the triangle's plane) cases are decided in the first coordinate-plane projection where
// the triangle's projection has a non-zero orientation; conservative mode accepts a
// separating line in any projection, since a common point would project to a common point.
#pragma once

#include <array>

#include "certimesh/predicates/intersection/mode.h"
#include "certimesh/predicates/intersection/vertex.h"

namespace certimesh::predicates {

Overlap triangle_segment_3d(const std::array<Vertex3, 3>& tri, const std::array<Vertex3, 2>& seg,
                            IntersectionMode mode);

}  // namespace certimesh::predicates
