// CGAL as the independent reference of the *_cgal_test.cpp files, behind plain functions over
// standard types: points in, index triangles / tetrahedra / pairs / booleans out.
//
// Why a library: CGAL's headers and templates cost 20-80 CPU s per translation unit, and the
// test files instantiated the same types again and again (Delaunay_triangulation_2/3 over
// Epick with info, convex_hull_3 into a Surface_mesh, the exact kernel's self-intersections).
// Here they are compiled once (cgal_reference_*.cpp), and a test file includes this header
// only. The library shares nothing with certimesh (no header, no type): it is an oracle.
//
// Every function does what the CGAL call it names does, on the points as given (no
// rescaling, no filtering); vertex indices are CGAL's iteration order unless said otherwise.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace cgal_reference {

using Point2 = std::array<double, 2>;
using Point3 = std::array<double, 3>;
using Index = std::uint32_t;
// The neighbour index of a face or cell whose neighbour is CGAL's infinite one.
inline constexpr Index kInfinite = 0xFFFFFFFFu;

// CGAL::Delaunay_triangulation_2 (Epick) of the points, inserted as one range of
// (point, input index) pairs.
struct Triangulation2 {
  int dimension = -1;
  std::vector<Point2> vertices;  // the finite vertices (duplicates merged), iteration order
  std::vector<Index> input;      // per vertex: the input index CGAL's info holds (one of the
                                 // equal points' indices)
  std::vector<std::array<Index, 3>> triangles;   // finite faces, CGAL's (counterclockwise) order
  std::vector<std::array<Index, 3>> neighbours;  // per face: neighbor(i), across from vertex i
                                                 // (a triangle index or kInfinite)
  std::vector<Index> hull;  // the vertices around the infinite vertex, circulator order
  std::size_t infinite_vertex_degree = 0;
  std::size_t infinite_faces = 0;
  std::size_t finite_edges = 0;
};
Triangulation2 delaunay_2(const std::vector<Point2>& points);

// CGAL::Constrained_Delaunay_triangulation_2 (Epick, exact predicates): the points inserted
// one by one, then each constraint (a pair of input indices). Triangles by input index.
std::vector<std::array<Index, 3>> constrained_delaunay_2(
    const std::vector<Point2>& points, const std::vector<std::array<Index, 2>>& constraints);

// CGAL::Delaunay_triangulation_3 (Epick) of the points, inserted as one range of
// (point, input index) pairs.
struct Triangulation3 {
  int dimension = -1;
  std::vector<Point3> vertices;  // the finite vertices (duplicates merged), iteration order
  std::vector<Index> input;      // per vertex: the input index CGAL's info holds
  std::vector<std::array<Index, 4>> tetrahedra;  // finite cells, CGAL's (positive) order
  std::vector<std::array<Index, 4>> neighbours;  // per cell: neighbor(i), across from vertex i
  std::size_t infinite_cells = 0;                // number_of_cells() - number_of_finite_cells()
  std::size_t finite_facets = 0;
  std::size_t finite_edges = 0;
  std::size_t infinite_vertex_degree = 0;
};
Triangulation3 delaunay_3(const std::vector<Point3>& points);

// CGAL::convex_hull_3 (Epick) of the points into a CGAL::Surface_mesh.
struct HullMesh {
  std::vector<Point3> vertices;            // the mesh's vertices, iteration order
  std::vector<std::vector<Index>> faces;   // vertices around each face (outward: counterclockwise)
  bool closed = false;                     // CGAL::is_closed
  // PMP::is_outward_oriented, asked only of a closed mesh of at least 4 faces (its
  // precondition); false otherwise.
  bool outward_oriented = false;
};
HullMesh convex_hull_3(const std::vector<Point3>& points);

// PMP::self_intersections with the exact kernel (Epeck) on the triangles (face i = triangle
// i), touchings included: each intersecting pair once, as CGAL lists it. nullopt when a
// triangle cannot be added to a CGAL::Surface_mesh (a non-manifold surface).
std::optional<std::vector<std::pair<Index, Index>>> self_intersections(
    const std::vector<Point3>& points, const std::vector<std::array<Index, 3>>& triangles);

// CGAL::Side_of_triangle_mesh (Epick, exact predicates) of the closed surface: whether q is
// ON_BOUNDED_SIDE.
bool strictly_inside(const std::vector<Point3>& points,
                     const std::vector<std::array<Index, 3>>& triangles, const Point3& q);

}  // namespace cgal_reference
