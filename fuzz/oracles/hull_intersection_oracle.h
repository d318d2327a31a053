// An exact oracle for the intersection tests, independent of the kernel: two elements (the
// convex hulls of their points) intersect beyond their shared vertices S (points with the
// same coordinates, bit for bit, in both) when some x = sum l_i a_i = sum m_j b_j, with
// l, m >= 0 and sum l = sum m = 1, lies outside conv(S). When A's points are affinely
// independent, conv(S) is the face of A where the weights of A's other points vanish, so
// the question is the exact linear program max sum_{i not in S} l_i > 0 (rational simplex,
// Bland's rule). A port of tests/packaging/cli_batch_test.py's oracle to GMP rationals.
//
// Slow (tens of microseconds) and obviously right: no rounding anywhere.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <optional>
#include <vector>

namespace certimesh::testing {

namespace hull_detail {

using Matrix = std::vector<std::vector<mpq_class>>;

/// max c.x subject to A x = b, x >= 0; nullopt when infeasible (the problems here are
/// bounded: every variable is a convex weight).
inline std::optional<mpq_class> simplex_max(const Matrix& A, const std::vector<mpq_class>& b,
                                            const std::vector<mpq_class>& c) {
  const std::size_t m = A.size(), n = A[0].size();
  Matrix T(m, std::vector<mpq_class>(n + m + 1));
  std::vector<std::size_t> basis(m);
  for (std::size_t i = 0; i < m; ++i) {
    const bool flip = b[i] < 0;
    for (std::size_t j = 0; j < n; ++j) T[i][j] = flip ? mpq_class(-A[i][j]) : A[i][j];
    T[i][n + i] = 1;
    T[i][n + m] = flip ? mpq_class(-b[i]) : b[i];
    basis[i] = n + i;
  }
  const auto in_basis = [&](std::size_t j) {
    for (std::size_t v : basis)
      if (v == j) return true;
    return false;
  };
  const auto pivot_on = [&](std::size_t r, std::size_t j) {
    const mpq_class p = T[r][j];
    for (auto& v : T[r]) v /= p;
    for (std::size_t i = 0; i < m; ++i)
      if (i != r && T[i][j] != 0) {
        const mpq_class f = T[i][j];
        for (std::size_t k = 0; k < T[i].size(); ++k) T[i][k] -= f * T[r][k];
      }
    basis[r] = j;
  };
  const auto run = [&](const std::vector<mpq_class>& cost, std::size_t allowed) {
    for (;;) {
      std::size_t entering = allowed;
      for (std::size_t j = 0; j < allowed && entering == allowed; ++j) {
        if (in_basis(j)) continue;
        mpq_class reduced = cost[j];
        for (std::size_t i = 0; i < m; ++i) reduced -= cost[basis[i]] * T[i][j];
        if (reduced > 0) entering = j;
      }
      if (entering == allowed) return;
      std::optional<std::size_t> best;
      mpq_class best_ratio;
      for (std::size_t i = 0; i < m; ++i)
        if (T[i][entering] > 0) {
          const mpq_class ratio = T[i][n + m] / T[i][entering];
          if (!best || ratio < best_ratio || (ratio == best_ratio && basis[i] < basis[*best])) {
            best = i;
            best_ratio = ratio;
          }
        }
      if (!best) return;  // unbounded: cannot happen for convex weights
      pivot_on(*best, entering);
    }
  };
  // Phase 1: maximise -(sum of artificials).
  std::vector<mpq_class> phase1(n + m, 0);
  for (std::size_t i = 0; i < m; ++i) phase1[n + i] = -1;
  run(phase1, n + m);
  for (std::size_t i = 0; i < m; ++i)
    if (basis[i] >= n && T[i][n + m] != 0) return std::nullopt;
  // Drive zero artificials out of the basis where possible; phase 2 on the originals.
  for (std::size_t i = 0; i < m; ++i)
    if (basis[i] >= n)
      for (std::size_t j = 0; j < n; ++j)
        if (!in_basis(j) && T[i][j] != 0) {
          pivot_on(i, j);
          break;
        }
  std::vector<mpq_class> cost(n + m, 0);
  for (std::size_t j = 0; j < n; ++j) cost[j] = c[j];
  run(cost, n);
  mpq_class value = 0;
  for (std::size_t i = 0; i < m; ++i) value += cost[basis[i]] * T[i][n + m];
  return value;
}

template <std::size_t D>
bool affinely_independent(const std::vector<std::array<mpq_class, D>>& p) {
  Matrix rows;
  for (std::size_t i = 1; i < p.size(); ++i) {
    std::vector<mpq_class> r(D);
    for (std::size_t k = 0; k < D; ++k) r[k] = p[i][k] - p[0][k];
    rows.push_back(std::move(r));
  }
  std::size_t rank = 0;
  for (std::size_t col = 0; col < D && rank < rows.size(); ++col) {
    std::size_t piv = rank;
    while (piv < rows.size() && rows[piv][col] == 0) ++piv;
    if (piv == rows.size()) continue;
    std::swap(rows[rank], rows[piv]);
    for (std::size_t i = 0; i < rows.size(); ++i)
      if (i != rank && rows[i][col] != 0) {
        const mpq_class f = rows[i][col] / rows[rank][col];
        for (std::size_t k = 0; k < D; ++k) rows[i][k] -= f * rows[rank][k];
      }
    ++rank;
  }
  return rank == rows.size();
}

}  // namespace hull_detail

/// Do conv(a) and conv(b) share a point outside conv(shared vertices)? nullopt when both
/// are affinely dependent and share a vertex (the question is then not a face's).
template <std::size_t D, std::size_t NA, std::size_t NB>
std::optional<bool> hulls_intersect_beyond_shared(const std::array<std::array<double, D>, NA>& a,
                                                  const std::array<std::array<double, D>, NB>& b) {
  namespace hd = hull_detail;
  using Q = std::array<mpq_class, D>;
  std::vector<Q> A, B;
  for (const auto& p : a) {
    Q q;
    for (std::size_t k = 0; k < D; ++k) q[k] = p[k];
    A.push_back(q);
  }
  for (const auto& p : b) {
    Q q;
    for (std::size_t k = 0; k < D; ++k) q[k] = p[k];
    B.push_back(q);
  }
  const auto same = [](const std::array<double, D>& x, const std::array<double, D>& y) {
    for (std::size_t k = 0; k < D; ++k)
      if (x[k] != y[k] || std::signbit(x[k]) != std::signbit(y[k])) return false;
    return true;
  };
  std::vector<bool> a_shared(NA, false), b_shared(NB, false);
  bool any_shared = false;
  for (std::size_t i = 0; i < NA; ++i)
    for (std::size_t j = 0; j < NB; ++j)
      if (same(a[i], b[j])) a_shared[i] = b_shared[j] = any_shared = true;
  const std::vector<Q>* first = &A;
  const std::vector<Q>* second = &B;
  const std::vector<bool>* first_shared = &a_shared;
  if (!hd::affinely_independent<D>(A)) {
    if (hd::affinely_independent<D>(B)) {
      first = &B;
      second = &A;
      first_shared = &b_shared;
    } else if (any_shared) {
      return std::nullopt;
    }
  }
  const std::size_t na = first->size(), nb = second->size();
  hd::Matrix rows;
  std::vector<mpq_class> rhs;
  std::vector<mpq_class> r0(na + nb, 0), r1(na + nb, 0);
  for (std::size_t i = 0; i < na; ++i) r0[i] = 1;
  for (std::size_t j = 0; j < nb; ++j) r1[na + j] = 1;
  rows.push_back(r0);
  rows.push_back(r1);
  rhs = {1, 1};
  for (std::size_t k = 0; k < D; ++k) {
    std::vector<mpq_class> r(na + nb);
    for (std::size_t i = 0; i < na; ++i) r[i] = (*first)[i][k];
    for (std::size_t j = 0; j < nb; ++j) r[na + j] = -(*second)[j][k];
    rows.push_back(std::move(r));
    rhs.push_back(0);
  }
  std::vector<mpq_class> objective(na + nb, 0);
  if (any_shared)
    for (std::size_t i = 0; i < na; ++i) objective[i] = (*first_shared)[i] ? 0 : 1;
  const auto best = hd::simplex_max(rows, rhs, objective);
  if (!any_shared) return best.has_value();
  return best.has_value() && *best > 0;
}

}  // namespace certimesh::testing
