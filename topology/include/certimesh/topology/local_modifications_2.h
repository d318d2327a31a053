// The five basic local modifications of a 2D triangle mesh (monograph §5.2, Algorithms 30-34;
// digest D §2.1): insert a node on an edge, flip an edge, shift a node, collapse an edge,
// delete a node. Each follows the same pattern:
//   1. build the virtual replacement triangles;
//   2. decide their validity with exact orient2d signs (every new triangle strictly
//      counterclockwise; the elements they replace were, so the changed region keeps its
//      boundary and is tiled exactly once);
//   3. compare Q1 = min quality of the new triangles with Q0 = min quality of the old ones;
//   4. commit iff Q1 > Q0 strictly; otherwise leave the mesh exactly as it was.
// Qualities are approximate (doubles); validity is exact.
//
// The boundary trace is kept: a constrained edge -- an open (boundary) facet, an interior
// facet with facet_label != 0 (cut, interface), or an edge between elements of different
// labels -- is never flipped or collapsed, and is split only when a boundary projection or the
// input segments are given; a vertex on a constrained edge never moves and is never deleted.
// An edge collapse may still merge a free vertex INTO a trace vertex, which stays where it is.
// Operations that would create a duplicate edge or a non-manifold star (the link condition)
// are refused.
//
// With `input_segments` given, the trace is kept geometrically instead of vertex for vertex
// (the monograph's boundary nodes, digest D §2.1 2D-1, 2D-3, 2D-4): a Steiner vertex strictly
// inside one input segment slides along that segment (node shift), may merge into a boundary
// neighbour on the same segment (edge collapse), and a constrained edge whose two ends are on
// one segment is split on it. Every new position is the round-once image of an exact point of
// the segment (design decision 2); a domain's own vertex never moves.
//
// The mesh must be valid and counterclockwise (every element positive) on entry; each operation
// returns the elements it removed and added so that a caller can keep its own order of
// elements (Algorithm 35, generators/improvement) up to date.
#pragma once

#include <functional>
#include <optional>
#include <vector>

#include "certimesh/topology/quality.h"
#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::topology {

/// The quality being optimised, of a counterclockwise triangle (a, b, c): e.g. the shape
/// quality (2.1.3) or the size-aware quality (6.1.5). Only compared, never used for validity.
using TriangleQualityFunction2 = std::function<double(const Point2d&, const Point2d&, const Point2d&)>;

/// Where a new vertex on the constrained edge (a, b) goes, given the midpoint of the edge:
/// a point of the true boundary (the monograph's F((t1 + t2) / 2)). The operation then checks
/// with exact signs that the point gives valid triangles (Lemma 5.2.2).
using BoundaryProjection2 = std::function<Point2d(VertexId a, VertexId b, const Point2d& midpoint)>;

/// A segment of the input domain, by its two endpoints exactly as the domain gives them.
struct InputSegment2 {
  Point2d start, end;
  friend bool operator==(const InputSegment2&, const InputSegment2&) = default;
};

/// The input segments, for the boundary operations that keep the trace only geometrically
/// (see above). Both functions are supplied by the caller that knows the domain (topology knows
/// no domain and does no exact construction):
struct InputSegments2 {
  /// The one input segment whose relative interior holds p (p is the rounding of an exact point
  /// of it, decided exactly: the segment meets p's rounding box), or std::nullopt when p is a
  /// domain vertex, on no segment, or not provably on a single one -- such a vertex stays fixed.
  std::function<std::optional<InputSegment2>(const Point2d& p)> segment_containing;
  /// The round-to-nearest image of the exact point start + f·(end − start), f in [0, 1]. Also
  /// called with a constrained edge between two vertices that are on no segment's interior,
  /// to ask (through segment_containing) whether the edge spans a whole input segment.
  std::function<Point2d(const InputSegment2& segment, double f)> point_on;
  explicit operator bool() const { return segment_containing && point_on; }
};

/// Algorithm 33's Q0 as printed covers only the triangles that survive the collapse; the
/// alternative reading also counts the two triangles on the collapsed edge (digest D §2.1).
/// Both keep the mesh's worst quality from decreasing.
enum class CollapseReference {
  survivors_only,          // Q0 = min over the surviving triangles in their old positions
  survivors_and_removed,   // Q0 also over the two triangles that vanish
};

