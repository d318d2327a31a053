// ConstrainedDelaunay2 against CGAL (the independent oracle): the same triangles as
// Delaunay_triangulation_2 on generic random points (the Delaunay triangulation is unique
// there), the same triangles as Constrained_Delaunay_triangulation_2 with random polygon
// constraints, and the same hull edges on degenerate input (grid, points on a circle).
#include <gtest/gtest.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "dt_triangulation_checks.h"

namespace certimesh::testing {
namespace {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using VertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using DtData = CGAL::Triangulation_data_structure_2<VertexBase>;
using CgalDelaunay = CGAL::Delaunay_triangulation_2<Kernel, DtData>;
using CdtVertexBase = CGAL::Triangulation_vertex_base_with_info_2<std::uint32_t, Kernel>;
using CdtFaceBase = CGAL::Constrained_triangulation_face_base_2<Kernel>;
using CdtData = CGAL::Triangulation_data_structure_2<CdtVertexBase, CdtFaceBase>;
using CgalConstrained = CGAL::Constrained_Delaunay_triangulation_2<Kernel, CdtData, CGAL::Exact_predicates_tag>;

template <class Triangulation>
std::vector<std::pair<Kernel::Point_2, std::uint32_t>> with_ids(const std::vector<Point2>& points) {
  std::vector<std::pair<Kernel::Point_2, std::uint32_t>> out;
  for (std::uint32_t i = 0; i < points.size(); ++i) out.emplace_back(Kernel::Point_2(points[i].x, points[i].y), i);
  return out;
}

template <class Triangulation>
std::set<Triangle> cgal_triangles(const Triangulation& t) {
  std::set<Triangle> out;
  for (auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f)
    out.insert(canonical({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}));
  return out;
}

template <class Triangulation>
std::set<Edge> cgal_hull_edges(const Triangulation& t) {
  std::set<Edge> out;
  auto c = t.incident_vertices(t.infinite_vertex()), done = c;
  std::vector<std::uint32_t> hull;
  do hull.push_back(c->info());
  while (++c != done);
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const auto a = hull[i], b = hull[(i + 1) % hull.size()];
    out.insert({std::min(a, b), std::max(a, b)});
  }
  return out;
}

std::set<Edge> hull_edges(const std::vector<Triangle>& tris) {
  std::map<Edge, int> count;
  for (const Triangle& t : tris)
    for (int i = 0; i < 3; ++i) {
      const auto a = t[(i + 1) % 3], b = t[(i + 2) % 3];
      ++count[{std::min(a, b), std::max(a, b)}];
    }
  std::set<Edge> out;
  for (const auto& [e, n] : count)
    if (n == 1) out.insert(e);
  return out;
}

TEST(dt_cgal, SameTrianglesAsCgalOnRandomPoints) {
  for (std::uint64_t seed = 1; seed <= 3; ++seed) {
    const auto points = uniform_points(20000 / std::size_t(sanitizer_slowdown), seed);
    const auto ids = with_ids<CgalDelaunay>(points);
    const CgalDelaunay cgal(ids.begin(), ids.end());
    EXPECT_EQ(canonical_set(ConstrainedDelaunay2(points).triangles()), cgal_triangles(cgal)) << "seed " << seed;
  }
}

TEST(dt_cgal, SameTrianglesAsCgalConstrainedDelaunay) {
  std::mt19937_64 rng(4);
  for (int trial = 0; trial < 10; ++trial) {
    std::vector<Point2> points = star_polygon(80, {0, 0}, 0.5, 1.0, rng);
    const auto inner = star_polygon(30, {0.05, 0}, 0.1, 0.3, rng);
    points.insert(points.end(), inner.begin(), inner.end());
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 400; ++i) points.push_back({u(rng), u(rng)});
    std::vector<Edge> constraints;
    for (std::uint32_t i = 0; i < 80; ++i) constraints.push_back({i, (i + 1) % 80});
    for (std::uint32_t i = 0; i < 30; ++i) constraints.push_back({80 + i, 80 + (i + 1) % 30});

    ConstrainedDelaunay2 mine(points);
    for (const Edge& e : constraints) mine.insert_constraint(e[0], e[1]);
    CgalConstrained cgal;
    std::vector<CgalConstrained::Vertex_handle> handles;
    for (std::uint32_t i = 0; i < points.size(); ++i) {
      handles.push_back(cgal.insert(Kernel::Point_2(points[i].x, points[i].y)));
      handles.back()->info() = i;
    }
    for (const Edge& e : constraints) cgal.insert_constraint(handles[e[0]], handles[e[1]]);
    EXPECT_EQ(canonical_set(mine.triangles()), cgal_triangles(cgal)) << "trial " << trial;
  }
}

TEST(dt_cgal, SameHullAsCgalOnGridAndCircle) {
  std::vector<std::vector<Point2>> inputs{grid_points(sanitizer_slowdown > 1 ? 40 : 120)};
  std::vector<Point2> circle;
  const std::size_t n = 100000 / std::size_t(sanitizer_slowdown);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * double(i) / double(n);
    circle.push_back({std::cos(a), std::sin(a)});
  }
  inputs.push_back(circle);
  for (const auto& points : inputs) {
    const auto ids = with_ids<CgalDelaunay>(points);
    const CgalDelaunay cgal(ids.begin(), ids.end());
    const auto mine = ConstrainedDelaunay2(points).triangles();
    EXPECT_EQ(hull_edges(mine), cgal_hull_edges(cgal));
    EXPECT_EQ(mine.size(), cgal.number_of_faces());
  }
}

}  // namespace
}  // namespace certimesh::testing
