// Algorithm 35 in 2D (quality_improvement_2.h; digest D §3.2).
//
// The work queue (the default schedule) is described in the header. The baskets schedule:
// rank pointer k and basket counter m as in the monograph: an element on which no operation
// succeeds goes into the basket (k := k + 1); after a success k is kept (the digest's reading
// of the printed listing); when k passes the basket size N2, the element count, or reaches an
// element already at the target, the basket is emptied (k := 1) and m counts one more round;
// more than N3 rounds means stagnation. Every committed operation raised the worst quality of
// what it changed strictly, so the mesh's worst quality never decreases.
#include "certimesh/generators/improvement/quality_improvement_2.h"

#include <algorithm>
#include <bit>
#include <cassert>
#include <cmath>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "certimesh/generators/improvement/angle_floor_2.h"
#include "certimesh/topology/element_orientation.h"
#include "certimesh/topology/quality.h"
#include "quality_order.h"

namespace certimesh::generators {

namespace {

using topology::ElementId;
using topology::LocalChange2;
using topology::TriangleMesh2;
using topology::VertexId;

topology::TriangleQualityFunction2 base_quality_function(const SizePolicy& size) {
  if (size.automatic())
    return [](const topology::Point2d& a, const topology::Point2d& b, const topology::Point2d& c) {
      return topology::triangle_quality(a, b, c);
    };
  return [size](const topology::Point2d& a, const topology::Point2d& b, const topology::Point2d& c) {
    const Point2 centroid{(a[0] + b[0] + c[0]) / 3.0, (a[1] + b[1] + c[1]) / 3.0};
    return topology::size_aware_triangle_quality(a, b, c, size.at(centroid));
  };
}

// With an angle floor, the floored score (angle_floor_2.h): a modification is committed only
// when the changed elements' worst score rises, so one that brings an element below the floor
// from none, or lowers the smallest angle below it further, is refused.
topology::TriangleQualityFunction2 quality_function(const ImprovementOptions2& options) {
  topology::TriangleQualityFunction2 base = base_quality_function(options.size);
  if (!(options.min_angle_floor > 0.0)) return base;
  return [base = std::move(base), floor = options.min_angle_floor](const topology::Point2d& a, const topology::Point2d& b,
                                                                    const topology::Point2d& c) {
    return floored_score(base(a, b, c), a, b, c, floor);
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

// The monograph's listing: rank pointer k over the ordered elements, baskets and rounds.
void run_baskets(TriangleMesh2& mesh, const ImprovementOptions2& options, const topology::LocalModificationOptions2& lm,
                 improvement::QualityOrder& order, ImprovementStats2& stats, const ProgressCallback& progress) {
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
        for (const ElementId added : attempt->change.added) order.insert(added, element_quality(mesh, added, lm.quality));
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
}

// The work queue (quality_improvement_2.h): the elements below the target, worst first; each
// tried once per entry; re-entered only when a committed modification touched it.
class WorkQueue {
 public:
  WorkQueue(const TriangleMesh2& mesh, const improvement::QualityOrder& order, double target, std::uint32_t max_attempts)
      : mesh_(mesh), order_(order), target_(target), max_attempts_(max_attempts) {}

  void offer(ElementId e) {
    if (!mesh_.is_live(e) || order_.quality(e) >= target_) return;
    if (attempts_.size() <= e.value) attempts_.resize(e.value + 1, 0);
    if (attempts_[e.value] >= max_attempts_) return;
    queue_.emplace(order_.quality(e), e.value);
  }
  /// Before an element leaves the mesh or changes its quality: out of the queue.
  void withdraw(ElementId e) { queue_.erase({order_.quality(e), e.value}); }
  bool empty() const { return queue_.empty(); }
  ElementId take() {
    const ElementId e{queue_.begin()->second};
    queue_.erase(queue_.begin());
    ++attempts_[e.value];
    return e;
  }
  /// A removed id that the mesh reuses for a new element starts afresh; one kept (a node shift's
  /// star) keeps its count.
  void forget(ElementId e) {
    if (e.value < attempts_.size()) attempts_[e.value] = 0;
  }

 private:
  const TriangleMesh2& mesh_;
  const improvement::QualityOrder& order_;
  double target_;
  std::uint32_t max_attempts_;
  std::set<std::pair<double, std::uint32_t>> queue_;  // (quality, id): worst first, ties by id
  std::vector<std::uint32_t> attempts_;               // by element slot
};

void run_work_queue(TriangleMesh2& mesh, const ImprovementOptions2& options, const topology::LocalModificationOptions2& lm,
                    improvement::QualityOrder& order, ImprovementStats2& stats, const ProgressCallback& progress) {
  const Budget budget = budget_of(options, order.size());
  const std::uint64_t report_every = std::max<std::uint64_t>(1, budget.operations / 200);
  WorkQueue queue(mesh, order, options.target_quality, std::max<std::uint32_t>(options.max_attempts, 1));
  for (std::uint32_t slot = 0; slot < mesh.element_slot_count(); ++slot) queue.offer(ElementId{slot});
  std::vector<ElementId> touched;
  double worst = order.worst();
  std::uint64_t last_raise = 0;  // the iteration that last raised the worst quality
  while (!queue.empty() && stats.iterations < budget.operations) {
    if (options.stall_iterations > 0 && stats.iterations - last_raise >= options.stall_iterations) break;
    if (order.worst() > worst) worst = order.worst(), last_raise = stats.iterations;
    const ElementId e = queue.take();
    ++stats.iterations;
    if (stats.iterations % report_every == 0) report(progress, "improvement", stats.iterations, budget.operations);
    auto attempt = try_operations(mesh, e, options.operations, lm);
    if (!attempt) continue;
    [[maybe_unused]] const double worst_before = order.worst();
    const LocalChange2& change = attempt->change;
    for (const ElementId gone : change.removed) {
      queue.withdraw(gone);
      order.erase(gone);
      if (std::find(change.added.begin(), change.added.end(), gone) == change.added.end()) queue.forget(gone);
    }
    touched.clear();
    for (const ElementId added : change.added) {
      order.insert(added, element_quality(mesh, added, lm.quality));
      touched.push_back(added);
      for (int i = 0; i < 3; ++i) {
        const ElementId n = mesh.neighbour(added, i);
        if (!n.is_none() && mesh.is_live(n)) touched.push_back(n);
      }
    }
    for (const ElementId t : touched) {
      queue.withdraw(t);
      queue.offer(t);
    }
    assert(order.worst() >= worst_before && "Algorithm 35 must never lower the worst quality");
    ++stats.successes[attempt->operation];
  }
}

}  // namespace

ImprovementStats2 improve_quality_2(TriangleMesh2& mesh, const ImprovementOptions2& options,
                                    const ProgressCallback& progress) {
  require_counterclockwise(mesh);
  const auto quality = quality_function(options);
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
  if (options.schedule == ImprovementSchedule2::baskets)
    run_baskets(mesh, options, lm, order, stats, progress);
  else
    run_work_queue(mesh, options, lm, order, stats, progress);
  stats.final_worst = order.worst();
  stats.final_mean = order.mean();
  stats.reached_target = stats.final_worst >= options.target_quality;
  return stats;
}

}  // namespace certimesh::generators
