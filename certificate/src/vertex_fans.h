// Internal: the cones of the boundary triangles at one vertex v, decided at once. Two closed
// triangles that share v meet beyond their shared vertices and edges only if they share a
// direction from v other than a shared edge's (their intersection is convex and holds v), so
// their cones at v decide them. Around a line L = v c through v, each triangle's cone spans a
// wedge of half-planes bounded by L, from one vertex's half-plane to the other's (strictly less
// than a half turn, as long as orient3d(v, c, a, b) != 0); a triangle with c itself as vertex
// lies in one half-plane. When the open wedges are pairwise disjoint and no single half-plane
// lies inside another's wedge, two cones can share a direction only in a half-plane that bounds
// both, and those pairs (typically two per half-plane: the triangles along one edge) are
// tested exactly. proofs/mesh_certificate.md section 6 has the argument.
#pragma once

#include <cstddef>
#include <functional>
#include <vector>

#include "mesh_view.h"

namespace certimesh::certificate::detail {

/// True only if no two of the triangles `fan` of `set` (each has v as a vertex) meet beyond
/// their shared vertices and edges; `meet(i, j)` is the exact test for the few pairs the cones
/// leave open. False also when no tried line L separates the cones: undecided, not a defect.
bool fan_is_embedded(const MeshView& m, const FacetSet& set, Index v, const std::vector<std::size_t>& fan,
                     const std::function<bool(std::size_t, std::size_t)>& meet);

}  // namespace certimesh::certificate::detail
