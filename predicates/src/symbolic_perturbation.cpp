// The perturbation scheme is documented in symbolic_perturbation.h. This is its literal,
// generic evaluation; orient3d and insphere use it, and it is the oracle of the 2D fast path
// (sos_2d.cpp, tests/predicates/sos_2d_test.cpp).
#include "certimesh/predicates/symbolic_perturbation.h"

#include <algorithm>
#include <array>
#include <bit>
#include <numeric>
#include <vector>

#include "integer_matrix.h"

namespace certimesh::predicates::detail {

namespace {

struct Symbol {
  int row;
  int column;
};

// Ranks the points by lexicographic order of their coordinates.
std::vector<int> lexicographic_ranks(std::span<const double> coordinates, int dim) {
  const int n = static_cast<int>(coordinates.size()) / dim;
  std::vector<int> order(static_cast<std::size_t>(n));
  std::iota(order.begin(), order.end(), 0);
  auto point = [&](int i) { return coordinates.subspan(static_cast<std::size_t>(i * dim),
                                                       static_cast<std::size_t>(dim)); };
  std::sort(order.begin(), order.end(), [&](int i, int j) {
    const auto p = point(i), q = point(j);
    return std::lexicographical_compare(p.begin(), p.end(), q.begin(), q.end());
  });
  std::vector<int> rank(static_cast<std::size_t>(n));
  for (int r = 0; r < n; ++r) rank[static_cast<std::size_t>(order[static_cast<std::size_t>(r)])] = r;
  return rank;
}

// The perturbed entries, most significant (largest infinitesimal) first.
std::vector<Symbol> symbols_by_significance(const std::vector<int>& rank, int dim, bool lifted) {
  const int n = static_cast<int>(rank.size());
  std::vector<int> row_of_rank(static_cast<std::size_t>(n));
  for (int r = 0; r < n; ++r) row_of_rank[static_cast<std::size_t>(rank[static_cast<std::size_t>(r)])] = r;
  std::vector<Symbol> symbols;
  if (lifted)
    for (int k = 0; k < n; ++k) symbols.push_back({row_of_rank[static_cast<std::size_t>(k)], dim});
  for (int k = 0; k < n; ++k)
    for (int c = 0; c < dim; ++c) symbols.push_back({row_of_rank[static_cast<std::size_t>(k)], c});
  return symbols;
}

// Sign of the coefficient of the monomial perturbing the entries `chosen`: the signed
// complementary minor (-1)^(sum rows + sum columns) * sgn(matching) * det(rest).
Sign coefficient_sign(const IntegerMatrix& m, const std::vector<Symbol>& chosen) {
  const int n = m.size();
  unsigned rows = (1u << n) - 1, cols = (1u << n) - 1;
  int parity = 0;
  std::vector<Symbol> by_row = chosen;
  std::sort(by_row.begin(), by_row.end(), [](Symbol a, Symbol b) { return a.row < b.row; });
  for (std::size_t i = 0; i < by_row.size(); ++i) {
    rows &= ~(1u << by_row[i].row);
    cols &= ~(1u << by_row[i].column);
    parity += by_row[i].row + by_row[i].column;
    for (std::size_t j = 0; j < i; ++j)  // inversions of the matching
      if (by_row[j].column > by_row[i].column) ++parity;
  }
  const Sign minor = m.minor_sign(rows, cols);
  return (parity & 1) ? -minor : minor;
}

// Visits the partial matchings among symbols [0, limit) compatible with the used rows and
// columns, in increasing order of the sum of 2^index -- that is, from the largest
// perturbation monomial to the smallest -- and stops at the first non-zero coefficient.
class MonomialSearch {
 public:
  MonomialSearch(const IntegerMatrix& m, std::vector<Symbol> symbols)
      : matrix_(m), symbols_(std::move(symbols)) {}

  Sign run() {
    for (int h = 0; h < static_cast<int>(symbols_.size()); ++h) {
      const Sign s = with_highest(h, 0u, 0u);
      if (s != Sign::zero) return s;
    }
    return Sign::zero;  // unreachable for distinct points: the last matching has +-1
  }

 private:
  // Matchings whose most significant-index (largest index) symbol is h.
  Sign with_highest(int h, unsigned used_rows, unsigned used_cols) {
    const Symbol s = symbols_[static_cast<std::size_t>(h)];
    if ((used_rows >> s.row) & 1u || (used_cols >> s.column) & 1u) return Sign::zero;
    chosen_.push_back(s);
    const unsigned rows = used_rows | (1u << s.row), cols = used_cols | (1u << s.column);
    // First the matching {h} plus nothing below, then plus matchings below h, in order.
    Sign result = coefficient_sign(matrix_, chosen_);
    for (int lower = 0; result == Sign::zero && lower < h; ++lower)
      result = with_highest(lower, rows, cols);
    chosen_.pop_back();
    return result;
  }

  const IntegerMatrix& matrix_;
  std::vector<Symbol> symbols_;
  std::vector<Symbol> chosen_;
};

}  // namespace

Sign perturbed_sign(std::span<const double> coordinates, int dim, bool lifted) {
  const IntegerMatrix matrix(coordinates, dim, lifted);
  const std::vector<int> rank = lexicographic_ranks(coordinates, dim);
  return MonomialSearch(matrix, symbols_by_significance(rank, dim, lifted)).run();
}

}  // namespace certimesh::predicates::detail
