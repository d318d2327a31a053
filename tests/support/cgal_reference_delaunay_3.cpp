// The 3D Delaunay triangulation of cgal_reference.h (one translation unit: CGAL compiles slowly).
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include "cgal_reference.h"

namespace cgal_reference {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_3<Index, Kernel>;
using Cb = CGAL::Triangulation_cell_base_with_info_3<Index, Kernel>;
using Dt = CGAL::Delaunay_triangulation_3<Kernel, CGAL::Triangulation_data_structure_3<Vb, Cb>>;

}  // namespace

Triangulation3 delaunay_3(const std::vector<Point3>& points) {
  std::vector<std::pair<Kernel::Point_3, Index>> in;
  in.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    in.emplace_back(Kernel::Point_3(points[i][0], points[i][1], points[i][2]), Index(i));
  Dt dt(in.begin(), in.end());

  Triangulation3 out;
  out.dimension = dt.dimension();
  // The vertices and cells are numbered in iteration order (info); infinite cells get kInfinite.
  Index next = 0;
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    out.vertices.push_back({v->point().x(), v->point().y(), v->point().z()});
    out.input.push_back(v->info());
    v->info() = next++;
  }
  for (auto c = dt.all_cells_begin(); c != dt.all_cells_end(); ++c) c->info() = kInfinite;
  next = 0;
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    c->info() = next++;
    out.tetrahedra.push_back({c->vertex(0)->info(), c->vertex(1)->info(), c->vertex(2)->info(), c->vertex(3)->info()});
  }
  for (auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c)
    out.neighbours.push_back({c->neighbor(0)->info(), c->neighbor(1)->info(), c->neighbor(2)->info(), c->neighbor(3)->info()});
  out.infinite_cells = dt.number_of_cells() - dt.number_of_finite_cells();
  out.finite_facets = dt.number_of_finite_facets();
  out.finite_edges = dt.number_of_finite_edges();
  out.infinite_vertex_degree = dt.degree(dt.infinite_vertex());
  return out;
}

}  // namespace cgal_reference
