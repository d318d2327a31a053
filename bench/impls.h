// Out-of-line entry points of the benchmarked loops. Each call runs the *whole* timed
// loop over a data set and returns the sum of the signs, so no variant pays a per-call
// penalty the others do not (see RESULTS.md, "Harness").
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "certimesh/predicates/point.h"

namespace certimesh_bench {

using certimesh::predicates::Point2;
using certimesh::predicates::Point3;

enum class Predicate { orient2d, orient3d, incircle, insphere };
// naive: double determinant, same formula as the filter; filtered: certimesh X();
// filteronly: certimesh X_filtered(); exact: detail::X_exact_stage(); prototype_ozaki: orient2d only,
// an Ozaki-style filter; prototype_fastexact: orient2d only, that filter plus an
// expansion-free exact path for exact differences (neither is certimesh's number); shewchuk: Shewchuk's adaptive
// predicates.c (reference peer, one out-of-line C call per predicate).
enum class Impl {
  naive,
  filtered,
  filteronly,
  exact,
  prototype_ozaki,
  prototype_fastexact,
  shewchuk
};

/// Points per tuple of each predicate.
constexpr std::size_t arity(Predicate p) {
  return p == Predicate::orient2d ? 3 : p == Predicate::insphere ? 5 : 4;
}
constexpr bool is_2d(Predicate p) {
  return p == Predicate::orient2d || p == Predicate::incircle;
}

// certimesh_loops.cpp (compiled with the kernel's floating-point flags).
// `points` holds ntuples * arity(p) points, tuple after tuple (Point2 for 2D predicates,
// Point3 for 3D ones).
long long certimesh_sum(Predicate p, Impl impl, const void* points, std::size_t ntuples);
void certimesh_signs(Predicate p, Impl impl, const void* points, std::size_t ntuples,
                     std::int8_t* out);

// cgal_peer.cpp: CGAL Epick. The points are converted to CGAL points once, outside the
// timed region. Signs follow certimesh's conventions (orient3d and insphere negated).
class CgalPoints {
 public:
  CgalPoints(Predicate p, const void* points, std::size_t ntuples);
  ~CgalPoints();
  CgalPoints(const CgalPoints&) = delete;
  CgalPoints& operator=(const CgalPoints&) = delete;
  long long sum() const;
  void signs(std::int8_t* out, std::size_t ntuples) const;  // the first ntuples

 private:
  struct Data;
  std::unique_ptr<Data> data_;
};

}  // namespace certimesh_bench
