// Snapping the points of a boolean operation's result back to exact constructions from its
// operands: an operand vertex, or the intersection point of two operand edges (exact rational,
// rounded to nearest once). Used by constructive_geometry_2.cpp, whose overlay (Boost) moves
// the points it constructs by up to ~1e-7 of the bounding box.
#pragma once

#include <initializer_list>
#include <utility>
#include <vector>

#include "certimesh/generators/domain/constructive_geometry_2.h"

namespace certimesh::generators::detail {

class ExactSnap {
 public:
  explicit ExactSnap(std::initializer_list<const Region2*> operands);

  /// Each point of `ring` replaced by its exact counterpart when one lies within the snap
  /// distance; consecutive points that became equal are merged.
  void apply(std::vector<Point2>& ring) const;

 private:
  Point2 snap(const Point2& p) const;
  bool nearest_vertex(const Point2& p, Point2& out) const;
  bool nearest_crossing(const Point2& p, Point2& out) const;

  std::vector<Point2> vertices_;                  // sorted by x
  std::vector<std::pair<Point2, Point2>> edges_;
  double distance_ = 0.0;                         // the snap distance (max norm)
};

}  // namespace certimesh::generators::detail
