// The elements in ascending quality with access to the k-th worst (digest D §3.1: the
// monograph's block-structured dynamic list). An ordered set of (quality, element id) pairs:
// O(log N) insert and erase, ties broken by id so the order is deterministic; the k-th worst
// costs O(k), and Algorithm 35 keeps k below its basket size N2.
#pragma once

#include <cstddef>
#include <set>
#include <utility>
#include <vector>

#include "certimesh/topology/index.h"

namespace certimesh::generators::improvement {

class QualityOrder {
 public:
  void insert(topology::ElementId e, double quality);
  void erase(topology::ElementId e);
  /// The k-th worst element, k >= 1; k <= size().
  topology::ElementId kth_worst(std::size_t k) const;
  double quality(topology::ElementId e) const { return quality_[e.value]; }
  double worst() const { return order_.begin()->first; }
  /// Summed in ascending order: the same value for the same set, whatever the history.
  double mean() const;
  std::size_t size() const { return order_.size(); }

 private:
  std::set<std::pair<double, std::uint32_t>> order_;
  std::vector<double> quality_;  // by element slot
};

}  // namespace certimesh::generators::improvement
