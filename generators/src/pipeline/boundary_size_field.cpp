#include "boundary_size_field.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <stdexcept>
#include <utility>

namespace certimesh::generators::detail {

namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

double point_distance(const Point2& p, const Point2& q) { return std::hypot(p.x - q.x, p.y - q.y); }

// Approximate distance from p to the segment ab (it steers sizes only).
double distance_to_segment(const Point2& p, const Point2& a, const Point2& b) {
  const double ux = b.x - a.x, uy = b.y - a.y;
  const double length2 = ux * ux + uy * uy;
  const double t = length2 > 0.0 ? std::clamp(((p.x - a.x) * ux + (p.y - a.y) * uy) / length2, 0.0, 1.0) : 0.0;
  return point_distance(p, Point2{a.x + t * ux, a.y + t * uy});
}

}  // namespace

BoundarySizeField2::BoundarySizeField2(const PlanarDomain& domain, double grading, double maximum)
    : cdt_(domain.points), grading_(grading), maximum_(maximum) {
  if (!(grading > 0.0) || !std::isfinite(grading) || !(maximum > 0.0) || !std::isfinite(maximum))
    throw std::invalid_argument("the size grading and maximum must be positive and finite");
  for (const DomainSegment& s : domain.segments) cdt_.insert_constraint(s.a, s.b);
  measure_local_feature_sizes();
  propagate();
}

void BoundarySizeField2::measure_local_feature_sizes() {
  lfs_.assign(cdt_.vertex_count(), kInfinity);
  for (ConstrainedDelaunay2::TriangleId t = 0; t < cdt_.triangle_slot_count(); ++t) {
    if (!cdt_.is_live(t)) continue;
    const auto v = cdt_.vertices(t);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t corner = v[static_cast<std::size_t>(i)];
      const Point2& p = cdt_.point(corner);
      const Point2& a = cdt_.point(v[static_cast<std::size_t>((i + 1) % 3)]);
      const Point2& b = cdt_.point(v[static_cast<std::size_t>((i + 2) % 3)]);
      double nearest = std::min(point_distance(p, a), point_distance(p, b));
      if (cdt_.is_constrained(t, i)) nearest = std::min(nearest, distance_to_segment(p, a, b));
      lfs_[corner] = std::min(lfs_[corner], nearest);
    }
  }
  for (double& h : lfs_) h = std::min(h, maximum_);  // also a point in no triangle
}

// Dijkstra over the CDT's edges from every vertex at once: h_v = min_u (lfs_u + g·path(u, v)).
void BoundarySizeField2::propagate() {
  const std::size_t n = cdt_.vertex_count();
  std::vector<std::uint32_t> offset(n + 1, 0), target;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (ConstrainedDelaunay2::TriangleId t = 0; t < cdt_.triangle_slot_count(); ++t) {
    if (!cdt_.is_live(t)) continue;
    const auto v = cdt_.vertices(t);
    for (std::size_t i = 0; i < 3; ++i) edges.emplace_back(v[i], v[(i + 1) % 3]);  // each direction once per side
  }
  for (const auto& e : edges) ++offset[e.first + 1];
  for (std::size_t v = 0; v < n; ++v) offset[v + 1] += offset[v];
  target.resize(edges.size());
  std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
  for (const auto& e : edges) target[fill[e.first]++] = e.second;

  h_ = lfs_;
  using Entry = std::pair<double, std::uint32_t>;  // ties by id: deterministic
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (std::uint32_t v = 0; v < n; ++v) queue.emplace(h_[v], v);
  while (!queue.empty()) {
    const auto [h, u] = queue.top();
    queue.pop();
    if (h > h_[u]) continue;
    for (std::uint32_t k = offset[u]; k < offset[u + 1]; ++k) {
      const std::uint32_t w = target[k];
      const double through = h + grading_ * point_distance(cdt_.point(u), cdt_.point(w));
      if (through < h_[w]) {
        h_[w] = through;
        queue.emplace(through, w);
      }
    }
  }
  smallest_ = h_.empty() ? maximum_ : *std::min_element(h_.begin(), h_.end());
}

double BoundarySizeField2::operator()(const Point2& p) const {
  ConstrainedDelaunay2::TriangleId t = cdt_.locate(p, hint_);
  if (t != ConstrainedDelaunay2::none && !cdt_.is_live(t)) {  // a ghost or flat slot: a live neighbour
    ConstrainedDelaunay2::TriangleId live = ConstrainedDelaunay2::none;
    for (int i = 0; i < 3 && live == ConstrainedDelaunay2::none; ++i) live = cdt_.neighbour(t, i);
    t = live;
  }
  if (t == ConstrainedDelaunay2::none) return smallest_;  // only more elements, never invalid
  hint_ = t;
  double h = maximum_;
  for (const std::uint32_t v : cdt_.vertices(t)) h = std::min(h, h_[v] + grading_ * point_distance(p, cdt_.point(v)));
  return h;
}

double default_maximum_size(const PlanarDomain& domain) {
  if (domain.points.empty()) return 1.0;
  double xlo = kInfinity, ylo = kInfinity, xhi = -kInfinity, yhi = -kInfinity;
  for (const Point2& p : domain.points) {
    xlo = std::min(xlo, p.x);
    ylo = std::min(ylo, p.y);
    xhi = std::max(xhi, p.x);
    yhi = std::max(yhi, p.y);
  }
  const double diagonal = std::hypot(xhi - xlo, yhi - ylo);
  return diagonal > 0.0 ? default_maximum_fraction * diagonal : 1.0;
}

SizePolicy boundary_adapted_policy(const PlanarDomain& domain, const SizePolicy& user) {
  if (user.size_function || !(user.grading > 0.0)) return user;
  const double maximum = user.uniform_size > 0.0 ? user.uniform_size : default_maximum_size(domain);
  auto field = std::make_shared<const BoundarySizeField2>(domain, user.grading, maximum);
  SizePolicy policy;
  policy.growth = user.growth;
  policy.grading = 0.0;  // already applied
  if (field->smallest() >= maximum) {
    policy.uniform_size = maximum;
    return policy;
  }
  policy.size_function = [field](const Point2& p) { return (*field)(p); };
  return policy;
}

}  // namespace certimesh::generators::detail
