// The exact validation of a closed triangulated surface before 3D meshing (issue 13 item 3,
// design decision 8, docs/surface_input.md). Every decision is an exact predicate.
//
// Stages, in order; a stage runs only when the ones before it found nothing, so that each
// can rely on them (a self-intersection test needs non-degenerate triangles):
//   1. duplicate vertices (identical coordinates; -0 == 0), degenerate triangles (a repeated
//      corner, or three collinear corners: orient2d of all three coordinate projections zero),
//      duplicate triangles (the same vertex set);
//   2. edges: an edge of 1 triangle is open. An edge of 2 triangles joins them; in an oriented
//      surface they must traverse it in opposite directions. An edge of 2k >= 4 triangles
//      (shells touching along an edge) is valid in an oriented surface when, in their exact
//      order around the edge, the triangles alternate in the direction they give it (the
//      certificate's rule, certificate/src/boundary_manifold.cpp); each triangle is joined to
//      its neighbour across the sector in front of both. Any other edge is non-manifold; in an
//      unoriented surface (.poly/.smesh) every edge of 3 or more triangles is refused
//      (multi-material interfaces: not supported yet). Vertices shared by several shells
//      (pinches) are valid.
//   3. self-intersections: every pair of triangles that meet beyond the simplex of their shared
//      vertices (predicates/intersection/triangle_triangle_3d.h, exact mode): crossings,
//      touchings, coplanar overlaps of neighbours, folds. Broad phase: the triangles' bounding
//      boxes listed in the columns of a grid over two axes (width: twice the median box,
//      doubled until the lists hold at most 8N + 64 entries), then sort and sweep along the
//      third (the longest axis of the whole box) within each column.
//   4. shells (classes of triangles joined across edges): an unoriented shell is made coherent
//      (non_orientable if it cannot be) and then turned outward; every shell gets its
//      orientation (+1 outward: the winding number is 1 just inside) and the winding numbers of
//      the whole surface just outside and just inside it. The solid is where the winding
//      number is non-zero, so flipping every triangle never changes it: a single shell given
//      inward is its solid, an inward shell inside an outward one (or an outward one inside an
//      inward one) bounds a cavity, two nested shells of one orientation are an interface.
//
// Cost, worst case (N triangles, V vertices, S shells, K pairs of triangles listed in a common
// column and overlapping along the sweep axis): O(V log V + N log N) for stages 1-2;
// O(N log N + K) box tests and one exact triangle-triangle test per pair whose boxes overlap,
// for stage 3 -- K is N(N-1)/2 when every box meets every other (N long thin triangles across
// the whole model): quadratic, and so is a vertex in N triangles (all its pairs are tested);
// O(S N) for stage 4 (a ray per shell against the triangles listed in its grid column over y
// and z, all N when every box meets that column: nested shells round one axis). Memory O(N + V)
// (the column lists are capped at 8N + 64 entries).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "certimesh/generators/domain/surface_3.h"
#include "certimesh/generators/domain/surface_problem_3.h"

namespace certimesh::generators {

struct SurfaceShell {
  std::uint32_t first_triangle = 0;  // its smallest triangle index
  std::uint32_t triangle_count = 0;
  int orientation = 1;               // +1: outward (winding 1 just inside it), -1: inward
  int winding_outside = 0;           // the whole surface's winding number just outside it
  int winding_inside = 0;            // ... just inside it (= outside + orientation)
};

struct SurfaceCheck {
  std::vector<SurfaceProblem> problems;    // empty: valid (then the rest is filled)
  std::size_t intersecting_pairs = 0;      // all of them, even beyond the listed problems
  std::vector<std::uint32_t> shell_of;     // per triangle
  std::vector<SurfaceShell> shells;        // numbered by smallest triangle
  std::size_t solids = 0;                  // shells with winding 0 outside: an outer boundary
  std::size_t cavities = 0;                // shells with winding 0 inside: a void's boundary
  std::size_t interfaces = 0;              // shells with solid on both sides
  std::size_t unused_vertices = 0;         // points in no triangle (kept: the mesher's to place)
};

/// Validates `surface`, at most `max_problems` problems listed (first by stage, then by
/// smallest triangle indices). An unoriented surface that passes is oriented in place (its
/// triangles' corners reordered, each shell outward) and marked oriented.
SurfaceCheck check_surface(Surface3& surface, std::size_t max_problems = 16);

/// check_surface, throwing InvalidSurface when a problem is found.
SurfaceCheck validate_surface(Surface3& surface, std::size_t max_problems = 16);

}  // namespace certimesh::generators
