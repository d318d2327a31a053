// Why the first few monomials decide, and with which signs.
//
// The generic search (symbolic_perturbation.cpp) gives the perturbed entry of significance
// index i the infinitesimal eps^(2^i), so a set S of perturbed entries is a monomial of
// degree sum_{i in S} 2^i: the search visits the sets in increasing order of their bitmask
// and stops at the first one that is a partial matching (no two entries in one row or
// column) whose coefficient is not zero. That coefficient is the complementary minor times
// (-1)^(sum of rows + sum of columns) times the sign of the matching; for a single entry
// (row r, column c) it is the cofactor (-1)^(r+c) det(rest). Rows are the arguments in
// argument order; "rank" is the lexicographic (x, y) rank.
//
// orient2d, matrix rows (x, y, 1). Symbols: (rank k, axis c) has index 2k + c.
//   mask 1, x entry of the rank-0 point (row r): (-1)^r det[y 1] of the other rows s < t,
//     that is (-1)^r (y_s - y_t);
//   mask 2, its y entry: (-1)^(r+1) (x_s - x_t).
//   Distinct s, t differ in x or y, so the search ends here.
//
// incircle, matrix rows (x, y, q, 1) with q = x^2 + y^2. Symbols: the lifted entry of rank
// k has index k, (rank k, axis c) has index 4 + 2k + c.
//   masks 1, 2, 4, 8, the lifted entries in rank order (the other masks below 16 put two
//     entries in the lifted column): (-1)^(r+2) det[x y 1] of the other rows, that is
//     (-1)^r orient2d(other three in argument order).
//   Mask 1 decides unless all four points are collinear. If the three points other than
//   the rank-0 point lie on a line L, their lifts (x, y, q) are three non-collinear points
//   (a parabola meets a line at most twice) spanning the vertical plane over L; the lifted
//   determinant being zero, the fourth row is a combination of theirs with weights summing
//   to 1 (the ones column), so the fourth lift lies in that plane and the fourth point on L.
//   Then masks 2, 4, 8 vanish too. With all four collinear, p = P + t D with D != 0, and for
//   u in {x, y}, by multilinearity in the columns (u = P_u + t D_u, q = |P|^2 + 2 t P.D +
//   t^2 |D|^2), det[u q 1] over rows i < j < k = D_u |D|^2 (t_j - t_i)(t_k - t_i)(t_k - t_j),
//   whose sign is that of (u_j - u_i)(u_k - u_i)(u_k - u_j) = D_u^3 (same product of t).
//   mask 16, x entry of the rank-0 point (row r): (-1)^r det[y q 1] of the other rows.
//     Zero only when D_y = 0: a horizontal line, all y equal. Then
//   masks 18, 20, 24 (a lifted entry of another row with that x entry): +-(y_s - y_t) of
//     the two remaining rows, zero on a horizontal line; the other masks up to 31 repeat a
//     row or the lifted column.
//   mask 32, y entry of the rank-0 point: (-1)^(r+1) det[x q 1] of the other rows, non-zero
//     since D_x != 0 on a horizontal line.
#include "sos_2d.h"

#include <array>
#include <cstddef>

#include "certimesh/predicates/orient2d.h"

namespace certimesh::predicates::detail {

namespace {

bool lexicographically_less(const Point2& p, const Point2& q) noexcept {
  return p.x < q.x || (p.x == q.x && p.y < q.y);
}

/// The sign of u - v, decided by comparison: the difference of two doubles has the sign of
/// their order, without computing it (it may not be representable).
Sign difference_sign(double u, double v) noexcept {
  return u > v ? Sign::positive : (u < v ? Sign::negative : Sign::zero);
}

/// The cofactor sign (-1)^parity applied to s.
Sign alternate(Sign s, std::size_t parity) noexcept { return (parity & 1u) ? -s : s; }

/// Sign of (u_j - u_i)(u_k - u_i)(u_k - u_j): the sign of det[u q 1] on collinear points.
Sign ordered_product_sign(double ui, double uj, double uk) noexcept {
  return difference_sign(uj, ui) * difference_sign(uk, ui) * difference_sign(uk, uj);
}

/// The row of the lexicographically smallest of N distinct points: the rank-0 point, whose
/// entries are the most significant symbols of their column.
template <std::size_t N>
std::size_t rank0_row(const std::array<const Point2*, N>& row) noexcept {
  std::size_t r = 0;
  for (std::size_t i = 1; i < N; ++i)
    if (lexicographically_less(*row[i], *row[r])) r = i;
  return r;
}

/// The rows other than `row`, in increasing order.
template <std::size_t N>
std::array<std::size_t, N - 1> other_rows(std::size_t row) noexcept {
  std::array<std::size_t, N - 1> rest{};
  for (std::size_t i = 0, k = 0; i < N; ++i)
    if (i != row) rest[k++] = i;
  return rest;
}

}  // namespace

Sign collinear_orient2d_sos(const Point2& a, const Point2& b, const Point2& c) noexcept {
  const std::array<const Point2*, 3> row{&a, &b, &c};
  const std::size_t r = rank0_row(row);
  const auto [s, t] = other_rows<3>(r);
  const Sign x_entry = difference_sign(row[s]->y, row[t]->y);  // mask 1
  if (x_entry != Sign::zero) return alternate(x_entry, r);
  return alternate(difference_sign(row[s]->x, row[t]->x), r + 1);  // mask 2
}

Sign cocircular_incircle_sos(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const std::array<const Point2*, 4> row{&a, &b, &c, &d};
  const std::size_t r = rank0_row(row);
  const auto [i, j, k] = other_rows<4>(r);
  const Sign lifted_entry = orient2d(*row[i], *row[j], *row[k]);  // mask 1
  if (lifted_entry != Sign::zero) return alternate(lifted_entry, r);
  // All four collinear: masks 2, 4, 8 vanish.
  const Sign x_entry = ordered_product_sign(row[i]->y, row[j]->y, row[k]->y);  // mask 16
  if (x_entry != Sign::zero) return alternate(x_entry, r);
  return alternate(ordered_product_sign(row[i]->x, row[j]->x, row[k]->x), r + 1);  // mask 32
}

}  // namespace certimesh::predicates::detail