struct LocalModificationOptions2 {
  TriangleQualityFunction2 quality;  // required
  BoundaryProjection2 boundary_projection;  // empty: constrained edges are never split
  CollapseReference collapse_reference = CollapseReference::survivors_and_removed;
  /// A node shift is committed only when it raises the star's worst quality by more than this
  /// (an absolute quality difference): near a local optimum the line search still finds gains
  /// of a few ulps, and Algorithm 35 would spend its whole budget on them (measured in the §5.2
  /// experiment: 183,729 shifts without progress). 0 = the monograph's bare Q1 > Q0.
  double minimum_shift_gain = 1e-3;
  /// Off by default (the trace is kept vertex for vertex). On: an edge collapse may also remove
  /// a boundary vertex that lies exactly (orient2d == 0) on the straight line between its two
  /// boundary neighbours, merging it into one of them along an open boundary edge. The boundary
  /// stays the same point set exactly; only its discretization coarsens (digest D §2.1, 2D-4:
  /// the book collapses boundary edges; here only where nothing moves).
  bool coarsen_straight_boundary = false;
  /// Empty (default): the trace is kept vertex for vertex. Given: boundary vertices inside an
  /// input segment slide along it and may be collapsed along it, and constrained edges are split
  /// on it (when no boundary_projection is given) -- see the header comment.
  InputSegments2 input_segments;
};

/// What a committed operation changed. A node shift keeps the element ids of the star: they
/// appear in both lists (their qualities changed).
struct LocalChange2 {
  std::vector<ElementId> removed;
  std::vector<ElementId> added;
};

/// Algorithm 30: a node at the midpoint of edge `local_edge` (the facet opposite that local
/// vertex) of `element`, the two (or, on a boundary edge, one) triangles split in two. On a
/// constrained edge the node goes where boundary_projection says, else (with input_segments,
/// both ends on one input segment) at the rounding of the exact point of the segment half-way
/// between the ends' fractions.
std::optional<LocalChange2> try_insert_on_edge(TriangleMesh2& mesh, ElementId element, int local_edge,
                                               const LocalModificationOptions2& options);

/// Algorithm 31: replace the edge by the other diagonal of its strictly convex quadrilateral.
std::optional<LocalChange2> try_flip(TriangleMesh2& mesh, ElementId element, int local_edge,
                                     const LocalModificationOptions2& options);

/// Algorithm 32: move the free vertex v along the forward-difference gradient of the worst
/// quality of its star (the central difference when the forward one finds no gain: a kink of
/// the min), to the best point a golden-section step search finds inside the star's kernel.
/// A boundary vertex inside an input segment (with `input_segments`) instead slides along the
/// segment between its two boundary neighbours: a golden-section search over the fraction of the
/// segment, every trial point the rounding of an exact point of it (try_boundary_slide).
std::optional<LocalChange2> try_node_shift(TriangleMesh2& mesh, VertexId v,
                                           const LocalModificationOptions2& options);

/// Moves the boundary vertex v to `target` along its input segment, if: v is a Steiner vertex
/// inside one input segment (options.input_segments), with an open star and no constrained
/// interior edge; its two boundary neighbours are on the same segment; `target` is on that
/// segment too and strictly between the two neighbours along it (a slide never passes another
/// boundary vertex); every triangle of v's star stays strictly counterclockwise (exact); and
/// the star's worst quality rises by more than options.minimum_shift_gain.
std::optional<LocalChange2> try_boundary_slide(TriangleMesh2& mesh, VertexId v, const Point2d& target,
                                               const LocalModificationOptions2& options);

/// Algorithm 33: merge the edge's endpoints at its midpoint (at the trace endpoint when one
/// endpoint is on the trace; never when both are, except a boundary vertex merging into its
/// neighbour along their boundary edge: a straight one with `coarsen_straight_boundary`, a
/// Steiner vertex inside an input segment into a neighbour on the same segment with
/// `input_segments`).
std::optional<LocalChange2> try_edge_collapse(TriangleMesh2& mesh, ElementId element, int local_edge,
                                              const LocalModificationOptions2& options);

/// Algorithm 34: remove the free interior vertex v and fill its star with the fan from one of
/// its link vertices (each tried in link order; the first that improves is kept).
std::optional<LocalChange2> try_node_deletion(TriangleMesh2& mesh, VertexId v,
                                              const LocalModificationOptions2& options);

/// Whether the edge opposite local vertex `local_edge` of `element` is constrained (see above).
bool is_constrained_edge(const TriangleMesh2& mesh, ElementId element, int local_edge);

/// Whether v may not move freely or be deleted: it lies on a constrained edge, or its star is
/// not a single fan connected through edges (a pinched vertex). With `input_segments` such a
/// vertex may still slide along, or be collapsed along, its input segment (see above).
bool is_trace_vertex(const TriangleMesh2& mesh, VertexId v);

}  // namespace certimesh::topology
