// Exact determinants of raw (untranslated) coordinates in expansion arithmetic: the
// building blocks of the exact stages (private to the kernel).
//
// Rows are points, columns are coordinates, possibly the lifted |p|^2, and a column of
// ones. Subtracting one row from the others shows these equal the translated determinants
// of the public contracts (orient2d.h, ..., insphere.h). Raw coordinates keep every
// product a product of input doubles, which keeps expansions short; the translated form
// is used only when every difference is exact (expansion_safe decides the range).
#pragma once

#include "certimesh/predicates/detail/expansion.h"

namespace certimesh::predicates::detail {

/// ui*vj - uj*vi, as four non-overlapping components (zeros kept: the later sums drop
/// them). Branch-free: Shewchuk's Two_Two_Diff on the two exact products.
inline Expansion<4> minor2(double ui, double vi, double uj, double vj) noexcept {
  double p1, p0, q1, q0;
  two_product(ui, vj, p1, p0);
  two_product(uj, vi, q1, q0);
  // (p1 + p0) - q0 = j + x0, then (j + x1') - q1.
  double i, j, k, x0, x1, x2, x3;
  two_diff(p0, q0, i, x0);
  two_sum(p1, i, j, k);
  two_diff(k, q1, i, x1);
  two_sum(j, i, x3, x2);
  Expansion<4> e;
  e.c = {x0, x1, x2, x3};
  e.n = 4;
  return e;
}

/// det[ui vi 1; uj vj 1; uk vk 1], expanded along the column of ones.
inline Expansion<12> minor3_with_ones(double ui, double vi, double uj, double vj, double uk,
                                      double vk) noexcept {
  return (minor2(uj, vj, uk, vk) - minor2(ui, vi, uk, vk)) + minor2(ui, vi, uj, vj);
}

/// |p|^2 for a 2D point.
inline Expansion<4> lift2(double x, double y) noexcept {
  return exact_product(x, x) + exact_product(y, y);
}

/// |p|^2 for a 3D point.
inline Expansion<6> lift3(double x, double y, double z) noexcept {
  return (exact_product(x, x) + exact_product(y, y)) + exact_product(z, z);
}

/// The sign of the exact value e when |e| > bound, zero otherwise (compared exactly).
template <std::size_t N>
Sign sign_beyond(const Expansion<N>& e, double bound) noexcept {
  const Sign s = e.sign();
  if (s == Sign::positive) return (e - expansion_of(bound)).sign() == Sign::positive ? s : Sign::zero;
  if (s == Sign::negative) return (e + expansion_of(bound)).sign() == Sign::negative ? s : Sign::zero;
  return Sign::zero;
}

struct Raw3 {
  double x, y, z;
};

/// det[x y z 1] of four points, expanded along the z column.
inline Expansion<96> det4_xyz1(const Raw3& a, const Raw3& b, const Raw3& c, const Raw3& d) noexcept {
  const auto m_bcd = minor3_with_ones(b.x, b.y, c.x, c.y, d.x, d.y);
  const auto m_acd = minor3_with_ones(a.x, a.y, c.x, c.y, d.x, d.y);
  const auto m_abd = minor3_with_ones(a.x, a.y, b.x, b.y, d.x, d.y);
  const auto m_abc = minor3_with_ones(a.x, a.y, b.x, b.y, c.x, c.y);
  return (scale(m_bcd, a.z) - scale(m_acd, b.z)) + (scale(m_abd, c.z) - scale(m_abc, d.z));
}

}  // namespace certimesh::predicates::detail
