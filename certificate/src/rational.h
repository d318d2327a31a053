// Internal: exact rational vectors for the domain checks (GMP). Every input double converts
// to an mpq_class exactly, so sums, products and comparisons here are exact.
#pragma once

#include <gmpxx.h>

#include <array>

#include "mesh_view.h"

namespace certimesh::certificate::detail {

using Q = mpq_class;
using Vec = std::array<Q, 3>;

inline Vec minus(const Vec& a, const Vec& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
inline Vec cross(const Vec& a, const Vec& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}
inline Q dot(const Vec& a, const Vec& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Q cross2(const Vec& a, const Vec& b) { return a[0] * b[1] - a[1] * b[0]; }
inline Vec point_of(const MeshView& g, Index v) {
  return {g.coord(v, 0), g.coord(v, 1), g.dim == 3 ? Q(g.coord(v, 2)) : Q(0)};
}
inline Vec point_of(const double* p, int dim) { return {p[0], p[1], dim == 3 ? Q(p[2]) : Q(0)}; }

/// The double nearest to sqrt(r), r >= 0, for any r (no overflow or underflow on the way:
/// the exponent is taken out before the square root).
double sqrt_of(const Q& r);

}  // namespace certimesh::certificate::detail
