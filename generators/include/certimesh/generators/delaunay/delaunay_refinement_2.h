// Delaunay refinement of a classified constrained Delaunay triangulation (--algorithm
// delaunay): interior Steiner points are inserted until every inside triangle meets the size
// policy, and skinny triangles get their circumcentre where that is safe.
//
// The boundary trace is kept: no point is ever inserted on a constrained edge, and a
// circumcentre that lies outside the triangle's region or behind a constrained edge (decided
// by an exact straight walk) is not inserted; a too-big triangle then gets the midpoint of
// its longest unconstrained edge instead, and a merely skinny one is left as it is. Triangles
// are processed worst first, ties broken by vertex ids: deterministic.
//
// Termination: every inserted point keeps a distance of at least a quarter of the local size
// from the vertices around it, so by packing at most `insertion_bound` points fit in the
// inside area; the loop stops there and says so (stats.bound_reached), it cannot hang.
#pragma once

#include <cstdint>
#include <vector>

#include "certimesh/generators/delaunay/constrained_delaunay_2.h"
#include "certimesh/generators/progress.h"
#include "certimesh/generators/size_policy.h"

namespace certimesh::generators {

struct DelaunayRefinementOptions {
  /// The target side length. Automatic: the longest constrained edge of an inside triangle
  /// (the boundary is discretized to the wanted size first), grown by `growth`.
  SizePolicy size;
  /// Circumradius over shortest edge above which an inside triangle is skinny (√2: angles
  /// ≥ 20.7° where the circumcentre can be inserted).
  double max_radius_edge_ratio = 1.4142135623730951;
  /// Insertion budget; 0 = the packing bound computed from the inside area and the sizes.
  std::uint64_t max_insertions = 0;
};

struct DelaunayRefinementStats {
  std::uint64_t inserted = 0;              // Steiner points added
  std::uint64_t circumcentres = 0;         // of them, circumcentres
  std::uint64_t edge_midpoints = 0;        // of them, midpoints of unconstrained edges
  std::uint64_t skipped = 0;               // bad triangles left: no safe point
  std::uint64_t insertion_bound = 0;       // the budget the loop asserted
  bool bound_reached = false;
};

/// Refines `cdt` in place; `labels` (classify(): inside ≥ 0, outside -1, indexed by slot)
/// is updated for the new triangles, which take their region's label. Deterministic.
DelaunayRefinementStats refine_delaunay_2(ConstrainedDelaunay2& cdt, std::vector<int>& labels,
                                          const DelaunayRefinementOptions& options,
                                          const ProgressCallback& progress = {});

/// The longest side of triangle (a, b, c): what refine_delaunay_2 compares with the size at
/// the centroid (an approximate length, as sizes are).
double longest_side(const Point2& a, const Point2& b, const Point2& c);

}  // namespace certimesh::generators
