// The CGAL side of the benchmark, in its own translation unit so that no other bench
// file includes CGAL. Kernel: CGAL::Exact_predicates_inexact_constructions_kernel
// (Epick = Filtered_kernel<Simple_cartesian<double>>: semi-static filter, then interval
// arithmetic, then exact arithmetic).
//
// The timed loop is the same template (loop.h) as for certimesh's predicates, and it
// runs here, inside this TU, with CGAL's predicate functor inlined into it: CGAL pays
// one out-of-line call per pass over the data, exactly as certimesh does.
//
// Sign conventions (checked against certimesh's exact stages on every data set at
// start-up, bench_predicates.cpp):
//   orient2d(a,b,c)      ==  CGAL::orientation(a,b,c)                 (both det[b-a; c-a])
//   orient3d(a,b,c,d)    == -CGAL::orientation(a,b,c,d)               (Shewchuk: d below
//                           the ccw plane abc is positive; CGAL: d on the positive side)
//   incircle(a,b,c,d)    ==  CGAL::side_of_oriented_circle(a,b,c,d)
//   insphere(a,b,c,d,e)  == -CGAL::side_of_oriented_sphere(a,b,c,d,e) (follows orient3d)
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <vector>

#include "impls.h"
#include "loop.h"

namespace certimesh_bench {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

struct CgalPoints::Data {
  Predicate predicate;
  std::size_t ntuples;
  std::vector<K::Point_2> p2;
  std::vector<K::Point_3> p3;
};

CgalPoints::CgalPoints(Predicate p, const void* points, std::size_t ntuples)
    : data_(std::make_unique<Data>()) {
  data_->predicate = p;
  data_->ntuples = ntuples;
  const std::size_t n = ntuples * arity(p);
  if (is_2d(p)) {
    const auto* q = static_cast<const Point2*>(points);
    data_->p2.reserve(n);
    for (std::size_t i = 0; i < n; ++i) data_->p2.emplace_back(q[i].x, q[i].y);
  } else {
    const auto* q = static_cast<const Point3*>(points);
    data_->p3.reserve(n);
    for (std::size_t i = 0; i < n; ++i) data_->p3.emplace_back(q[i].x, q[i].y, q[i].z);
  }
}

CgalPoints::~CgalPoints() = default;

namespace {

template <class Loop>
long long run(const CgalPoints* /*unused*/, Predicate p, const std::vector<K::Point_2>& p2,
              const std::vector<K::Point_3>& p3, std::size_t n, Loop loop) {
  const K k;
  switch (p) {
    case Predicate::orient2d: {
      const auto f = k.orientation_2_object();
      return loop.template operator()<3>(p2.data(), n, [f](const K::Point_2* t) {
        return static_cast<int>(f(t[0], t[1], t[2]));
      });
    }
    case Predicate::orient3d: {
      const auto f = k.orientation_3_object();
      return loop.template operator()<4>(p3.data(), n, [f](const K::Point_3* t) {
        return -static_cast<int>(f(t[0], t[1], t[2], t[3]));
      });
    }
    case Predicate::incircle: {
      const auto f = k.side_of_oriented_circle_2_object();
      return loop.template operator()<4>(p2.data(), n, [f](const K::Point_2* t) {
        return static_cast<int>(f(t[0], t[1], t[2], t[3]));
      });
    }
    case Predicate::insphere: {
      const auto f = k.side_of_oriented_sphere_3_object();
      return loop.template operator()<5>(p3.data(), n, [f](const K::Point_3* t) {
        return -static_cast<int>(f(t[0], t[1], t[2], t[3], t[4]));
      });
    }
  }
  return 0;
}

}  // namespace

long long CgalPoints::sum() const {
  return run(this, data_->predicate, data_->p2, data_->p3, data_->ntuples,
             []<std::size_t Ar, class P, class F>(const P* pts, std::size_t n, F f) {
               return sum_signs<Ar>(pts, n, f);
             });
}

void CgalPoints::signs(std::int8_t* out, std::size_t ntuples) const {
  run(this, data_->predicate, data_->p2, data_->p3, std::min(ntuples, data_->ntuples),
      [out]<std::size_t Ar, class P, class F>(const P* pts, std::size_t n, F f) {
        store_signs<Ar>(pts, n, out, f);
        return 0LL;
      });
}

}  // namespace certimesh_bench
