// Does a tetrahedron intersect a triangle beyond their shared vertices (mode.h)?
// The monograph's Algorithm 17 (digest C §1.5): faces against triangle edges, tetrahedron
// edges against the triangle (Algorithm 16, 18 calls), then containment of the triangle's
// free vertices, where "inside" means "not certified outside".
#pragma once

#include <array>

#include "certimesh/predicates/intersection/mode.h"
#include "certimesh/predicates/intersection/vertex.h"

namespace certimesh::predicates {

Overlap tetrahedron_triangle(const std::array<Vertex3, 4>& tet, const std::array<Vertex3, 3>& tri,
                             IntersectionMode mode);

}  // namespace certimesh::predicates
