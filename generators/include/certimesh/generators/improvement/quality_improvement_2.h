// The monograph's Algorithm 35 in 2D: mesh improvement by local modifications (digest D §3).
// Elements are kept in ascending quality; the worst is tried first with the five basic
// operations of topology/local_modifications_2.h (insert on edge, flip, node shift, edge
// collapse, node deletion), each committed only when the worst quality of what it changes
// rises strictly (accept-only-if-better), so the mesh quality never decreases. Validity is
// decided by exact orientation signs, never by a tolerance.
//
// Two schedules. `baskets` is the monograph's listing (rank pointer k, basket N2, rounds N3):
// an element that failed is tried again in every later round, so a mesh whose poor elements
// cannot all be repaired costs N1 iterations of O(N2) each. `work_queue` (the default) keeps
// the elements below the target in a queue, worst first; an element is tried when it leaves
// the queue and then dropped, and comes back only when a committed modification touched it
// (it is new, or it shares an edge with a new element), at most `max_attempts` times per
// element id. Worst case: at most min(N1, max_attempts·(N + 2·S)) attempts, S the committed
// modifications (each adds at most two elements' worth of ids), each attempt O(d² + log N) for
// a vertex degree d -- near-linear in the mesh size for bounded degrees.
//
// The boundary trace is kept: boundary edges and constrained interior edges (labelled
// facets: cuts, region interfaces) are never flipped, split, collapsed or moved off -- vertex
// for vertex by default, only geometrically (on the input segments) with `input_segments`.
#pragma once

#include <array>
#include <cstdint>

#include "certimesh/generators/progress.h"
#include "certimesh/generators/size_policy.h"
#include "certimesh/topology/local_modifications_2.h"
#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::generators {

enum class LocalOperation2 : std::uint8_t {
  insert_on_edge = 1u << 0,  // Algorithm 30
  flip = 1u << 1,            // Algorithm 31
  node_shift = 1u << 2,      // Algorithm 32
  edge_collapse = 1u << 3,   // Algorithm 33
  node_deletion = 1u << 4,   // Algorithm 34
};
inline constexpr std::uint8_t all_local_operations_2 = 0x1f;

enum class ImprovementSchedule2 : std::uint8_t { work_queue, baskets };

struct ImprovementOptions2 {
  ImprovementSchedule2 schedule = ImprovementSchedule2::work_queue;
  /// Work queue: how often one element id may be tried (the first try and re-queues).
  std::uint32_t max_attempts = 8;
  /// When positive (degrees): never commit a modification after which the smallest angle of
  /// the elements it changed is below this floor and below the smallest angle they had
  /// before; where a changed element is below the floor, the optimised quality there is the
  /// smallest angle (elements at or above it are compared by `size`/shape quality as usual).
  /// So the improvement never lowers the mesh's smallest angle below the floor (e.g. the
  /// --min-angle bound a Delaunay refinement achieved). 0 = off.
  double min_angle_floor = 0.0;
  double target_quality = 0.9;       // Q0: stop when the worst element reaches it
  std::uint64_t max_operations = 0;  // N1; 0 = 5 x the element count
  /// Work queue: stop after this many iterations in a row that did not raise the worst quality
  /// (0: only the target and max_operations stop it).
  std::uint64_t stall_iterations = 0;
  std::uint32_t basket_size = 0;     // N2 (baskets); 0 = 7 % of the element count (at least 16)
  std::uint32_t max_baskets = 0;     // N3 (baskets); 0 = enough that N2 * N3 exceeds the element count
  std::uint8_t operations = all_local_operations_2;
  /// Size-aware quality (6.1.5) with this size; shape quality (2.1.3) when empty.
  SizePolicy size;
  /// Where a node inserted on a constrained edge goes (a point of the true boundary); empty:
  /// constrained edges are never split (local_modifications_2.h).
  topology::BoundaryProjection2 boundary_projection;
  /// Algorithm 33's Q0 reading (digest D §2.1).
  topology::CollapseReference collapse_reference = topology::CollapseReference::survivors_and_removed;
  /// The least gain of the star's worst quality for which a node shift counts (see
  /// LocalModificationOptions2::minimum_shift_gain).
  double minimum_shift_gain = 1e-3;
  /// Let edge collapses remove boundary vertices that lie exactly on the straight line between
  /// their boundary neighbours (LocalModificationOptions2::coarsen_straight_boundary). Off: the
  /// boundary trace is kept vertex for vertex.
  bool coarsen_straight_boundary = false;
  /// Empty (default): the boundary trace is kept vertex for vertex. Given (e.g.
  /// input_segments_of(domain)): the trace is kept geometrically -- boundary Steiner vertices
  /// slide along their input segment in node shifts and may be collapsed along it, and boundary
  /// edges are split on it when no boundary_projection is given (LocalModificationOptions2).
  topology::InputSegments2 input_segments;
};

struct ImprovementStats2 {
  std::uint64_t iterations = 0;                   // elements tried (Algorithm 35 iterations)
  std::array<std::uint64_t, 5> successes{};       // per operation, in the enum's bit order
  double initial_worst = 0.0, final_worst = 0.0;  // with the quality being optimised
  double initial_mean = 0.0, final_mean = 0.0;
  bool reached_target = false;
};

/// Improves `mesh` in place. Deterministic. Operations are tried on the k-th worst element in
/// this order, each on every edge or vertex of the element, the first success committed:
/// flip, node shift, edge collapse, node deletion, insert on edge (size-neutral and cheap
/// first; the count-changing ones last). Throws std::invalid_argument, naming the element, if
/// some element is not strictly counterclockwise (the mesh must be valid on entry).
ImprovementStats2 improve_quality_2(topology::TriangleMesh2& mesh, const ImprovementOptions2& options,
                                    const ProgressCallback& progress = {});

}  // namespace certimesh::generators
