// The monograph's Algorithm 35 in 3D: sliver removal by local modifications (digest D §3).
// The tetrahedra below the target quality are kept in ascending quality (QualityOrder: O(log N)
// per insert and erase); the worst is taken out and tried with edge removal of each of its
// edges (n-to-2n-4, 3-2 for n = 3), the 2-3 flip of each of its facets and the node shift of
// each of its free vertices (topology/local_modifications_3.h), in that order; the first that
// raises the worst quality of what it changes is committed (accept-only-if-better, so the
// mesh's sorted quality vector only rises) and the tetrahedra it made that are still below the
// target join the queue. An element that nothing improves is dropped until the next pass; a
// pass that commits nothing ends the run. Worst case: at most max_passes passes of at most
// max_operations attempts each, each attempt O(r³ + s + log N) for rings of r <= max_ring
// tetrahedra and stars of s; no step is O(N) except building the queue once per pass.
//
// The boundary is kept exactly: no boundary facet, constrained facet (Tetrahedralization3's
// constrained_faces) or facet between two region labels is flipped away, no edge in one is
// removed, no vertex of one moves, nor any vertex below first_movable_vertex (the input's).
// No vertex is added or removed, so vertex ids are unchanged.
#pragma once

#include <cstdint>

#include "certimesh/generators/delaunay/tetrahedralization_3.h"

namespace certimesh::generators {

struct ImprovementOptions3 {
  double target_quality = 0.6;       // tetrahedra at or above it are left alone
  std::uint32_t max_passes = 2;
  std::uint64_t max_operations = 0;  // attempts per pass; 0 = 3 x the tetrahedra below the target
};

struct ImprovementStats3 {
  bool ran = false;
  std::uint64_t attempts = 0;
  std::uint64_t edge_removals = 0;  // 3-2 flips included
  std::uint64_t flips_2_3 = 0;
  std::uint64_t node_shifts = 0;
  std::uint32_t passes = 0;
  double worst_before = 0.0, worst_after = 0.0;
};

/// Improves `mesh` in place (tetrahedra, labels; points of free vertices move). The mesh must
/// be valid: positive tetrahedra, each facet in at most two.
ImprovementStats3 improve_tetrahedra_3(Tetrahedralization3& mesh, std::uint32_t first_movable_vertex,
                                       const ImprovementOptions3& options = {});

}  // namespace certimesh::generators
