// The 3D meshing pipeline (issue 13): a solid given by a point set (its convex hull, as TetGen
// meshes a .node) or, once boundary recovery lands, by a closed surface, tetrahedralized by
// exact Delaunay and refined to a size and a radius-edge bound. One stage per file in
// generators/src/pipeline_3; the result carries each stage's time and counts for the CLI.
//
//   stage        what it does                                   worst-case cost
//   validation   the surface's exact checks (surface_validation_3.h)  quadratic when every
//                                                               triangle's box meets every other
//   recovery     Delaunay3 of the surface's vertices, the surface recovered and its trace
//                restored (boundary_recovery_3.h; its proof note states the bounds)
//   delaunay     Delaunay3 of the points (delaunay_3.h)         O(n^2) (n log n expected on
//                                                               spread points, BRIO order)
//   refinement   refine_tetrahedra_3 (tetrahedral_refinement_3.h) O(k) expected for k new
//                                                               points; each walk bounded
//   improvement  improve_tetrahedra_3 (quality_improvement_3.h)  O(N log N) per pass, a
//                                                               bounded number of passes
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "certimesh/generators/delaunay/tetrahedral_refinement_3.h"
#include "certimesh/generators/domain/surface_3.h"
#include "certimesh/generators/improvement/quality_improvement_3.h"
#include "certimesh/generators/progress.h"
#include "certimesh/io/mesh_data.h"

namespace certimesh::generators {

struct MeshOptions3 {
  /// --size H: the largest edge length wanted; 0: sizes from the boundary's own edges,
  /// growing by `grading` per unit distance.
  double size = 0.0;
  double grading = 0.25;
  /// --radius-edge R: circumradius over shortest edge above which a tetrahedron is refined.
  double max_radius_edge = 2.0;
  /// Refine at all (a point set without --size or --radius-edge is not: its Delaunay
  /// tetrahedralization is the answer, as `tetgen` without -q gives).
  bool refine = true;
  std::uint64_t max_insertions = 0;  // 0: the refinement's own budget
  /// --refine-surface: Steiner points of the recovery may stay on the surface (each the
  /// rounding of an exact point of its edge or triangle); default: none on it.
  bool refine_surface = false;
  /// Sliver removal after refinement (quality_improvement_3.h; --no-improve turns it off). A
  /// point set that is not refined keeps its Delaunay tetrahedralization.
  bool improve = true;
};

struct StageTime {
  std::string_view stage;
  double seconds = 0.0;
};

struct MeshStats3 {
  std::size_t input_vertices = 0;           // input vertices in the mesh
  std::size_t unused_input_vertices = 0;    // in no surface triangle: left out
  std::size_t interior_steiner_points = 0;  // vertices added inside the solid
  std::size_t boundary_steiner_points = 0;  // vertices added on the boundary (0 by default)
  std::size_t surface_shells = 0, cavities = 0;
  std::size_t hole_tetrahedra = 0;          // removed by hole points (before refinement)
  TetrahedralRefinementStats refinement;
  ImprovementStats3 improvement;
  std::vector<StageTime> stages;            // in the order they ran
};

struct MeshResult3 {
  io::MeshData mesh;  // dimension 3, positive tetrahedra, input vertices first with their ids
  MeshStats3 stats;
};

/// The solid a closed surface bounds (where its winding number is not zero, design decision
/// 8): validated (InvalidSurface naming the first problems), the surface recovered exactly --
/// every input triangle a boundary face with bit-identical vertices, unless refine_surface --
/// then refined. Input vertices come first in their order; vertices in no triangle are left
/// out (and counted). TetGen's hole points remove their regions and region points label
/// theirs (solid_regions_3.h). Throws BoundaryRecoveryError when the recovery cannot finish,
/// SolidRegionsError for a hole or region point it cannot take.
MeshResult3 mesh_surface_3(Surface3 surface, const MeshOptions3& options, const ProgressCallback& progress = {});

/// The convex hull of the points of `points` (dimension 3), tetrahedralized and refined.
/// Throws DelaunayError as delaunay_of_points_3 does.
MeshResult3 mesh_convex_hull_3(const io::MeshData& points, const MeshOptions3& options,
                               const ProgressCallback& progress = {});

}  // namespace certimesh::generators
