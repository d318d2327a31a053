// Built-in domains: the README's default (a plate with holes and a crack), the unit square,
// and the square with two round holes of the monograph's regrading experiment (§5.2).
#pragma once

#include <cstddef>

#include "certimesh/generators/domain/planar_domain.h"

namespace certimesh::generators {

/// The 4 x 2 plate [0,4] x [0,2] with two round holes of radius 0.4 about (1,1) and (3,1)
/// (32 segments each) and a crack: the open polyline (2,0)-(2,0.25)-(2.125,0.5)-(2.125,0.75)
/// from the middle of the bottom edge into the plate (an internal cut, the domain on both
/// sides; its tip (2.125,0.75) has degree 1). Segment labels: outer boundary 1, holes 2 and 3,
/// crack 4. Hole points at the hole centres. Every coordinate but the holes' is dyadic.
PlanarDomain plate_with_holes_and_crack();

/// The unit square [0,1]^2: 4 vertices, 4 segments labelled 1.
PlanarDomain unit_square();

/// The monograph's §5.2 domain, reconstructed (the book gives no coordinates): the unit square
/// (label 1) with two round holes of radius 0.1 about (0.3,0.5) and (0.7,0.5) (labels 2 and
/// 3), each a regular polygon of `segments_per_hole` sides (16 by default: at the ~1,800
/// triangles of the experiment, h ~ 0.034, the pipeline refines them further).
PlanarDomain square_with_two_holes(std::size_t segments_per_hole = 16);

}  // namespace certimesh::generators
