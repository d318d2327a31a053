// The input segments of a planar domain as the 2D local modifications read them when the
// boundary trace is kept only geometrically (topology/local_modifications_2.h,
// InputSegments2): which segment a boundary vertex lies inside, and the exact point of a
// segment rounded once (design decision 2), the same rule as the pipeline's boundary split.
#pragma once

#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/topology/local_modifications_2.h"

namespace certimesh::generators {

/// The domain's segments for the local modifications. A point is inside a segment when the
/// segment meets the box of the point's neighbouring doubles (which holds its rounding box),
/// decided exactly with orient2d and coordinate comparisons; a point that is a domain vertex,
/// or that meets several segments, is inside none (it stays fixed). The answer keeps a copy of
/// the segments; each query scans them (O(segments): meant for Algorithm 35 on domains of up
/// to a few hundred segments, as in the §5.2 experiment).
topology::InputSegments2 input_segments_of(const PlanarDomain& domain);

}  // namespace certimesh::generators
