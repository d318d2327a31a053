// Delaunay refinement of a tetrahedral mesh of a solid (issue 13, item 5): interior Steiner
// points are inserted until every tetrahedron meets the size and a radius-edge bound where
// that is safe. The boundary is kept exactly: no point is ever inserted on a boundary face
// or on a face between two regions, so every input triangle stays a face, bit for bit.
//
// Which faces are constraints: the mesh's boundary faces (a face of one tetrahedron), the
// faces between tetrahedra of different labels, and the faces the caller lists in
// `constrained_faces` (internal facets of one region). A cavity never crosses one.
//
// Insertion (refinement_mesh_3.h): the point is located by a visibility walk from the
// tetrahedron that asked for it; a walk that would cross a constraint, or does not arrive
// within a step bound, refuses the point (it lies outside the solid, behind an internal facet
// or too far). The cavity is the connected set of tetrahedra whose circumsphere holds the
// point strictly (exact insphere), never across a constraint, then shrunk until the point
// sees every cavity face strictly (exact orientation) and no vertex is inside it: the new
// tetrahedra are then positive and tile the cavity exactly. The mesh need not be Delaunay.
//
// Criteria, per tetrahedron: too big when its longest edge exceeds the size at its centroid;
// skinny when circumradius / shortest edge exceeds `max_radius_edge`. Both get their
// circumcentre when it is insertable and at least the tetrahedron's shortest edge (skinny) or
// a quarter of the size (too big) away from every vertex of its cavity; a too-big tetrahedron
// whose circumcentre is refused gets its centroid instead; a skinny one is left as it is.
//
// Sizes: `size_function` when given; else every vertex carries a size -- an input vertex the
// mean length of its boundary edges (or `uniform_size` when it has none), an inserted one the
// smallest h_u + grading * |p - u| over its cavity's vertices u -- capped by `uniform_size`
// when positive, and the size at a point is min_u (h_u + grading * |x - u|) over the
// tetrahedron's corners: sizes follow the surface's own edge lengths and grow away from it.
//
// Termination: new edges are never shorter than the shortest edge of the tetrahedron that
// asked (skinny) or a quarter of the local size (too big), and the loop also asserts an
// insertion budget (a packing bound from the volume and the smallest of these lengths,
// capped); reaching it stops the loop and says so (stats.bound_reached): it cannot hang.
// Deterministic: first-in first-out over tetrahedron ids, no randomness.
// Cost: O(1) expected per insertion for a well-spread mesh; the walk is bounded per point.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <vector>

#include "certimesh/generators/delaunay/tetrahedralization_3.h"
#include "certimesh/generators/progress.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators {

using predicates::Point3;

/// A size in 3D: a positive finite length at every point of the solid.
using SizeFunction3 = std::function<double(const Point3&)>;

struct TetrahedralRefinementOptions {
  SizeFunction3 size_function;   // when set, the size everywhere
  double uniform_size = 0.0;     // --size H: the largest size; 0 = none
  double grading = 0.25;         // growth of the size per unit distance from the vertices
  double max_radius_edge = 2.0;  // --radius-edge R (TetGen's -q default); 0 = no quality bound
  std::uint64_t max_insertions = 0;  // 0 = the packing budget described above
};

struct TetrahedralRefinementStats {
  std::uint64_t inserted = 0;       // Steiner points added
  std::uint64_t circumcentres = 0;  // of them, circumcentres
  std::uint64_t centroids = 0;      // of them, centroids of too-big tetrahedra
  std::uint64_t refused_outside = 0;  // candidates refused: outside the solid or behind a facet
  std::uint64_t refused_close = 0;    // candidates refused: too near a vertex or a boundary face
  std::uint64_t refused_other = 0;    // candidates refused: on a vertex or facet, not visible
  std::uint64_t skinny_left = 0;    // skinny tetrahedra left at the end
  std::uint64_t insertion_bound = 0;
  bool bound_reached = false;
};

/// Refines `mesh` in place (points appended, tetrahedra replaced). DelaunayError-free: the
/// input must be a valid mesh (positive tetrahedra, conforming); std::invalid_argument when a
/// tetrahedron is not positive or a face is shared by more than two.
TetrahedralRefinementStats refine_tetrahedra_3(Tetrahedralization3& mesh, const TetrahedralRefinementOptions& options,
                                               const ProgressCallback& progress = {});

}  // namespace certimesh::generators
