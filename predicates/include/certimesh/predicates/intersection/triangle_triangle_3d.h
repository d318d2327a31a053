// Do two triangles in space intersect beyond their shared vertices (mode.h)?
// Each edge of one against the other triangle (Algorithm 16, six calls): a point of the
// intersection outside the shared simplex always lies on an edge of one of them.
#pragma once

#include <array>

#include "certimesh/predicates/intersection/mode.h"
#include "certimesh/predicates/intersection/vertex.h"

namespace certimesh::predicates {

Overlap triangle_triangle_3d(const std::array<Vertex3, 3>& a, const std::array<Vertex3, 3>& b,
                             IntersectionMode mode);

}  // namespace certimesh::predicates
