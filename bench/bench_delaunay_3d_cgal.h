// The CGAL peer of bench_delaunay_3d: Delaunay_triangulation_3<Epick> with its own spatial
// sort (insert(begin, end)), in a translation unit of its own (CGAL needs -frounding-math).
#pragma once

#include <array>
#include <cstddef>
#include <vector>

namespace certimesh::bench {

/// Tetrahedralizes the points with CGAL; returns the number of finite cells.
std::size_t cgal_delaunay_cells(const std::vector<std::array<double, 3>>& points);

}  // namespace certimesh::bench
