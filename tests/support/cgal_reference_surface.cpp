// The convex hull and the surface queries of cgal_reference.h (one translation unit: CGAL
// compiles slowly).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orientation.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/convex_hull_3.h>

#include <iterator>

#include "cgal_reference.h"

namespace cgal_reference {
namespace {

namespace PMP = CGAL::Polygon_mesh_processing;
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Epeck = CGAL::Exact_predicates_exact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<Epick::Point_3>;
using ExactMesh = CGAL::Surface_mesh<Epeck::Point_3>;

}  // namespace

HullMesh convex_hull_3(const std::vector<Point3>& points) {
  std::vector<Epick::Point_3> in;
  in.reserve(points.size());
  for (const Point3& p : points) in.emplace_back(p[0], p[1], p[2]);
  Mesh hull;
  CGAL::convex_hull_3(in.begin(), in.end(), hull);
  HullMesh out;
  auto index = hull.add_property_map<Mesh::Vertex_index, Index>("v:reference_index", kInfinite).first;
  for (const auto v : hull.vertices()) {
    index[v] = Index(out.vertices.size());
    out.vertices.push_back({hull.point(v).x(), hull.point(v).y(), hull.point(v).z()});
  }
  for (const auto f : hull.faces()) {
    std::vector<Index>& face = out.faces.emplace_back();
    for (const auto v : CGAL::vertices_around_face(hull.halfedge(f), hull)) face.push_back(index[v]);
  }
  out.closed = CGAL::is_closed(hull);
  out.outward_oriented = out.closed && hull.number_of_faces() >= 4 && PMP::is_outward_oriented(hull);
  return out;
}

std::optional<std::vector<std::pair<Index, Index>>> self_intersections(
    const std::vector<Point3>& points, const std::vector<std::array<Index, 3>>& triangles) {
  ExactMesh m;
  for (const Point3& p : points) m.add_vertex(Epeck::Point_3(p[0], p[1], p[2]));
  for (const auto& t : triangles) {
    const auto f = m.add_face(ExactMesh::Vertex_index(t[0]), ExactMesh::Vertex_index(t[1]), ExactMesh::Vertex_index(t[2]));
    if (f == ExactMesh::null_face()) return std::nullopt;
  }
  std::vector<std::pair<ExactMesh::Face_index, ExactMesh::Face_index>> found;
  PMP::self_intersections(m, std::back_inserter(found));
  std::vector<std::pair<Index, Index>> out;
  for (const auto& [a, b] : found) out.emplace_back(Index(a.idx()), Index(b.idx()));
  return out;
}

bool strictly_inside(const std::vector<Point3>& points, const std::vector<std::array<Index, 3>>& triangles,
                     const Point3& q) {
  Mesh m;
  for (const Point3& p : points) m.add_vertex(Epick::Point_3(p[0], p[1], p[2]));
  for (const auto& t : triangles) m.add_face(Mesh::Vertex_index(t[0]), Mesh::Vertex_index(t[1]), Mesh::Vertex_index(t[2]));
  const CGAL::Side_of_triangle_mesh<Mesh, Epick> side(m);
  return side(Epick::Point_3(q[0], q[1], q[2])) == CGAL::ON_BOUNDED_SIDE;
}

}  // namespace cgal_reference
