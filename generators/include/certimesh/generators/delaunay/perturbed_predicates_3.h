// The signs the 3D Delaunay tetrahedralization decides with, as ints: the exact orientation
// and the perturbed (SoS) in-sphere sign. The filter is inline here, on the hot path; when it
// is uncertain the exact sign comes from 128-bit integers for small-integer points or else
// from the kernel's exact stage, and for an exact in-sphere zero the lifted terms of
// insphere_sos's perturbation are evaluated here by exact orientations
// (insphere_lifted_perturbation). tests/generators/dt_delaunay_3_test.cpp
// (LiftedPerturbationIsInsphereSos) checks the whole against insphere_sos on random
// quintuples of a 3 x 3 x 3 grid, of an integer sphere and of integer clusters near 2^21.
//
// Why orient3d is exact and not perturbed: the tetrahedralization never holds a flat
// tetrahedron, so every in-sphere test is against four points off one plane, and then
// insphere_sos's perturbation stops at its first, lifted terms (symbolic_perturbation.h:
// the coefficient of a point's lifted entry is the orientation of the other four, and the
// tetrahedron's own is not zero). That is the perturbation of the lifting alone, a regular
// triangulation with infinitesimal generic weights: unique, with no flat tetrahedron. A
// point exactly in the plane of a hull face is decided by the same in-sphere sign
// (delaunay_3.cpp, conflicts()). orient3d_sos would instead tilt coplanar hull points into
// flat tetrahedra, as the 2D triangulation's flat hull triangles.
#pragma once

#include <cstdint>
#include <utility>

#include "certimesh/predicates/insphere.h"
#include "certimesh/predicates/orient3d.h"

namespace certimesh::generators::detail {

using predicates::Point3;

/// The exact orientation (Shewchuk's sign of det[a - d; b - d; c - d]).
inline int orient3d_exact(const Point3& a, const Point3& b, const Point3& c, const Point3& d) {
  const predicates::FilteredSign f = predicates::orient3d_filtered(a, b, c, d);
  if (predicates::is_certain(f)) [[likely]]
    return predicates::to_int(f);
  return predicates::to_int(predicates::orient3d(a, b, c, d));
}

/// insphere_sos's answer when the exact in-sphere sign is zero, for five distinct points with
/// (a, b, c, d) not coplanar, without its generic GMP search: the perturbed determinant is
/// det[p, |p|^2 + e(p), 1] (rows a..e, symbolic_perturbation.h), whose first non-zero
/// term, the rows taken by lexicographic rank, is e(p_r) times the cofactor (-1)^(r+3) *
/// orient3d(the other four rows, in order); row e's is -orient3d(a, b, c, d), not zero, so
/// the search ends within five exact orientations. 0 when every cofactor is zero (then
/// (a, b, c, d) was coplanar and the caller asks insphere_sos).
inline int insphere_lifted_perturbation(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e) {
  const Point3* p[5] = {&a, &b, &c, &d, &e};
  int order[5] = {0, 1, 2, 3, 4};
  auto less = [&](int i, int j) {
    const Point3 &u = *p[i], &v = *p[j];
    return u.x != v.x ? u.x < v.x : (u.y != v.y ? u.y < v.y : u.z < v.z);
  };
  for (int i = 1; i < 5; ++i)  // insertion sort of five
    for (int j = i; j > 0 && less(order[j], order[j - 1]); --j) std::swap(order[j], order[j - 1]);
  for (int r : order) {
    const Point3* q[4];
    for (int i = 0, k = 0; i < 5; ++i)
      if (i != r) q[k++] = p[i];
    const int o = orient3d_exact(*q[0], *q[1], *q[2], *q[3]);
    if (o != 0) return (r % 2 == 1) ? o : -o;
  }
  return 0;
}

__extension__ typedef __int128 Int128;

/// The exact in-sphere sign for points whose coordinates are all integers below 2^22 in
/// magnitude (integer grids, integer points on a sphere: where exact zeros are common and the
/// expansion arithmetic of the exact stage was half the time), in 128-bit integers: the
/// differences are below 2^23, each 3 x 3 minor below 6 * 2^69, each lifted entry below
/// 3 * 2^46, the determinant below 72 * 2^115 < 2^127. `false` when the points do not qualify.
inline bool insphere_small_integers(const Point3& a, const Point3& b, const Point3& c, const Point3& d, const Point3& e,
                                    int* sign) {
  const Point3* p[5] = {&a, &b, &c, &d, &e};
  for (const Point3* q : p)
    for (double v : {q->x, q->y, q->z})
      if (!(v > -0x1p22 && v < 0x1p22) || v != static_cast<double>(static_cast<std::int32_t>(v))) return false;
  std::int64_t m[4][4];
  for (int i = 0; i < 4; ++i) {
    const std::int64_t x = static_cast<std::int64_t>(p[i]->x - e.x), y = static_cast<std::int64_t>(p[i]->y - e.y),
                       z = static_cast<std::int64_t>(p[i]->z - e.z);
    m[i][0] = x, m[i][1] = y, m[i][2] = z, m[i][3] = x * x + y * y + z * z;
  }
  auto minor3 = [&](int skip) {  // det of rows != skip, columns 0..2
    int r[3], k = 0;
    for (int i = 0; i < 4; ++i)
      if (i != skip) r[k++] = i;
    const std::int64_t* u = m[r[0]];
    const std::int64_t* v = m[r[1]];
    const std::int64_t* w = m[r[2]];
    return Int128(u[0]) * (Int128(v[1]) * w[2] - Int128(v[2]) * w[1]) -
           Int128(u[1]) * (Int128(v[0]) * w[2] - Int128(v[2]) * w[0]) +
           Int128(u[2]) * (Int128(v[0]) * w[1] - Int128(v[1]) * w[0]);
  };
  Int128 det = 0;  // along the lifted column: sum of (-1)^(i+3) m[i][3] * minor3(i)
  for (int i = 0; i < 4; ++i) det += (i % 2 == 1 ? Int128(m[i][3]) : -Int128(m[i][3])) * minor3(i);
  *sign = det > 0 ? 1 : (det < 0 ? -1 : 0);
  return true;
}

/// The exact and then perturbed stages of insphere_perturbed, out of line (rare: the filter
/// decides almost every test; kept apart so that the filter inlines into its caller).
[[gnu::noinline, gnu::cold]] inline int insphere_perturbed_exact(const Point3& a, const Point3& b, const Point3& c,
                                                                 const Point3& d, const Point3& e) {
  int s;
  if (!insphere_small_integers(a, b, c, d, e, &s)) s = predicates::to_int(predicates::detail::insphere_exact_stage(a, b, c, d, e));
  if (s != 0) return s;
  if (e == a || e == b || e == c || e == d || a == b || a == c || a == d || b == c || b == d || c == d) return 0;
  const int lifted = insphere_lifted_perturbation(a, b, c, d, e);
  return lifted != 0 ? lifted : predicates::to_int(predicates::insphere_sos(a, b, c, d, e));
}

/// The perturbed in-sphere sign of e against (a, b, c, d): 0 only when e equals one of them.
[[gnu::always_inline]] inline int insphere_perturbed(const Point3& a, const Point3& b, const Point3& c, const Point3& d,
                                                     const Point3& e) {
  const predicates::FilteredSign f = predicates::insphere_filtered(a, b, c, d, e);
  if (predicates::is_certain(f)) [[likely]]
    return predicates::to_int(f);
  return insphere_perturbed_exact(a, b, c, d, e);
}

}  // namespace certimesh::generators::detail
