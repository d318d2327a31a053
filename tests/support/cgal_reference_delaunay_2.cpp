// The 2D triangulations of cgal_reference.h (one translation unit: CGAL compiles slowly).
#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "cgal_reference.h"

namespace cgal_reference {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<Index, Kernel>;
using Fb = CGAL::Triangulation_face_base_with_info_2<Index, Kernel>;
using Dt = CGAL::Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vb, Fb>>;
using CdtFb = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<Kernel, CGAL::Triangulation_data_structure_2<Vb, CdtFb>,
                                                       CGAL::Exact_predicates_tag>;

}  // namespace

Triangulation2 delaunay_2(const std::vector<Point2>& points) {
  std::vector<std::pair<Kernel::Point_2, Index>> in;
  in.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) in.emplace_back(Kernel::Point_2(points[i][0], points[i][1]), Index(i));
  Dt dt(in.begin(), in.end());

  Triangulation2 out;
  out.dimension = dt.dimension();
  // The vertices and faces are numbered in iteration order (info); infinite faces get kInfinite.
  Index next = 0;
  for (auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    out.vertices.push_back({v->point().x(), v->point().y()});
    out.input.push_back(v->info());
    v->info() = next++;
  }
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) f->info() = kInfinite;
  next = 0;
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f) {
    f->info() = next++;
    out.triangles.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  }
  for (auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    out.neighbours.push_back({f->neighbor(0)->info(), f->neighbor(1)->info(), f->neighbor(2)->info()});
  for (auto f = dt.all_faces_begin(); f != dt.all_faces_end(); ++f) out.infinite_faces += dt.is_infinite(f) ? 1 : 0;
  for (auto e = dt.finite_edges_begin(); e != dt.finite_edges_end(); ++e) ++out.finite_edges;
  if (dt.dimension() >= 1) {
    auto c = dt.incident_vertices(dt.infinite_vertex()), done = c;
    do out.hull.push_back(c->info());
    while (++c != done);
  }
  out.infinite_vertex_degree = dt.degree(dt.infinite_vertex());
  return out;
}

std::vector<std::array<Index, 3>> constrained_delaunay_2(const std::vector<Point2>& points,
                                                         const std::vector<std::array<Index, 2>>& constraints) {
  Cdt cdt;
  std::vector<Cdt::Vertex_handle> handles;
  for (std::size_t i = 0; i < points.size(); ++i) {
    handles.push_back(cdt.insert(Kernel::Point_2(points[i][0], points[i][1])));
    handles.back()->info() = Index(i);
  }
  for (const auto& e : constraints) cdt.insert_constraint(handles[e[0]], handles[e[1]]);
  std::vector<std::array<Index, 3>> out;
  for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
    out.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
  return out;
}

}  // namespace cgal_reference
