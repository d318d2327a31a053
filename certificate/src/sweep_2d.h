// Internal: one plane sweep over 2D segments (boundary edges, or domain segments) that does
// the certificate's worst-case-sensitive 2D work in O((n + q) log n), whatever the shape:
//  * it finds whether two segments meet beyond their shared vertices (Shamos and Hoey's
//    test: the first contact of the sweep order makes the two segments neighbours in the
//    sweep status before the sweep passes it);
//  * for each query point q, once no contact exists: W, the winding number of the oriented
//    segments at a point just left of q (the leftward ray's signed crossings), the first
//    segment that ray hits, and whether q lies on a segment.
// The sweep line is y = const, ties broken by x (a lexicographic order on points, so
// horizontal segments need no special case); every comparison is an exact orient2d sign.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "certimesh/predicates/point.h"
#include "mesh_view.h"

namespace certimesh::certificate::detail {

/// The sweep's order on points: by y, then x (lexicographic, so horizontal segments need no
/// special case).
inline bool sweep_less(const predicates::Point2& a, const predicates::Point2& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; }

struct SweepAnswer {
  int winding = 0;               // W at a point infinitesimally left of the query point
  std::int64_t left_facet = -1;  // the first segment the leftward ray hits, -1 if none
  bool on_facet = false;         // the query point lies on a segment (not only at its lower end)
};

/// Runs the sweep over the segments of `set` (2D; endpoint ids into m, distinct points).
/// Returns the first contact found as a Finding (`touching` when a vertex of one segment lies
/// on the other, else `crossing`); when there is none, fills `answers` for `queries`.
/// `vertex_order`, when given, is every vertex of m in sweep order, ties by index (check_input's
/// lex_order in 2D): the endpoints are then taken from it instead of sorted.
Finding sweep_2d(const MeshView& m, const FacetSet& set, Defect touching, Defect crossing, const std::string& what,
                 const std::vector<std::array<double, 2>>& queries, std::vector<SweepAnswer>& answers,
                 const std::vector<Index>* vertex_order = nullptr);

}  // namespace certimesh::certificate::detail
