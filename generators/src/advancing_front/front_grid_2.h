// A uniform grid over the front edges, for the local front F_k^R of Algorithm 10.
//
// Each edge is filed in every cell its bounding box overlaps; an edge whose box covers many
// cells goes to a short "long edges" list that every query returns instead. A query for a
// box returns every edge whose bounding box meets it (a superset of the edges meeting the
// box: digest B §3.2 [DERIVED] (ii)), possibly several times -- the caller deduplicates.
// The cell of a coordinate is floor((x - origin) / cell) clamped to the grid, a monotone
// function of x in floating point, so "boxes overlap" implies "cell ranges overlap" exactly.
#pragma once

#include <cstdint>
#include <vector>

#include "certimesh/predicates/point.h"

namespace certimesh::generators::advancing_front_detail {

using predicates::Point2;

struct Box2 {
  double xlo, ylo, xhi, yhi;
  bool contains(const Point2& p) const {
    return xlo <= p.x && p.x <= xhi && ylo <= p.y && p.y <= yhi;
  }
};

class FrontGrid2 {
 public:
  /// A grid over `bounds` with cells of about `cell` (enlarged so that there are at most
  /// `max_cells` cells).
  FrontGrid2(const Box2& bounds, double cell, std::size_t max_cells);

  void insert(std::uint32_t edge, const Point2& a, const Point2& b);
  void erase(std::uint32_t edge, const Point2& a, const Point2& b);

  /// Calls f(edge) for every filed edge whose bounding box may meet `query`.
  template <class F>
  void for_each_edge_near(const Box2& query, F&& f) const {
    const Range r = range(query.xlo, query.ylo, query.xhi, query.yhi);
    for (std::uint32_t j = r.jlo; j <= r.jhi; ++j)
      for (std::uint32_t i = r.ilo; i <= r.ihi; ++i)
        for (const std::uint32_t e : cells_[std::size_t{j} * nx_ + i]) f(e);
    for (const std::uint32_t e : long_edges_) f(e);
  }

  double cell_size() const { return cell_; }

 private:
  struct Range {
    std::uint32_t ilo, jlo, ihi, jhi;
  };
  std::uint32_t column(double x) const;
  std::uint32_t row(double y) const;
  Range range(double xlo, double ylo, double xhi, double yhi) const;
  Range edge_range(const Point2& a, const Point2& b) const;
  static bool is_long(const Range& r);

  double x0_ = 0, y0_ = 0, cell_ = 1, inverse_cell_ = 1;
  std::uint32_t nx_ = 1, ny_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;
  std::vector<std::uint32_t> long_edges_;
};

}  // namespace certimesh::generators::advancing_front_detail
