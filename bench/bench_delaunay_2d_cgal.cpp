#include "bench_delaunay_2d_cgal.h"

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace certimesh::bench {

std::size_t cgal_delaunay_faces(const std::vector<std::pair<double, double>>& points) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_2> cgal_points;
  cgal_points.reserve(points.size());
  for (const auto& [x, y] : points) cgal_points.emplace_back(x, y);
  CGAL::Delaunay_triangulation_2<Kernel> dt;
  dt.insert(cgal_points.begin(), cgal_points.end());
  return dt.number_of_faces();
}

}  // namespace certimesh::bench
