// Delaunay refinement with a guaranteed smallest angle (`certimesh mesh --min-angle A`, as
// Triangle's -q): Ruppert's algorithm as Shewchuk states it ("Delaunay refinement algorithms
// for triangular mesh generation", 2002), on a classified constrained Delaunay triangulation.
//
//  - A subsegment (a piece of an input segment between two mesh vertices) is *encroached*
//    when the apex of an inside triangle on it lies strictly inside its diametral circle
//    (the angle at the apex exceeds 90 degrees). Encroached subsegments are split first.
//  - A split puts the new vertex at the midpoint of the subsegment, except when exactly one
//    end is an input vertex: then at the power of two 2^k nearest to the middle (L/3 <= 2^k
//    <= 2L/3, L its length) from that vertex -- concentric shells, so that segments meeting at
//    a small input angle are split at the same radii and do not split each other without end.
//    The new vertex is the rounding to nearest of that exact point of the *input* segment
//    (design decision 2; point_on_segment.h), so it lies on the segment up to half an ulp.
//  - A triangle is *bad* when it is bigger than the size policy, or when its smallest angle,
//    computed from the vertices' coordinates as they are, is below `min_angle_degrees` and it
//    is not *exempt*. Bad triangles are split at their circumcentre, worst first; a
//    circumcentre that lies beyond a constrained edge, or strictly inside the diametral circle
//    of a subsegment that bounds its cavity, is not inserted: those subsegments are split.
//  - Exempt (the small-input-angle rule of Shewchuk and Triangle): the triangle's shortest edge
//    (u, w) joins two Steiner points u, w lying on two different input segments s1, s2 that
//    share an end point z, with the angle between s1 and s2 at z below 60 degrees, and
//    |uz|, |wz| equal within a factor 1.001 in squared length (the same shell). Such a
//    triangle's small angle is forced by the input angle at z; splitting it would only make
//    the cascade the shells prevent.
//
// Termination: at most `max_steiner` Steiner points are inserted; when that cap is met the
// loop stops and says so (stats.cap_reached, stats.below_min_angle) instead of hanging. For
// A <= 20.7 degrees (radius-edge ratio sqrt 2) and no input angle below 60 degrees Ruppert's
// proof bounds the count by the local feature size; with smaller input angles the shells and
// the exemption are what Triangle does, and the cap is the honest bound.
//
// Deterministic: worst first, ties broken by vertex ids; no hash-map iteration.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "certimesh/generators/delaunay/constrained_delaunay_2.h"
#include "certimesh/generators/progress.h"
#include "certimesh/generators/size_policy.h"

namespace certimesh::generators {

/// A constrained edge of the triangulation and the input segment it is a piece of.
struct Subsegment2 {
  std::uint32_t a = 0, b = 0;  // vertex ids of the triangulation
  std::uint32_t segment = 0;   // index into QualityRefinementOptions::segments
};

/// An input segment: the ids of its end vertices (input vertices, ids < input_vertices).
struct InputSegment2 {
  std::uint32_t a = 0, b = 0;
};

struct QualityRefinementOptions {
  /// The smallest angle wanted, in degrees, in (0, 60).
  double min_angle_degrees = 20.7;
  /// The largest edge length; automatic: no size bound (quality only).
  SizePolicy size;
  /// Steiner point cap (see above).
  std::uint64_t max_steiner = 4'000'000;
  /// Vertices [0, input_vertices) of the triangulation are the domain's own vertices; the
  /// others on a subsegment are Steiner points of its input segment.
  std::uint32_t input_vertices = 0;
  std::span<const InputSegment2> segments;
};

struct QualityRefinementStats {
  std::uint64_t inserted = 0;            // Steiner points
  std::uint64_t circumcentres = 0;       // of them, circumcentres
  std::uint64_t segment_splits = 0;      // of them, on segments
  std::uint64_t refused_splits = 0;      // subsegments whose rounded split point did not fit
  std::uint64_t exempt = 0;              // final inside triangles exempt (small input angle)
  std::uint64_t below_min_angle = 0;     // final inside triangles below the angle, not exempt
  double smallest_angle = 0.0;           // degrees, over the non-exempt inside triangles
  double smallest_exempt_angle = 0.0;    // degrees, over the exempt ones (0 when none)
  bool cap_reached = false;
};

/// Refines `cdt` in place. `labels` (classify(): inside >= 0, outside -1, by slot) is kept
/// up to date; `subsegments` lists every constrained edge of `cdt` on entry and is updated
/// as they are split (order deterministic). Throws std::invalid_argument for an angle outside
/// (0, 60).
QualityRefinementStats refine_quality_2(ConstrainedDelaunay2& cdt, std::vector<int>& labels,
                                        std::vector<Subsegment2>& subsegments,
                                        const QualityRefinementOptions& options,
                                        const ProgressCallback& progress = {});

/// The smallest angle of triangle (a, b, c) in degrees, from the coordinates as they are
/// (atan2 of cross and dot products: accurate to a few ulps of the angle).
double smallest_angle_degrees(const Point2& a, const Point2& b, const Point2& c);

}  // namespace certimesh::generators
