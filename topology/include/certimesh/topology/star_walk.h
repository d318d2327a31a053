// The star Ω(v) of one vertex found locally: start at the vertex's incident-element hint and
// walk across the facets through v. Costs O(|Ω(v)|) and needs no global structure, which is
// what local modifications want (VertexStars builds every star at once instead).
// Finds the whole star when it is connected through facets (every vertex of a manifold
// mesh, with or without boundary); of a pinched star it finds the part holding the hint.
#pragma once

#include <vector>

#include "certimesh/topology/index.h"

namespace certimesh::topology {

/// The elements of v's star reachable from incident_element(v), in increasing id order.
/// Empty when v has no incident element (or is not live).
template <class Mesh>
std::vector<ElementId> walk_star(const Mesh& mesh, VertexId v);

}  // namespace certimesh::topology
