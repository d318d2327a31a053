// How an intersection test may answer, and what it answers.
//
// Two elements *intersect* when their closed point sets share a point outside the simplex
// spanned by their shared vertices (vertex.h). Sharing a vertex, an edge or a face and
// nothing more is `disjoint`: that keeps a mesh conformal.
#pragma once

#include <cstdint>

#include "certimesh/predicates/non_finite_input.h"

namespace certimesh::predicates {

enum class IntersectionMode : std::uint8_t {
  /// Filtered signs only (an uncertain filter counts as zero). May report a disjoint pair
  /// as intersecting (first-type error), never an intersecting pair as disjoint: every
  /// `disjoint` rests on a separating line or plane certified by certain signs.
  /// Never throws; NaN or infinite coordinates answer `intersect`.
  conservative,
  /// Exact signs; never wrong, for every finite input, degenerate elements included.
  /// Throws NonFiniteInput (non_finite_input.h) for NaN or infinite coordinates.
  exact,
};

enum class Overlap : std::uint8_t { disjoint, intersect };

}  // namespace certimesh::predicates
