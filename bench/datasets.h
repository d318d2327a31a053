// The input data sets: uniform random tuples and near-degenerate ones (points on a
// line / plane / circle / sphere, rounded to double), as in
// docs design note predicates.md §1. Deterministic (fixed seeds).
#pragma once

#include <cstddef>
#include <vector>

#include "impls.h"

namespace certimesh_bench {

struct DataSet {
  Predicate predicate;
  bool near_degenerate;
  std::size_t ntuples;
  std::vector<Point2> p2;  // 2D predicates: ntuples * arity points
  std::vector<Point3> p3;  // 3D predicates
  const void* points() const {
    return is_2d(predicate) ? static_cast<const void*>(p2.data())
                            : static_cast<const void*>(p3.data());
  }
};

DataSet make_dataset(Predicate p, bool near_degenerate, std::size_t ntuples);

}  // namespace certimesh_bench
