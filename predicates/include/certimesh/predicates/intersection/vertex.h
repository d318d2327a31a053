// The vertices an intersection test receives: a point and the mesh's vertex id.
//
// Two elements share a vertex when the same id appears in both *with the same
// coordinates*; coordinates alone never make a vertex shared (two distinct ids at the
// same point are two vertices that touch, which counts as intersecting). An id that
// appears with different coordinates in the two elements is a caller error; the tests
// then treat the two vertices as unrelated, which can only turn "disjoint" into
// "intersect". The same id twice within one element means nothing: that element is the
// convex hull of its coordinates.
#pragma once

#include <cstdint>

#include "certimesh/predicates/point.h"

namespace certimesh::predicates {

struct Vertex2 {
  Point2 point;
  std::int64_t id = 0;
};

struct Vertex3 {
  Point3 point;
  std::int64_t id = 0;
};

}  // namespace certimesh::predicates
