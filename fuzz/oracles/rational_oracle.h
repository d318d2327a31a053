// The independent exact oracle of the test suite: GMP rationals, a different formula
// (translated matrix, Gaussian elimination) and no code shared with the kernel.
//
// Slow (microseconds per call) and obviously right: every double converts to mpq_class
// exactly, and rational elimination has no rounding.
#pragma once

#include <gmpxx.h>

#include <array>
#include <utility>
#include <vector>

namespace certimesh::testing {

/// Sign of det(m) for a square rational matrix, by Gaussian elimination with pivoting.
inline int rational_determinant_sign(std::vector<std::vector<mpq_class>> m) {
  const std::size_t n = m.size();
  int sign = 1;
  for (std::size_t col = 0; col < n; ++col) {
    std::size_t pivot = col;
    while (pivot < n && m[pivot][col] == 0) ++pivot;
    if (pivot == n) return 0;
    if (pivot != col) {
      std::swap(m[pivot], m[col]);
      sign = -sign;
    }
    for (std::size_t r = col + 1; r < n; ++r) {
      if (m[r][col] == 0) continue;
      const mpq_class f = m[r][col] / m[col][col];
      for (std::size_t c = col; c < n; ++c) m[r][c] -= f * m[col][c];
    }
    if (m[col][col] < 0) sign = -sign;
  }
  return sign;
}

/// Sign of det[p_i - p_last (, |p_i - p_last|^2)] for i < last: the translated form that
/// defines orient2d/orient3d (not lifted) and incircle/insphere (lifted).
template <std::size_t D, std::size_t N>
int oracle_sign(const std::array<std::array<double, D>, N>& p, bool lifted) {
  std::vector<std::vector<mpq_class>> m;
  for (std::size_t i = 0; i + 1 < N; ++i) {
    std::vector<mpq_class> row;
    mpq_class lift = 0;
    for (std::size_t k = 0; k < D; ++k) {
      mpq_class d = mpq_class(p[i][k]) - mpq_class(p[N - 1][k]);
      lift += d * d;
      row.push_back(d);
    }
    if (lifted) row.push_back(lift);
    m.push_back(std::move(row));
  }
  return rational_determinant_sign(std::move(m));
}

inline int oracle_orient2d(double ax, double ay, double bx, double by, double cx, double cy) {
  return oracle_sign<2, 3>({{{ax, ay}, {bx, by}, {cx, cy}}}, false);
}

}  // namespace certimesh::testing
