// Boxes and the broad-phase grid (close_pairs.h).
#include <algorithm>
#include <cmath>

#include "close_pairs.h"

namespace certimesh::certificate::detail {

Box facet_box(const MeshView& m, const Index* f, int count) {
  Box b;
  for (int k = 0; k < m.dim; ++k) b.lo[k] = b.hi[k] = m.coord(f[0], k);
  for (int i = 1; i < count; ++i)
    for (int k = 0; k < m.dim; ++k) {
      b.lo[k] = std::min(b.lo[k], m.coord(f[i], k));
      b.hi[k] = std::max(b.hi[k], m.coord(f[i], k));
    }
  return b;
}

bool boxes_overlap(const Box& a, const Box& b, int dim) {
  for (int k = 0; k < dim; ++k)
    if (a.hi[k] < b.lo[k] || b.hi[k] < a.lo[k]) return false;
  return true;
}

void BoxGrid::range(const Box& b, int first[3], int last[3]) const {
  for (int k = 0; k < 3; ++k) first[k] = last[k] = 0;
  for (int k = 0; k < dim_; ++k) first[k] = cell(b.lo[k], k), last[k] = cell(b.hi[k], k);
}

// About one cell per box, fewer when long boxes would fill too many cells.
BoxGrid::BoxGrid(const std::vector<Box>& boxes, int dim) : boxes_(boxes), dim_(dim) {
  if (boxes.empty()) return;
  double hi[3] = {0, 0, 0};
  for (int k = 0; k < dim; ++k) {
    lo_[k] = boxes[0].lo[k], hi[k] = boxes[0].hi[k];
    for (const Box& b : boxes) lo_[k] = std::min(lo_[k], b.lo[k]), hi[k] = std::max(hi[k], b.hi[k]);
  }
  const double n = static_cast<double>(boxes.size());
  cells_ = std::clamp(static_cast<int>(std::pow(n, 1.0 / dim)), 1, dim == 2 ? 4096 : 256);
  for (;; cells_ = std::max(1, cells_ / 2)) {
    for (int k = 0; k < dim; ++k) {
      const double extent = hi[k] - lo_[k];
      scale_[k] = extent > 0 && std::isfinite(extent) ? cells_ / extent : 0.0;
    }
    entries_.clear();
    bool fits = true;
    for (std::size_t i = 0; i < boxes.size() && fits; ++i) {
      int f[3], l[3], c[3];
      range(boxes[i], f, l);
      const auto count = static_cast<std::size_t>(l[0] - f[0] + 1) * static_cast<std::size_t>(l[1] - f[1] + 1) *
                         static_cast<std::size_t>(l[2] - f[2] + 1);
      fits = cells_ == 1 || entries_.size() + count <= 16 * boxes.size() + 1024;
      for (c[2] = f[2]; fits && c[2] <= l[2]; ++c[2])
        for (c[1] = f[1]; c[1] <= l[1]; ++c[1])
          for (c[0] = f[0]; c[0] <= l[0]; ++c[0]) entries_.push_back({index(c), i});
    }
    if (fits) break;
  }
  std::sort(entries_.begin(), entries_.end());
  first_.resize(3 * boxes.size());
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    int l[3];
    range(boxes[i], first_.data() + 3 * i, l);
  }
}

}  // namespace certimesh::certificate::detail
