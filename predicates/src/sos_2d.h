// The perturbed signs of orient2d and incircle on degenerate input, without the generic
// monomial search (private to the kernel).
//
// The scheme is the one of symbolic_perturbation.h, and the answers are the generic
// search's (detail::perturbed_sign), answer for answer: tests/predicates/sos_2d_test.cpp
// compares the two. The generic search costs GMP minors (~10 us a call); in 2D the first
// monomials whose coefficient can be non-zero have coefficients that are comparisons of
// coordinates or exact orient2d signs, and the search always ends among them (sos_2d.cpp
// derives the order and the signs), so these cost a few comparisons and at most one exact
// orientation.
#pragma once

#include "certimesh/predicates/point.h"
#include "certimesh/predicates/sign.h"

namespace certimesh::predicates::detail {

/// orient2d_sos of three pairwise distinct points whose exact orientation is zero.
Sign collinear_orient2d_sos(const Point2& a, const Point2& b, const Point2& c) noexcept;

/// incircle_sos of four pairwise distinct points whose exact in-circle sign is zero.
/// Throws only what orient2d throws (NonFiniteInput), which the caller has excluded.
Sign cocircular_incircle_sos(const Point2& a, const Point2& b, const Point2& c, const Point2& d);

}  // namespace certimesh::predicates::detail
