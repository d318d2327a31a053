// The tetrahedral mesh of the solid bounded by a closed triangulated surface (issue 13, item
// 4): a Delaunay tetrahedralization of the surface's vertices (Delaunay3), then the surface
// recovered in it (the monograph's Algorithm 18, digest C section 2.2) and its trace restored
// (Algorithm 19, section 2.3), every decision by exact predicates. proofs/boundary_recovery_3.md
// is the argument that it terminates and is correct on every valid surface.
//
// Stages:
//   1. edges:  every surface edge becomes a chain of mesh edges: walk along it from one end
//              and remove the face or edge it crosses by a flip (2-3 flip, edge removal)
//              where one is valid, else split it at the exact crossing point;
//   2. faces:  every surface triangle becomes a union of mesh faces: every mesh edge that
//              crosses its interior is removed by an edge removal where one is valid, else
//              split at the exact crossing point;
//   3. solid:  keep the tetrahedra where the winding number of the surface is non-zero;
//   4. trace:  (default) every Steiner point of stages 1-2 (all on the surface) is taken off
//              it: the surface faces around it are re-triangulated by diagonals without it and
//              the point moves to a double position inside its star where every incident
//              tetrahedron is positive by exact orient3d.
// During stages 1-3 a Steiner point is an exact rational point of its surface edge or
// triangle, so the recovered surface faces lie exactly in their input planes.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "certimesh/generators/progress.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators {

/// Thrown when the mesh cannot be made: input the recovery does not take (fewer than four
/// points, all in a plane, a non-finite point, a triangle index out of range; surfaces that
/// are not valid may also be detected, but validating is not this function's job), or a
/// Steiner point whose star holds no double position (proofs/boundary_recovery_3.md section 5
/// says when that can happen). The message says what and where.
class BoundaryRecoveryError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

struct BoundaryRecoveryOptions {
  /// false (default): the boundary is exactly the input surface, no Steiner point on it.
  /// true (--refine-surface): Steiner points stay on the surface, each the round-to-nearest
  /// of an exact point of its edge or triangle (design decision 2); BoundaryRecoveryError if
  /// rounding makes a tetrahedron non-positive.
  bool keep_surface_steiner_points = false;
};

struct BoundaryRecoveryCounts {
  std::size_t delaunay_tetrahedra = 0;   // of the surface's vertices
  std::size_t edge_steiner_points = 0;   // made on surface edges (stage 1)
  std::size_t face_steiner_points = 0;   // made inside surface triangles (stage 2)
  std::size_t flips = 0;                 // 2-3 flips and edge removals (stages 1-2), no point made
  std::size_t moved_inside = 0;          // of those, taken off the surface (stage 4)
  std::size_t outside_tetrahedra = 0;    // removed in stage 3
};

struct SolidMesh3 {
  /// The input points first, bit-identical and at their input indices, then the Steiner
  /// points. Input points no triangle uses are in the array but in no tetrahedron.
  std::vector<predicates::Point3> points;
  /// Positive tetrahedra (Medit/Gmsh: det[b-a, c-a, d-a] > 0, design decision 4).
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;
  BoundaryRecoveryCounts counts;
};

/// The tetrahedral mesh of the solid where the winding number of the oriented closed surface
/// (`triangles`, indices into `points`, counterclockwise seen from outside) is non-zero.
/// The surface must be valid (closed, manifold, no degenerate triangle, not self-intersecting:
/// generators/domain validates it); then every input triangle is exactly a boundary face
/// of the result (default) or a union of boundary faces (keep_surface_steiner_points).
/// Deterministic: same input, same output, bit for bit. Progress stages: "recovery".
SolidMesh3 tetrahedralize_solid_3(std::span<const predicates::Point3> points,
                                  std::span<const std::array<std::uint32_t, 3>> triangles,
                                  const BoundaryRecoveryOptions& options = {},
                                  const ProgressCallback& progress = {});

}  // namespace certimesh::generators
