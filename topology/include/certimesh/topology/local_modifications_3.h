// Local modifications of a tetrahedral mesh that remove slivers (monograph §5.3, digest D):
// the 2-3 face flip, edge removal (n tetrahedra round an interior edge replaced by the 2n - 4
// of the best triangulation of its link polygon; n = 3 is the 3-2 flip) and node shift. Each
// follows the pattern of the 2D ones (local_modifications_2.h):
//   1. build the virtual replacement tetrahedra;
//   2. decide their validity with exact volume signs (every new tetrahedron strictly positive;
//      with the boundary of the changed region unchanged, positivity means the new tetrahedra
//      tile it exactly once: each point is covered by as many as the boundary winds round it);
//   3. compare Q1 = min quality of the new tetrahedra with Q0 = min quality of the old ones;
//   4. commit iff Q1 > Q0 strictly; otherwise leave the mesh exactly as it was.
// Qualities are approximate (doubles, quality.h); validity is exact.
//
// The boundary trace is kept vertex for vertex: a constrained facet -- an open (boundary)
// facet, an interior facet with facet_label != 0, or a facet between elements of different
// labels -- is never flipped or removed, an edge in a constrained facet is never removed, and
// a vertex of a constrained facet never moves. Neither do the vertices below
// `first_movable_vertex` (the input's own points). No operation adds or removes a vertex.
//
// The mesh must be valid (every element positive, Medit convention) on entry; each operation
// returns the elements it removed and added so that a caller can keep its own order of
// elements (Algorithm 35, generators/improvement) up to date.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "certimesh/topology/quality.h"
#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::topology {

struct LocalModificationOptions3 {
  /// Vertices with a smaller id never move (the caller's input points).
  std::uint32_t first_movable_vertex = 0;
  /// Edge removal looks at rings of at most this many tetrahedra (the dynamic programme over
  /// the link's triangulations costs O(n³)).
  std::size_t max_ring = 10;
  /// A node shift counts only when the star's worst quality q rises by more than
  /// min(minimum_shift_gain, q): a fixed step above, a doubling below. Without it a vertex
  /// creeps by ever smaller gains, each re-queueing its star (the 2D operations' rule).
  double minimum_shift_gain = 1e-3;
  /// When not empty: is_fixed_vertex of every vertex slot, precomputed by the caller (no
  /// operation here changes it: constrained facets stay, their vertices stay), so a node
  /// shift need not look up the facets of the star.
  std::span<const std::uint8_t> fixed_vertices;
};

/// What a committed operation changed. A node shift keeps the element ids of the star: they
/// appear in both lists (their qualities changed).
struct LocalChange3 {
  std::vector<ElementId> removed;
  std::vector<ElementId> added;
};

/// The 2-3 flip: the facet opposite local vertex `facet` of `element` and the two tetrahedra
/// on it are replaced by the three round the edge joining their apexes.
std::optional<LocalChange3> try_flip_2_3(TetrahedralMesh3& mesh, ElementId element, int facet);

/// Edge removal of the edge (local vertices a, b) of `element`: every tetrahedron round it is
/// replaced by the pairs (triangle, each endpoint) over the triangulation of its link polygon
/// that maximises the worst quality (a dynamic programme over the polygon's triangulations,
/// exact validity per triangle). Refused for an edge on the boundary or in a constrained facet.
std::optional<LocalChange3> try_edge_removal(TetrahedralMesh3& mesh, ElementId element, int a, int b,
                                             const LocalModificationOptions3& options);

/// Node shift of the free vertex v: moves it to the best of a few points towards the centroid
/// of its link and towards the point that lifts the worst tetrahedron of its star, if every
/// tetrahedron of the star stays positive (exact) and the star's worst quality rises (by more
/// than options.minimum_shift_gain, see there).
std::optional<LocalChange3> try_node_shift(TetrahedralMesh3& mesh, VertexId v,
                                           const LocalModificationOptions3& options);

/// Whether facet i of e is constrained (see above).
bool is_constrained_facet(const TetrahedralMesh3& mesh, ElementId e, int i);

/// Whether v may not move: below first_movable_vertex, or in a constrained facet of its star.
bool is_fixed_vertex(const TetrahedralMesh3& mesh, VertexId v, const std::vector<ElementId>& star,
                     const LocalModificationOptions3& options);

/// The worst quality (6⁴√2|V|/P³) over some elements of the mesh; 0 for a non-positive one.
double worst_quality(const TetrahedralMesh3& mesh, const std::vector<ElementId>& elements);

}  // namespace certimesh::topology
