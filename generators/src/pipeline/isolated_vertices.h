// Isolated input vertices (on no segment, inside the domain) are mesh vertices (design
// decision 8). The advancing front grows from the boundary and ignores them; afterwards each
// one's cavity -- the triangles that contain it and their neighbours across unconstrained
// edges, and the star of a generated vertex it crowds (within half the containing triangles'
// mean edge), which it replaces -- is re-triangulated by the constrained Delaunay completion
// with the vertex inside.
// The improvement then keeps the vertex in place through a pinned edge (pin_edges).
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "certimesh/generators/domain/planar_domain.h"
#include "improvement_region.h"

namespace certimesh::generators::detail {

/// Makes every vertex of `isolated` (ids into mesh.points, used by no triangle, inside the
/// meshed region, on no `constrained` edge) a vertex of the mesh. A generated vertex with the
/// same coordinates is replaced by it. Cost: O(n + c + k log k) for n triangles and k points,
/// c the number of grid cells the triangles' boxes cover (a uniform grid of about n cells
/// locates the points; the cavities are re-triangulated together): linear for the advancing
/// front's well-shaped triangles; a mesh of long slivers crossing the domain is the worst case,
/// O(n^1.5) cells.
void insert_isolated_vertices(TriangleSoup& mesh, std::span<const DomainSegment> constrained,
                              std::span<const std::uint32_t> isolated);

/// One mesh edge at each isolated vertex, for the improvement's constrained list: a vertex of
/// a constrained edge is never moved or removed.
std::vector<DomainSegment> pin_edges(const TriangleSoup& mesh, std::span<const std::uint32_t> isolated);

}  // namespace certimesh::generators::detail
