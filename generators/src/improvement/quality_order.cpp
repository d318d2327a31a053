#include "quality_order.h"

#include <iterator>

namespace certimesh::generators::improvement {

void QualityOrder::insert(topology::ElementId e, double quality) {
  if (quality_.size() <= e.value) quality_.resize(e.value + 1, 0.0);
  quality_[e.value] = quality;
  order_.emplace(quality, e.value);
}

void QualityOrder::erase(topology::ElementId e) {
  if (e.value >= quality_.size()) return;  // never inserted
  order_.erase({quality_[e.value], e.value});
}

topology::ElementId QualityOrder::kth_worst(std::size_t k) const {
  return topology::ElementId{std::next(order_.begin(), static_cast<std::ptrdiff_t>(k - 1))->second};
}

double QualityOrder::mean() const {
  if (order_.empty()) return 0.0;
  double sum = 0.0;
  for (const auto& entry : order_) sum += entry.first;
  return sum / static_cast<double>(order_.size());
}

}  // namespace certimesh::generators::improvement
