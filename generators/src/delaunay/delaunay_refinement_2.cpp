#include "certimesh/generators/delaunay/delaunay_refinement_2.h"

#include <algorithm>
#include <cmath>
#include <queue>
#include <tuple>

#include "refinement_geometry.h"

namespace certimesh::generators {

namespace {

using CdtTriangleId = ConstrainedDelaunay2::TriangleId;
using CdtVertexId = ConstrainedDelaunay2::VertexId;
constexpr std::uint32_t no_id = ConstrainedDelaunay2::none;
constexpr double pi = 3.141592653589793;

using detail::circumcentre;
using detail::Corners;
using detail::distance;

// The refinement state: the triangulation, its labels, the size and the work queue.
class Refiner {
 public:
  Refiner(ConstrainedDelaunay2& cdt, std::vector<int>& labels, const DelaunayRefinementOptions& options)
      : cdt_(cdt), labels_(labels), options_(options) {
    labels_.resize(cdt_.triangle_slot_count(), -1);
    if (options_.size.automatic()) automatic_size_ = automatic_size();
  }

  DelaunayRefinementStats run(const ProgressCallback& progress) {
    stats_.insertion_bound = options_.max_insertions ? options_.max_insertions : packing_bound();
    for (CdtTriangleId t = 0; t < cdt_.triangle_slot_count(); ++t) consider(t);
    while (!queue_.empty()) {
      const CdtTriangleId t = queue_.pop(cdt_);
      if (t == no_id) continue;
      if (stats_.inserted >= stats_.insertion_bound) {
        stats_.bound_reached = true;
        break;
      }
      refine(t);
      if ((stats_.inserted & 0x3fff) == 0) report(progress, "refinement", stats_.inserted, stats_.insertion_bound);
    }
    return stats_;
  }

 private:
  double size_at(const Point2& p) const {
    return options_.size.automatic() ? automatic_size_ : options_.size.at(p);
  }

  // The longest constrained edge of an inside triangle, times the growth factor.
  double automatic_size() const {
    double longest = 0.0;
    for (CdtTriangleId t = 0; t < cdt_.triangle_slot_count(); ++t) {
      if (!cdt_.is_live(t) || labels_[t] < 0) continue;
      const auto v = cdt_.vertices(t);
      for (int i = 0; i < 3; ++i)
        if (cdt_.is_constrained(t, i))
          longest = std::max(longest, distance(cdt_.point(v[static_cast<std::size_t>((i + 1) % 3)]),
                                               cdt_.point(v[static_cast<std::size_t>((i + 2) % 3)])));
    }
    return longest * std::max(1.0, options_.size.growth);
  }

  // Inserted points keep h/4 from their neighbours, so disks of radius h_min/8 around them are
  // disjoint and (nearly) inside: area / (pi (h_min/8)^2), with slack for the boundary.
  std::uint64_t packing_bound() const {
    double area = 0.0, smallest = 0.0;
    bool first = true;
    for (CdtTriangleId t = 0; t < cdt_.triangle_slot_count(); ++t) {
      if (!cdt_.is_live(t) || labels_[t] < 0) continue;
      const Corners c(cdt_, t);
      area += std::fabs((c.p[1].x - c.p[0].x) * (c.p[2].y - c.p[0].y) - (c.p[1].y - c.p[0].y) * (c.p[2].x - c.p[0].x)) / 2;
      for (const Point2& q : {c.p[0], c.p[1], c.p[2], c.centroid()}) {
        const double h = size_at(q);
        if (h > 0.0 && std::isfinite(h) && (first || h < smallest)) smallest = h, first = false;
      }
    }
    if (first || !(area > 0.0)) return 0;
    const double disks = 2.0 * area / (pi * (smallest / 8) * (smallest / 8)) + 64.0;
    return disks < 1e12 ? static_cast<std::uint64_t>(disks) : std::uint64_t{1000000000000};
  }

  // 0 when t is fine; otherwise how bad, too-big triangles first (badness > 1 + ratio).
  double badness(CdtTriangleId t) const {
    if (!cdt_.is_live(t) || labels_[t] < 0) return 0.0;
    const Corners c(cdt_, t);
    const double h = size_at(c.centroid());
    const double longest = longest_side(c.p[0], c.p[1], c.p[2]);
    if (h > 0.0 && longest > h) return 2.0 + longest / h;
    const double r = distance(circumcentre(c.p[0], c.p[1], c.p[2]), c.p[0]);
    // Skinny triangles are refined only while they are not tiny against the size: without
    // segment splitting a small input angle would otherwise attract points without end.
    if (r > options_.max_radius_edge_ratio * c.shortest() && !(h > 0.0 && r < h / 4)) return 1.0 + r / c.shortest() / 1e6;
    return 0.0;
  }

