#include "front_grid_2.h"

#include <algorithm>
#include <cmath>

namespace certimesh::generators::advancing_front_detail {
namespace {

// An edge whose box covers more cells than this is cheaper to return on every query than to
// file cell by cell (front edges are about one cell long; only input edges can be long).
constexpr std::uint32_t long_edge_cells = 16;

void erase_value(std::vector<std::uint32_t>& list, std::uint32_t value) {
  const auto it = std::find(list.begin(), list.end(), value);
  if (it == list.end()) return;
  *it = list.back();
  list.pop_back();
}

std::uint32_t clamp_index(double t, std::uint32_t n) {
  if (!(t > 0.0)) return 0;  // also NaN
  if (t >= static_cast<double>(n - 1)) return n - 1;
  return static_cast<std::uint32_t>(t);
}

}  // namespace

FrontGrid2::FrontGrid2(const Box2& bounds, double cell, std::size_t max_cells) {
  const double width = std::max(bounds.xhi - bounds.xlo, 0.0);
  const double height = std::max(bounds.yhi - bounds.ylo, 0.0);
  const double biggest = std::max(width, height);
  if (!(cell > 0.0) || !std::isfinite(cell)) cell = biggest > 0.0 ? biggest : 1.0;
  // Enough cells per side that max_cells is respected (square-root rule, then exact check).
  const double fair = std::sqrt(width * height / static_cast<double>(std::max<std::size_t>(max_cells, 1)));
  cell = std::max({cell, fair, biggest / 65535.0});
  for (;;) {
    const double nx = std::floor(width / cell) + 1.0, ny = std::floor(height / cell) + 1.0;
    if (nx * ny <= static_cast<double>(std::max<std::size_t>(max_cells, 1))) {
      nx_ = static_cast<std::uint32_t>(nx);
      ny_ = static_cast<std::uint32_t>(ny);
      break;
    }
    cell *= 1.25;
  }
  x0_ = bounds.xlo;
  y0_ = bounds.ylo;
  cell_ = cell;
  inverse_cell_ = 1.0 / cell;
  cells_.resize(std::size_t{nx_} * ny_);
}

std::uint32_t FrontGrid2::column(double x) const {
  return clamp_index(std::floor((x - x0_) * inverse_cell_), nx_);
}
std::uint32_t FrontGrid2::row(double y) const {
  return clamp_index(std::floor((y - y0_) * inverse_cell_), ny_);
}

FrontGrid2::Range FrontGrid2::range(double xlo, double ylo, double xhi, double yhi) const {
  return Range{column(xlo), row(ylo), column(xhi), row(yhi)};
}

FrontGrid2::Range FrontGrid2::edge_range(const Point2& a, const Point2& b) const {
  return range(std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y));
}

bool FrontGrid2::is_long(const Range& r) {
  return std::uint64_t{r.ihi - r.ilo + 1} * (r.jhi - r.jlo + 1) > long_edge_cells;
}

void FrontGrid2::insert(std::uint32_t edge, const Point2& a, const Point2& b) {
  const Range r = edge_range(a, b);
  if (is_long(r)) {
    long_edges_.push_back(edge);
    return;
  }
  for (std::uint32_t j = r.jlo; j <= r.jhi; ++j)
    for (std::uint32_t i = r.ilo; i <= r.ihi; ++i) cells_[std::size_t{j} * nx_ + i].push_back(edge);
}

void FrontGrid2::erase(std::uint32_t edge, const Point2& a, const Point2& b) {
  const Range r = edge_range(a, b);
  if (is_long(r)) {
    erase_value(long_edges_, edge);
    return;
  }
  for (std::uint32_t j = r.jlo; j <= r.jhi; ++j)
    for (std::uint32_t i = r.ilo; i <= r.ihi; ++i) erase_value(cells_[std::size_t{j} * nx_ + i], edge);
}

}  // namespace certimesh::generators::advancing_front_detail
