#include "bench_delaunay_3d_cgal.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

namespace certimesh::bench {

std::size_t cgal_delaunay_cells(const std::vector<std::array<double, 3>>& points) {
  using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
  std::vector<Kernel::Point_3> cgal_points;
  cgal_points.reserve(points.size());
  for (const auto& [x, y, z] : points) cgal_points.emplace_back(x, y, z);
  CGAL::Delaunay_triangulation_3<Kernel> dt;
  dt.insert(cgal_points.begin(), cgal_points.end());
  return dt.number_of_finite_cells();
}

}  // namespace certimesh::bench
