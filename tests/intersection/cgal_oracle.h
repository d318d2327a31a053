// The independent oracle of the intersection tests: CGAL's exact kernel (EPECK), in one
// translation unit (cgal_oracle.cpp) because CGAL compiles slowly.
//
// It shares nothing with the library but the vertex type. Each element is cut into
// non-degenerate CGAL objects (every affinely independent subset of the right size: a
// Caratheodory cover, not the library's triangulation); CGAL::intersection gives each
// piece pair's intersection as a point, segment, triangle or polygon; the pair
// intersects when a vertex of one of these lies outside the shared simplex (the hull of
// the vertices with the same id and coordinates in both elements).
#pragma once

#include <array>

#include "certimesh/predicates/intersection/vertex.h"

namespace certimesh::testing {

using predicates::Vertex2;
using predicates::Vertex3;

bool oracle_segment_segment_2d(const std::array<Vertex2, 2>& s, const std::array<Vertex2, 2>& t);
bool oracle_triangle_segment_2d(const std::array<Vertex2, 3>& tri,
                                const std::array<Vertex2, 2>& seg);
bool oracle_triangle_segment_3d(const std::array<Vertex3, 3>& tri,
                                const std::array<Vertex3, 2>& seg);
bool oracle_triangle_triangle_3d(const std::array<Vertex3, 3>& a, const std::array<Vertex3, 3>& b);
bool oracle_tetrahedron_triangle(const std::array<Vertex3, 4>& tet,
                                 const std::array<Vertex3, 3>& tri);

}  // namespace certimesh::testing
