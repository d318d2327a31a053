// The exact test for any input, degenerate elements included: do two elements meet
// outside the simplex sigma spanned by their shared vertices? Slower than the rules; the
// exact mode calls it only for degenerate elements (zero length, area or volume).
//
// 1. Each element becomes its distinct points; sigma the distinct shared points. An
//    element whose points all lie in sigma meets the other only inside sigma.
// 2. Otherwise sigma is a point or a segment, and each element is split into
//    non-degenerate pieces that have sigma as a face (simplex_pieces.h). A piece pair
//    meets sigma exactly in the face C spanned by their common vertices in sigma.
// 3. Pieces F, G meet outside a common face C iff, for some s in C, F without s meets G
//    outside C without s, or F meets G without s likewise. (Walk from a point x inside
//    C towards a common point outside C: the walk leaves F or G first, through a face
//    that misses x, hence misses some s in C; faces of a non-degenerate simplex meet
//    C only in their own vertices.) With C empty it is hulls_intersect (hull_intersection.h).
#pragma once

#include <span>

#include "certimesh/predicates/intersection/vertex.h"

namespace certimesh::predicates::intersection_detail {

bool exact_overlap(std::span<const Vertex3> a, std::span<const Vertex3> b);

}  // namespace certimesh::predicates::intersection_detail
