// Ideal-point smoothing of the vertices around poor triangles: each free vertex moves toward
// the mean of the apexes of the equilateral triangles standing on the far edges of its star,
// or toward the centroid of its link (whichever of a few steps is best), and the move is kept
// only when every triangle of the star stays positively oriented (exact
// orient2d) and the star's worst quality strictly rises -- so no move can tangle the mesh or
// lower its quality. Flat arrays, a few sweeps: cheap enough to run before Algorithm 35,
// which then has far fewer poor triangles to work on.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "certimesh/generators/domain/planar_domain.h"
#include "improvement_region.h"

namespace certimesh::generators::detail {

struct SmoothingStats {
  std::uint64_t candidates = 0;  // vertex visits
  std::uint64_t moved = 0;       // moves kept
};

/// Smooths the free vertices of triangles below `target` (shape quality) and of their
/// neighbours, `sweeps` times. Vertices of `fixed_edges` never move. With `min_angle_floor`
/// > 0 (degrees) the star is scored by the floored score of angle_floor_2.h, so no move
/// brings a star triangle below the floor or lowers a smallest angle below it further.
SmoothingStats smooth_poor_regions(TriangleSoup& mesh, std::span<const DomainSegment> fixed_edges, double target,
                                   int sweeps, double min_angle_floor = 0.0);

}  // namespace certimesh::generators::detail
