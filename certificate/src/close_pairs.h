// Internal: the broad phase of the intersection checks. A deterministic uniform grid over
// the boxes; each pair of overlapping boxes is visited exactly once, in the first grid cell
// both cover, so no set of visited pairs is needed. The cell of a coordinate is a monotone
// function of it, so two boxes that overlap always share a cell: nothing is missed.
#pragma once

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "mesh_view.h"

namespace certimesh::certificate::detail {

class BoxGrid {
 public:
  BoxGrid(const std::vector<Box>& boxes, int dim);
  /// Calls visit(i, j), i < j, for every pair of overlapping boxes until it returns true.
  template <class Visit>
  bool any_pair(Visit visit) const;
  /// Calls visit(i) once for every box i overlapping `query` (a box not in the grid).
  template <class Visit>
  void each_overlapping(const Box& query, Visit visit) const;

 private:
  int cell(double x, int axis) const {
    const double t = std::floor((x - lo_[axis]) * scale_[axis]);
    if (!(t > 0)) return 0;  // also NaN, from an infinite extent
    return t >= cells_ - 1 ? cells_ - 1 : static_cast<int>(t);
  }
  void range(const Box& b, int first[3], int last[3]) const;
  std::size_t index(const int c[3]) const { return (std::size_t(c[2]) * std::size_t(cells_) + std::size_t(c[1])) * std::size_t(cells_) + std::size_t(c[0]); }
  const std::vector<Box>& boxes_;
  int dim_;
  int cells_ = 1;
  double lo_[3] = {0, 0, 0}, scale_[3] = {0, 0, 0};
  std::vector<std::pair<std::size_t, std::size_t>> entries_;  // (cell, box), sorted
  std::vector<int> first_;  // per box: the first cell of its range, 3 coordinates (0 beyond dim)
};

template <class Visit>
bool BoxGrid::any_pair(Visit visit) const {
  // A cell's boxes copied side by side with their first cells (the lower corner of their range):
  // the pair loop, quadratic in a crowded cell, then reads contiguous memory and no range.
  struct Local {
    Box box;
    int first[3];
    std::size_t id;
  };
  std::vector<Local> here;
  for (std::size_t first = 0, end = 0; first < entries_.size(); first = end) {
    const std::size_t c = entries_[first].first;
    while (end < entries_.size() && entries_[end].first == c) ++end;
    here.clear();
    for (std::size_t a = first; a < end; ++a) {
      const std::size_t i = entries_[a].second;
      here.push_back({boxes_[i], {first_[3 * i], first_[3 * i + 1], first_[3 * i + 2]}, i});
    }
    for (std::size_t a = 0; a < here.size(); ++a)
      for (std::size_t b = a + 1; b < here.size(); ++b) {
        const Local &x = here[a], &y = here[b];
        if (!boxes_overlap(x.box, y.box, dim_)) continue;
        const int common[3] = {std::max(x.first[0], y.first[0]), std::max(x.first[1], y.first[1]), std::max(x.first[2], y.first[2])};
        if (index(common) == c && visit(x.id, y.id)) return true;
      }
  }
  return false;
}

template <class Visit>
void BoxGrid::each_overlapping(const Box& query, Visit visit) const {
  int fq[3], lq[3], c[3];
  range(query, fq, lq);
  for (c[2] = fq[2]; c[2] <= lq[2]; ++c[2])
    for (c[1] = fq[1]; c[1] <= lq[1]; ++c[1])
      for (c[0] = fq[0]; c[0] <= lq[0]; ++c[0]) {
        const std::size_t here = index(c);
        auto it = std::lower_bound(entries_.begin(), entries_.end(), std::pair<std::size_t, std::size_t>{here, 0});
        for (; it != entries_.end() && it->first == here; ++it) {
          const std::size_t i = it->second;
          if (!boxes_overlap(boxes_[i], query, dim_)) continue;
          int common[3] = {0, 0, 0};
          for (int k = 0; k < dim_; ++k) common[k] = std::max(first_[3 * i + static_cast<std::size_t>(k)], fq[k]);
          if (index(common) == here) visit(i);  // the first cell both cover: once per box
        }
      }
}

}  // namespace certimesh::certificate::detail
