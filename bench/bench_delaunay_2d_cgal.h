// The CGAL peer of bench_delaunay_2d: Delaunay_triangulation_2<Epick> with its own spatial
// sort (insert(begin, end)), in a translation unit of its own (CGAL needs -frounding-math).
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace certimesh::bench {

/// Triangulates the points with CGAL; returns the number of finite faces.
std::size_t cgal_delaunay_faces(const std::vector<std::pair<double, double>>& points);

}  // namespace certimesh::bench