  void consider(CdtTriangleId t) {
    const double b = badness(t);
    if (b > 0.0) queue_.push(cdt_, t, b);
  }

  bool far_enough(const Point2& q, CdtTriangleId around, double h) const {
    const Corners c(cdt_, around);
    return std::min({distance(q, c.p[0]), distance(q, c.p[1]), distance(q, c.p[2])}) >= h / 4;
  }

  // A safe point for t: its circumcentre when reachable inside its region, else (t too big)
  // the midpoint of its longest unconstrained edge.
  void refine(CdtTriangleId t) {
    const int label = labels_[t];
    const Corners c(cdt_, t);
    const double h = size_at(c.centroid());
    const bool too_big = h > 0.0 && longest_side(c.p[0], c.p[1], c.p[2]) > h;
    const Point2 centre = circumcentre(c.p[0], c.p[1], c.p[2]);
    const CdtTriangleId holder = std::isfinite(centre.x) && std::isfinite(centre.y) ? detail::straight_walk(cdt_, t, centre).holder : no_id;
    if (holder != no_id && labels_[holder] == label && far_enough(centre, holder, size_at(centre))) {
      if (insert(centre, holder, label)) {
        ++stats_.circumcentres;
        return;
      }
    }
    if (too_big && insert_edge_midpoint(t, c, h, label)) {
      ++stats_.edge_midpoints;
      return;
    }
    ++stats_.skipped;
  }

  bool insert_edge_midpoint(CdtTriangleId t, const Corners& c, double h, int label) {
    int best = -1;
    double best_length = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double l = distance(c.p[static_cast<std::size_t>((i + 1) % 3)], c.p[static_cast<std::size_t>((i + 2) % 3)]);
      if (!cdt_.is_constrained(t, i) && cdt_.neighbour(t, i) != no_id && l > best_length) best = i, best_length = l;
    }
    if (best < 0 || !(best_length > h)) return false;
    const Point2 &a = c.p[static_cast<std::size_t>((best + 1) % 3)], &b = c.p[static_cast<std::size_t>((best + 2) % 3)];
    const Point2 m{a.x + (b.x - a.x) / 2, a.y + (b.y - a.y) / 2};
    const CdtTriangleId other = cdt_.neighbour(t, best);
    if (labels_[other] != label || !far_enough(m, t, h) || !far_enough(m, other, h)) return false;
    return insert(m, t, label);
  }

  // Inserts q when it lies in a triangle of region `label`. An edge midpoint is rounded, so
  // it need not lie on its edge: next to a segment it can fall across it, outside the region
  // (an edge along a segment, between points rounded onto the segment's line). The cavity
  // never crosses a constrained edge, so q's star then stays inside the region.
  bool insert(const Point2& q, CdtTriangleId hint, int label) {
    const CdtTriangleId at = cdt_.locate(q, hint);
    if (at == no_id || !cdt_.is_live(at) || labels_[at] != label) return false;
    const CdtVertexId v = cdt_.insert_point(q, at);
    if (v == no_id) return false;
    ++stats_.inserted;
    labels_.resize(cdt_.triangle_slot_count(), -1);
    // Every new triangle is incident to v (Bowyer-Watson star) and inside its region.
    const CdtTriangleId first = cdt_.incident_triangle(v);
    for (int direction = 1; direction <= 2; ++direction) {
      CdtTriangleId t = first;
      do {
        labels_[t] = label;
        consider(t);
        const auto vs = cdt_.vertices(t);
        const int k = vs[0] == v ? 0 : (vs[1] == v ? 1 : 2);
        t = cdt_.neighbour(t, (k + direction) % 3);
      } while (t != no_id && t != first);
      if (t == first) break;
    }
    return true;
  }

  ConstrainedDelaunay2& cdt_;
  std::vector<int>& labels_;
  const DelaunayRefinementOptions& options_;
  double automatic_size_ = 0.0;
  detail::WorstFirstQueue queue_;
  DelaunayRefinementStats stats_;
};

}  // namespace

double longest_side(const Point2& a, const Point2& b, const Point2& c) {
  return std::max({distance(a, b), distance(b, c), distance(c, a)});
}

DelaunayRefinementStats refine_delaunay_2(ConstrainedDelaunay2& cdt, std::vector<int>& labels,
                                          const DelaunayRefinementOptions& options, const ProgressCallback& progress) {
  return Refiner(cdt, labels, options).run(progress);
}

}  // namespace certimesh::generators
