// Input points of the predicate kernel: plain double coordinates, no behaviour.
#pragma once

namespace certimesh::predicates {

struct Point2 {
  double x = 0.0;
  double y = 0.0;
  friend constexpr bool operator==(const Point2&, const Point2&) = default;
};

struct Point3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  friend constexpr bool operator==(const Point3&, const Point3&) = default;
};

}  // namespace certimesh::predicates
