// A boundary Steiner vertex inside one input segment, seen from the local modifications that
// keep the trace only geometrically (local_modifications_2.h, `input_segments`): the segment,
// the vertex's two boundary neighbours on it, and the exact order of points along it.
#pragma once

#include <optional>

#include "local_geometry_2.h"

namespace certimesh::topology::local {

/// v's open star, its input segment, and its boundary neighbours `before` = link.front() and
/// `after` = link.back(), both on the same segment (an endpoint of it or inside it).
struct SegmentRun2 {
  OrderedStar2 star;
  InputSegment2 segment;
  VertexId before, after;
};

/// std::nullopt unless v is a Steiner vertex inside one input segment, its star is open and one
/// fan, no constrained interior edge passes through v (a cut or interface vertex stays fixed),
/// and both boundary neighbours are on the same segment.
std::optional<SegmentRun2> segment_run(const TriangleMesh2& mesh, VertexId v, const InputSegments2& segments);

/// Whether p is an endpoint of s or the caller places p inside s.
bool lies_on(const Point2d& p, const InputSegment2& s, const InputSegments2& segments);

/// The same segment, whichever way round.
bool same_segment(const InputSegment2& s, const InputSegment2& t);

/// The fraction f of s nearest p (approximate: only a starting value for the exact rounding
/// of a point of s, never a decision).
double fraction_along(const Point2d& p, const InputSegment2& s);

/// Whether x is strictly between a and b along s, decided exactly by comparing the coordinate
/// in which s is not constant (the larger extent): rounding a point of s is monotone in that
/// coordinate, so points that compare equal there are refused rather than guessed.
bool strictly_between(const Point2d& a, const Point2d& x, const Point2d& b, const InputSegment2& s);

/// The node shift of a boundary Steiner vertex (try_node_shift): the best position along its
/// segment between its neighbours (boundary_slide_2.cpp).
std::optional<LocalChange2> slide_along_segment(TriangleMesh2& mesh, VertexId v,
                                                const LocalModificationOptions2& options);

}  // namespace certimesh::topology::local
