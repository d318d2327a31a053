// The monograph's Algorithm 10: the 2D advancing front (digest B §3.2-§3.7).
//
// Input: points and a closed front F(P) of directed edges with the unmeshed region on their
// left (outer sides counterclockwise, both directions of every internal cut). Each step takes
// the shortest front edge (the input front's edges before the grown ones, so that the first
// layer follows the boundary), builds the ideal apex from the size policy (on the bisector at
// a front corner of 82 to 150 degrees), gathers candidate
// front vertices from a local search structure, applies the h and r exclusion radii, and
// accepts the first candidate whose triangle is positively oriented and meets no front edge
// (triangle-segment tests that may err only towards "intersect"); when the local search
// finds nothing it retries over the whole front with exact predicates (§3.3.3 needs exact
// signs there). Every loop is bounded by the estimates (3.3.3)-(3.3.4), asserted.
//
// It never fails on a valid front: whatever it leaves (max_triangles or the bound reached, or
// no candidate -- impossible with exact signs, but checked) is returned as `remaining_front`,
// a closed front of the unmeshed rest, for the Delaunay completion.
//
// Sizes (generators/src/advancing_front/front_sizing_2.h): with a size function or a
// uniform size, s = max(l, size(midpoint of e12)) (the book's mode A); with growth > 1 as
// well, s is also capped at growth * l, so growth limits how fast the front coarsens towards
// the size; with no size, s = growth * l (mode B). h = hc/2 and r by (3.3.2) with the book's
// parameters for the mode. The candidate order (front vertices near the ideal apex first,
// then the apex, then the others by shape) is documented in advancing_front_2.cpp.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "certimesh/generators/progress.h"
#include "certimesh/generators/size_policy.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators {

using predicates::Point2;

struct FrontEdge {
  std::uint32_t a = 0;  // the region lies to the left of a -> b
  std::uint32_t b = 0;
  friend bool operator==(const FrontEdge&, const FrontEdge&) = default;
};

struct AdvancingFrontOptions {
  SizePolicy size;
  /// Upper bound on triangles; 0 = the bound (3.3.4) computed from the input.
  std::uint64_t max_triangles = 0;
  /// Upper bound on global retries (full enumerations, O(front) each); 0 = none. When it is
  /// reached the front stops and returns the rest, which the Delaunay completion fills: a
  /// spiky domain then costs O(front) per retry only a bounded number of times.
  std::uint64_t max_global_retries = 0;
  /// Upper bound on the front edges all global retries together may enumerate; 0 = none. With
  /// a retry count alone, a front of 250,000 edges (a star of 10^4 thin spikes) spent 18 s in
  /// 256 retries before handing its rest to the completion.
  std::uint64_t max_global_retry_work = 0;
};

struct AdvancingFrontStats {
  std::uint64_t triangles = 0;
  std::uint64_t new_vertices = 0;
  std::uint64_t global_retries = 0;        // local search failed, full enumeration used
  std::uint64_t candidates_tested = 0;
  std::uint64_t triangle_bound = 0;        // the (3.3.4) bound the loop asserted
  bool completed = false;                  // the front closed by itself
};

struct AdvancingFrontResult {
  std::vector<Point2> points;                          // the input points, then the new vertices
  std::vector<std::array<std::uint32_t, 3>> triangles; // counterclockwise, indices into points
  std::vector<FrontEdge> remaining_front;              // empty when completed
  AdvancingFrontStats stats;
};

/// Runs Algorithm 10 from the closed front `front` over `points`. Deterministic.
/// Throws std::invalid_argument, naming the edge or vertices, for a front that is not one:
/// an index out of range, an edge from a vertex to itself or listed twice, a non-finite
/// coordinate, a vertex whose in- and out-degrees differ (not closed), two front vertices at
/// the same point, a front enclosing no positive area (an outer loop clockwise); and for growth < 1 or a size function value that is not positive and
/// finite. Points no front edge uses are copied to the result and otherwise ignored.
AdvancingFrontResult advance_front_2(std::span<const Point2> points, std::span<const FrontEdge> front,
                                     const AdvancingFrontOptions& options,
                                     const ProgressCallback& progress = {});

}  // namespace certimesh::generators
