// The perturbed (SoS) orientation and in-circle signs the Delaunay triangulation decides
// with, and shortcuts for their degenerate cases.
//
// predicates::orient2d_sos / incircle_sos evaluate the perturbation with GMP minors, a few
// microseconds a call; on an integer grid every unit square is cocircular and every grid line
// collinear, so that cost dominated. The perturbation scheme (predicates/
// symbolic_perturbation.h) makes the first monomials cheap in the common degenerate cases:
//   orient2d, three distinct collinear points: the most significant symbol is the x entry of
//     the lexicographically smallest point p (row r); its coefficient is the cofactor
//     (-1)^r (y_s - y_t) of the other two rows s < t; when that is 0, the y entry's:
//     (-1)^(r+1) (x_s - x_t), non-zero for distinct points.
//   incircle, four distinct cocircular points, no three collinear: the most significant
//     symbol is the lifted entry of the smallest point (row r, column 2): the cofactor
//     (-1)^r orient2d(other three rows in order), non-zero.
//   incircle, four distinct collinear points: see cocircular_incircle_sos.
// Only comparisons and one exact orient2d: no GMP. tests/generators/dt_perturbed_predicates_test.cpp
// checks the shortcuts against the kernel's _sos on many degenerate inputs.
#pragma once

#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/orient2d.h"

namespace certimesh::generators::detail {

using predicates::Point2;

inline bool lexicographically_less(const Point2& a, const Point2& b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

inline int sign_of(double v) { return (v > 0.0) - (v < 0.0); }

/// orient2d_sos for three distinct points whose exact orientation is zero.
inline int collinear_orient_sos(const Point2& a, const Point2& b, const Point2& c) {
  const Point2* row[3] = {&a, &b, &c};
  int r = 0;
  for (int i = 1; i < 3; ++i)
    if (lexicographically_less(*row[i], *row[r])) r = i;
  const Point2& s = *row[r == 0 ? 1 : 0];
  const Point2& t = *row[r == 2 ? 1 : 2];
  const int parity = (r & 1) ? -1 : 1;
  // Differences of doubles compared exactly: y_s - y_t has the sign of the comparison.
  const int dy = (s.y > t.y) - (s.y < t.y);
  if (dy != 0) return parity * dy;
  return -parity * ((s.x > t.x) - (s.x < t.x));
}

/// The perturbed orientation: filter, exact stage, then the shortcut; 0 only for equal points.
inline int orient_perturbed(const Point2& a, const Point2& b, const Point2& c) {
  const predicates::FilteredSign f = predicates::orient2d_filtered(a, b, c);
  if (predicates::is_certain(f)) return predicates::to_int(f);
  const predicates::Sign s = predicates::detail::orient2d_exact_stage(a, b, c);
  if (s != predicates::Sign::zero) return predicates::to_int(s);
  if (a == b || b == c || a == c) return 0;
  return collinear_orient_sos(a, b, c);
}

/// incircle_sos for four distinct points whose exact in-circle sign is zero.
inline int cocircular_incircle_sos(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const Point2* row[4] = {&a, &b, &c, &d};
  int r = 0;
  for (int i = 1; i < 4; ++i)
    if (lexicographically_less(*row[i], *row[r])) r = i;
  const Point2* rest[3];
  for (int i = 0, k = 0; i < 4; ++i)
    if (i != r) rest[k++] = row[i];
  const int o = predicates::to_int(predicates::orient2d(*rest[0], *rest[1], *rest[2]));
  const int parity = (r & 1) ? -1 : 1;
  if (o != 0) return parity * o;
  // Four collinear points: every lifted-only monomial vanishes. The next candidate is the x
  // entry of the smallest point, cofactor (-1)^r det[y, |p|^2, 1] of the other rows; on the
  // line p = P + t D that determinant is D_y |D|^2 (t2-t1)(t3-t1)(t3-t2), whose sign is that
  // of (y2-y1)(y3-y1)(y3-y2). On a horizontal line it is 0, and so are the monomials pairing
  // a lifted entry with it (y differences); then the y entry's: (-1)^(r+1) det[x, |p|^2, 1].
  // Distinct points on the line differ in the coordinate used: no zero factor.
  auto order_sign = [](double u1, double u2, double u3) {
    return (u2 > u1 ? 1 : -1) * (u3 > u1 ? 1 : -1) * (u3 > u2 ? 1 : -1);
  };
  if (!(rest[0]->y == rest[1]->y && rest[1]->y == rest[2]->y))
    return parity * order_sign(rest[0]->y, rest[1]->y, rest[2]->y);
  return -parity * order_sign(rest[0]->x, rest[1]->x, rest[2]->x);
}

/// The perturbed in-circle sign of d against (a, b, c): 0 only when d equals one of them.
inline int incircle_perturbed(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const predicates::FilteredSign f = predicates::incircle_filtered(a, b, c, d);
  if (predicates::is_certain(f)) return predicates::to_int(f);
  const predicates::Sign s = predicates::detail::incircle_exact_stage(a, b, c, d);
  if (s != predicates::Sign::zero) return predicates::to_int(s);
  if (a == d || b == d || c == d) return 0;
  return cocircular_incircle_sos(a, b, c, d);
}

}  // namespace certimesh::generators::detail
