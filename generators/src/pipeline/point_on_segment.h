// Steiner points on input segments (design decision 2): the exact point a + f·(b − a) of the
// segment, for a fraction f in [0, 1] given as a double, rounded once to the nearest double
// coordinate-wise. The certificate then finds the segment inside the point's rounding box.
#pragma once

#include "certimesh/predicates/point.h"

namespace certimesh::generators::detail {

/// Round-to-nearest (ties to even) of the exact point a + f·(b − a). Finite a, b; f ∈ [0, 1].
predicates::Point2 point_on_segment(const predicates::Point2& a, const predicates::Point2& b, double f);

}  // namespace certimesh::generators::detail
