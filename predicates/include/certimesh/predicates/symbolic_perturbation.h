// Simulation of simplicity (Edelsbrunner & Muecke, ACM TOG 9(1), 1990) for the four
// predicates: how their `_sos` variants turn an exact zero into a consistent non-zero sign.
//
// The scheme. Every point p gets a rank: its position in the lexicographic order of
// (x, y[, z]) -- a total order on distinct points that does not depend on the call, so
// every predicate call perturbs a point the same way. Each perturbed matrix entry
// (point p, column j) receives an infinitesimal e(p, j) = eps^(2^i), where i is the entry's
// place in this significance order:
//   1. for incircle and insphere, the lifted column |p|^2 of every point, by rank;
//   2. then the coordinates, by rank and then by axis.
// (The lifted column is treated as an independent coordinate, so the perturbed input is a
// weighted point set in general position; orient and in-sphere signs of the same points stay
// mutually consistent because the coordinate perturbation is the same in all four.)
// The perturbed determinant is a polynomial in eps whose monomials all have distinct
// degrees; its sign is the sign of the first monomial, in order of increasing degree, whose
// coefficient -- a signed minor of the unperturbed matrix -- is not zero. The column of ones
// is never perturbed, so the monomial that perturbs one entry in every other column has
// coefficient +-1: the sign is never zero when the points are distinct.
//
// Cost: one exact determinant when it is non-zero. For degenerate input, a few exact
// minors in GMP integers (rarely more than three; at most 501 for insphere) -- except in 2D,
// where orient2d_sos and incircle_sos reach the same answer by coordinate comparisons and at
// most one exact orient2d (src/sos_2d.cpp derives why the search always ends there).
#pragma once

#include <span>

#include "certimesh/predicates/sign.h"

namespace certimesh::predicates::detail {

/// The sign of the perturbed determinant of `point_count` points of dimension `dim`
/// (coordinates stored point after point), lifted when `lifted`. Call it only when the
/// exact determinant is zero and the points are pairwise distinct.
Sign perturbed_sign(std::span<const double> coordinates, int dim, bool lifted);

}  // namespace certimesh::predicates::detail
