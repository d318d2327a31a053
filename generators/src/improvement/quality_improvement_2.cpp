// Algorithm 35 in 2D (quality_improvement_2.h; digest D §3.2).
//
// Rank pointer k and basket counter m as in the monograph: an element on which no operation
// succeeds goes into the basket (k := k + 1); after a success k is kept (the digest's reading
// of the printed listing); when k passes the basket size N2, the element count, or reaches an
// element already at the target, the basket is emptied (k := 1) and m counts one more round;
// more than N3 rounds means stagnation. Every committed operation raised the worst quality of
// what it changed strictly, so the mesh's worst quality never decreases.
#include "certimesh/generators/improvement/quality_improvement_2.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <optional>
#include <stdexcept>
#include <string>

#include "certimesh/topology/element_orientation.h"
#include "certimesh/topology/quality.h"
#include "quality_order.h"

namespace certimesh::generators {

namespace {

using topology::ElementId;
using topology::LocalChange2;
using topology::TriangleMesh2;
using topology::VertexId;

topology::TriangleQualityFunction2 quality_function(const SizePolicy& size) {
  if (size.automatic())
    return [](const topology::Point2d& a, const topology::Point2d& b, const topology::Point2d& c) {
      return topology::triangle_quality(a, b, c);
    };
  return [size](const topology::Point2d& a, const topology::Point2d& b, const topology::Point2d& c) {
    const Point2 centroid{(a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0};
    return topology::size_aware_triangle_quality(a, b, c, size.at(centroid));
  };
}

double element_quality(const TriangleMesh2& mesh, ElementId e, const topology::TriangleQualityFunction2& q) {
  const auto v = mesh.vertices(e);
  return q(mesh.point(v[0]), mesh.point(v[1]), mesh.point(v[2]));
}

void require_counterclockwise(const TriangleMesh2& mesh) {
  for (std::uint32_t slot = 0; slot < mesh.element_slot_count(); ++slot) {
    const ElementId e{slot};
    if (mesh.is_live(e) && topology::element_orientation(mesh, e) != predicates::Sign::positive)
      throw std::invalid_argument("improve_quality_2: element " + std::to_string(slot) +
                                  " is not strictly counterclockwise; the mesh must be valid");
  }
}

struct Attempt {
  std::size_t operation = 0;  // bit index of LocalOperation2
  LocalChange2 change;
};

// The basic operations on element e, in the documented order; the first success.
std::optional<Attempt> try_operations(TriangleMesh2& mesh, ElementId e, std::uint8_t allowed,
                                      const topology::LocalModificationOptions2& lm) {
  const auto vertices = mesh.vertices(e);
  const auto on = [&](LocalOperation2 op) { return (allowed & static_cast<std::uint8_t>(op)) != 0; };
  const auto bit = [](LocalOperation2 op) {
    return static_cast<std::size_t>(std::countr_zero(static_cast<unsigned>(op)));
  };
  std::optional<LocalChange2> change;
  if (on(LocalOperation2::flip))
    for (int i = 0; i < 3 && !change; ++i) change = topology::try_flip(mesh, e, i, lm);
  if (change) return Attempt{bit(LocalOperation2::flip), std::move(*change)};
  if (on(LocalOperation2::node_shift))
    for (std::size_t i = 0; i < 3 && !change; ++i) change = topology::try_node_shift(mesh, vertices[i], lm);
  if (change) return Attempt{bit(LocalOperation2::node_shift), std::move(*change)};
  if (on(LocalOperation2::edge_collapse))
    for (int i = 0; i < 3 && !change; ++i) change = topology::try_edge_collapse(mesh, e, i, lm);
  if (change) return Attempt{bit(LocalOperation2::edge_collapse), std::move(*change)};
  if (on(LocalOperation2::node_deletion))
    for (std::size_t i = 0; i < 3 && !change; ++i) change = topology::try_node_deletion(mesh, vertices[i], lm);
  if (change) return Attempt{bit(LocalOperation2::node_deletion), std::move(*change)};
  if (on(LocalOperation2::insert_on_edge))
    for (int i = 0; i < 3 && !change; ++i) change = topology::try_insert_on_edge(mesh, e, i, lm);
  if (change) return Attempt{bit(LocalOperation2::insert_on_edge), std::move(*change)};
  return std::nullopt;
}

struct Budget {
  std::uint64_t operations;  // N1
  std::size_t basket;        // N2
  std::uint64_t baskets;     // N3
};

Budget budget_of(const ImprovementOptions2& options, std::size_t elements) {
  Budget b{options.max_operations, options.basket_size, options.max_baskets};
  if (b.operations == 0) b.operations = 5 * static_cast<std::uint64_t>(elements);
  if (b.basket == 0) b.basket = std::max<std::size_t>(16, elements * 7 / 100);
  if (b.baskets == 0) b.baskets = elements / b.basket + 1;  // N2 * N3 > N
  return b;
}

}  // namespace

ImprovementStats2 improve_quality_2(TriangleMesh2& mesh, const ImprovementOptions2& options,
                                    const ProgressCallback& progress) {
  require_counterclockwise(mesh);
  const auto quality = quality_function(options.size);
  const topology::LocalModificationOptions2 lm{quality, options.boundary_projection,
                                               options.collapse_reference, options.minimum_shift_gain,
                                               options.coarsen_straight_boundary, options.input_segments};
  improvement::QualityOrder order;
  for (std::uint32_t slot = 0; slot < mesh.element_slot_count(); ++slot)
    if (mesh.is_live(ElementId{slot})) order.insert(ElementId{slot}, element_quality(mesh, ElementId{slot}, quality));

  ImprovementStats2 stats;
  if (order.size() == 0) return stats;
  stats.initial_worst = order.worst();
  stats.initial_mean = order.mean();
  const Budget budget = budget_of(options, order.size());
  const std::uint64_t report_every = std::max<std::uint64_t>(1, budget.operations / 200);
  std::size_t k = 1;
  std::uint64_t round = 1;
  while (stats.iterations < budget.operations) {
    if (k > order.size()) k = 1;  // collapses and deletions shrink the list under the pointer
    const ElementId e = order.kth_worst(k);
    if (order.quality(e) >= options.target_quality) {
      if (k == 1) break;  // the worst element reached Q0
      k = order.size() + 1;  // everything past the basket is good already: start a new round
    } else {
      ++stats.iterations;
      if (stats.iterations % report_every == 0) report(progress, "improvement", stats.iterations, budget.operations);
      if (auto attempt = try_operations(mesh, e, options.operations, lm)) {
        [[maybe_unused]] const double worst_before = order.worst();
        for (const ElementId gone : attempt->change.removed) order.erase(gone);
        for (const ElementId added : attempt->change.added) order.insert(added, element_quality(mesh, added, quality));
        assert(order.worst() >= worst_before && "Algorithm 35 must never lower the worst quality");
        ++stats.successes[attempt->operation];
        continue;
      }
      ++k;
    }
    if (k > budget.basket || k > order.size()) {
      k = 1;
      if (++round > budget.baskets) break;
    }
  }
  stats.final_worst = order.worst();
  stats.final_mean = order.mean();
  stats.reached_target = stats.final_worst >= options.target_quality;
  return stats;
}

}  // namespace certimesh::generators
