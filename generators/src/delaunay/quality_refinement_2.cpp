#include "certimesh/generators/delaunay/quality_refinement_2.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <tuple>
#include <deque>
#include <unordered_map>
#include <unordered_set>

#include "../pipeline/point_on_segment.h"
#include "certimesh/predicates/incircle.h"
#include "refinement_geometry.h"

namespace certimesh::generators {

namespace {

using CdtTriangleId = ConstrainedDelaunay2::TriangleId;
using CdtVertexId = ConstrainedDelaunay2::VertexId;
using detail::circumcentre;
using detail::Corners;
using detail::distance;
constexpr std::uint32_t none = ConstrainedDelaunay2::none;
constexpr double degree = 3.14159265358979323846 / 180.0;

std::uint64_t cdt_edge_key(CdtVertexId u, CdtVertexId w) {
  return (std::uint64_t{std::min(u, w)} << 32) | std::max(u, w);
}

double dot_about(const Point2& o, const Point2& a, const Point2& b) {
  return (a.x - o.x) * (b.x - o.x) + (a.y - o.y) * (b.y - o.y);
}

// Whether c lies strictly inside the diametral circle of (a, b): the angle acb exceeds 90°.
bool in_diametral_circle(const Point2& a, const Point2& b, const Point2& c) { return dot_about(c, a, b) < 0.0; }

// Where a vertex lies: on which input segment (none for an interior or input vertex) and at
// which fraction of it (the double whose exact point was rounded to the vertex).
struct Place {
  std::uint32_t segment = none;
  double fraction = 0.0;
};

class QualityRefiner {
 public:
  QualityRefiner(ConstrainedDelaunay2& cdt, std::vector<int>& labels, std::vector<Subsegment2>& subsegments,
                 const QualityRefinementOptions& options)
      : cdt_(cdt), labels_(labels), subsegments_(subsegments), options_(options),
        min_angle_(options.min_angle_degrees) {
    if (!(min_angle_ > 0.0 && min_angle_ < 60.0))
      throw std::invalid_argument("the minimum angle must be in (0, 60) degrees, got " + std::to_string(min_angle_));
    labels_.resize(cdt_.triangle_slot_count(), -1);
    places_.resize(cdt_.vertex_count());
    for (std::uint32_t i = 0; i < subsegments_.size(); ++i) {
      const Subsegment2& s = subsegments_[i];
      index_of_.emplace(cdt_edge_key(s.a, s.b), i);
      for (const CdtVertexId v : {s.a, s.b})
        if (v >= options_.input_vertices) places_[v] = {s.segment, projected_fraction(s.segment, cdt_.point(v))};
    }
  }

  QualityRefinementStats run(const ProgressCallback& progress) {
    for (std::uint32_t i = 0; i < subsegments_.size(); ++i) check_encroached(subsegments_[i].a, subsegments_[i].b);
    for (CdtTriangleId t = 0; t < cdt_.triangle_slot_count(); ++t) consider(t);
    while (!stats_.cap_reached) {
      if (!encroached_.empty()) {
        const Encroached e = encroached_.front();
        encroached_.pop_front();
        if (is_subsegment(e.u, e.w) && (e.by_circumcentre || encroached(e.u, e.w))) split(e.u, e.w);
        continue;
      }
      if (triangles_.empty()) break;
      const CdtTriangleId t = triangles_.pop(cdt_);
      if (t == none || badness(t) <= 0.0) continue;
      refine(t);
      if ((stats_.inserted & 0x3fff) == 0) report(progress, "quality refinement", stats_.inserted, options_.max_steiner);
    }
    final_statistics();
    return stats_;
  }

 private:

  const InputSegment2& segment(std::uint32_t s) const { return options_.segments[s]; }
  Point2 end_a(std::uint32_t s) const { return cdt_.point(segment(s).a); }
  Point2 end_b(std::uint32_t s) const { return cdt_.point(segment(s).b); }

  double projected_fraction(std::uint32_t s, const Point2& p) const {
    const Point2 a = end_a(s), b = end_b(s);
    const double l2 = dot_about(a, b, b);
    return l2 > 0.0 ? std::clamp(dot_about(a, p, b) / l2, 0.0, 1.0) : 0.0;
  }

  bool is_input(CdtVertexId v) const { return v < options_.input_vertices; }

  // The fraction of vertex v along input segment s (its ends: 0 and 1).
  double fraction(CdtVertexId v, std::uint32_t s) const {
    if (v == segment(s).a) return 0.0;
    if (v == segment(s).b) return 1.0;
    return places_[v].fraction;
  }

  bool is_subsegment(CdtVertexId u, CdtVertexId w) const { return index_of_.count(cdt_edge_key(u, w)) != 0; }

  bool is_inside(CdtTriangleId t) const { return t != none && cdt_.is_live(t) && labels_[t] >= 0; }

  // The apex of the live inside triangle left of u -> w, or none.
  CdtVertexId inside_apex(CdtVertexId u, CdtVertexId w) const {
    const CdtTriangleId t = cdt_.triangle_left_of(u, w);
    if (!is_inside(t)) return none;
    const auto v = cdt_.vertices(t);
    for (const CdtVertexId x : v)
      if (x != u && x != w) return x;
    return none;
  }

  bool encroached(CdtVertexId u, CdtVertexId w) const {
    if (refused_.count(cdt_edge_key(u, w))) return false;
    for (const CdtVertexId apex : {inside_apex(u, w), inside_apex(w, u)})
      if (apex != none && in_diametral_circle(cdt_.point(u), cdt_.point(w), cdt_.point(apex))) return true;
    return false;
  }

  void check_encroached(CdtVertexId u, CdtVertexId w) {
    if (encroached(u, w)) encroached_.push_back({u, w, false});
  }

  // The exemption of the header, on this refinement's own record of which segment each
  // Steiner point was put on.
  bool exempt(const std::array<CdtVertexId, 3>& v, const Corners& c) const {
    int shortest = 0;
    for (int i = 1; i < 3; ++i)
      if (c.side(i) < c.side(shortest)) shortest = i;
    const CdtVertexId u = v[static_cast<std::size_t>((shortest + 1) % 3)], w = v[static_cast<std::size_t>((shortest + 2) % 3)];
    if (is_input(u) || is_input(w)) return false;
    const std::uint32_t su = places_[u].segment, sw = places_[w].segment;
    if (su == none || sw == none || su == sw) return false;
    CdtVertexId z = none;
    for (const CdtVertexId e : {segment(su).a, segment(su).b})
      if (e == segment(sw).a || e == segment(sw).b) z = e;
    if (z == none) return false;
    const Point2 pz = cdt_.point(z);
    const Point2 far_u = segment(su).a == z ? end_b(su) : end_a(su);
    const Point2 far_w = segment(sw).a == z ? end_b(sw) : end_a(sw);
    if (smallest_angle_at(pz, far_u, far_w) >= 60.0) return false;
    const double du = dot_about(pz, cdt_.point(u), cdt_.point(u)), dw = dot_about(pz, cdt_.point(w), cdt_.point(w));
    return du < 1.001 * dw && dw < 1.001 * du;
  }

  static double smallest_angle_at(const Point2& o, const Point2& a, const Point2& b) {
    const double cross = (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x);
    return std::atan2(std::fabs(cross), dot_about(o, a, b)) / degree;
  }

  double size_at(const Point2& p) const { return options_.size.automatic() ? 0.0 : options_.size.at(p); }

  // 0 when t is fine; too big ones first (> 2), then skinny ones, the smallest angle first.
  double badness(CdtTriangleId t) const {
    if (!is_inside(t)) return 0.0;
    const Corners c(cdt_, t);
    const double h = size_at(c.centroid());
    const double longest = std::max({c.side(0), c.side(1), c.side(2)});
    if (h > 0.0 && longest > h) return 2.0 + longest / h;
    const double angle = smallest_angle_degrees(c[0], c[1], c[2]);
    if (angle >= min_angle_ || exempt(cdt_.vertices(t), c)) return 0.0;
    return 1.0 + (min_angle_ - angle) / min_angle_;
  }

  void consider(CdtTriangleId t) {
    const double b = badness(t);
    if (b > 0.0) triangles_.push(cdt_, t, b);
  }

  bool at_cap() {
    if (stats_.inserted >= options_.max_steiner) stats_.cap_reached = true;
    return stats_.cap_reached;
  }

  // Splits bad triangle t at its circumcentre, or the subsegments that keep it out.
  void refine(CdtTriangleId t) {
    if (at_cap()) return;
    const Corners c(cdt_, t);
    const Point2 centre = circumcentre(c[0], c[1], c[2]);
    if (!std::isfinite(centre.x) || !std::isfinite(centre.y)) return;
    const detail::WalkEnd end = detail::straight_walk(cdt_, t, centre);
    if (end.holder == none) {
      if (end.before == none) return;  // blocked by a vertex on the way: leave t
      const auto v = cdt_.vertices(end.before);
      const CdtVertexId u = v[static_cast<std::size_t>((end.edge + 1) % 3)], w = v[static_cast<std::size_t>((end.edge + 2) % 3)];
      if (is_subsegment(u, w) && !refused_.count(cdt_edge_key(u, w))) {
        split(u, w);
        consider(t);
      }
      return;
    }
    if (labels_[end.holder] != labels_[t]) return;
    bool rejected = false;
    for (const auto& [u, w] : cavity_subsegments(end.holder, centre)) {
      if (refused_.count(cdt_edge_key(u, w)) || !in_diametral_circle(cdt_.point(u), cdt_.point(w), centre)) continue;
      encroached_.push_back({u, w, true});
      rejected = true;
    }
    if (rejected) {
      consider(t);
      return;
    }
    const int label = labels_[t];
    const CdtVertexId v = cdt_.insert_point(centre, end.holder);
    if (v == none) return;
    ++stats_.inserted;
    ++stats_.circumcentres;
    places_.resize(cdt_.vertex_count());
    labels_.resize(cdt_.triangle_slot_count(), -1);
    for (const CdtTriangleId s : star(v)) labels_[s] = label;
    after_insertion(v);
  }

  // The subsegments on the boundary of p's cavity (the triangles whose circumcircle holds p,
  // reachable from `holder` without crossing a constrained edge): those p could encroach.
  std::vector<std::array<CdtVertexId, 2>> cavity_subsegments(CdtTriangleId holder, const Point2& p) {
    std::vector<std::array<CdtVertexId, 2>> out;
    visited_.clear();
    std::vector<CdtTriangleId> stack{holder};
    visited_.push_back(holder);
    while (!stack.empty()) {
      const CdtTriangleId t = stack.back();
      stack.pop_back();
      const auto v = cdt_.vertices(t);
      for (int i = 0; i < 3; ++i) {
        const CdtVertexId u = v[static_cast<std::size_t>((i + 1) % 3)], w = v[static_cast<std::size_t>((i + 2) % 3)];
        if (cdt_.is_constrained(t, i)) {
          if (is_subsegment(u, w)) out.push_back({u, w});
          continue;
        }
        const CdtTriangleId n = cdt_.neighbour(t, i);
        if (n == none || std::find(visited_.begin(), visited_.end(), n) != visited_.end()) continue;
        const Corners cn(cdt_, n);
        if (predicates::incircle(cn[0], cn[1], cn[2], p) != predicates::Sign::positive) continue;
        visited_.push_back(n);
        stack.push_back(n);
      }
    }
    return out;
  }

  // The fraction along input segment s where subsegment (u, w) is split: concentric shells
  // when exactly one end is an input vertex, else the middle.
  double split_fraction(CdtVertexId u, CdtVertexId w, std::uint32_t s) const {
    const double fu = fraction(u, s), fw = fraction(w, s);
    if (is_input(u) == is_input(w)) return fu + (fw - fu) / 2;
    const double length = distance(end_a(s), end_b(s));
    const double piece = length * std::fabs(fw - fu);
    int exponent = 0;
    std::frexp(piece / 1.5, &exponent);               // piece / 1.5 = m 2^exponent, m in [1/2, 1)
    const double shell = std::ldexp(1.0, exponent - 1);  // piece / 3 < shell <= piece / 1.5
    const double from = is_input(u) ? fu : fw, to = is_input(u) ? fw : fu;
    return from + (to > from ? shell : -shell) / length;
  }

  // Splits (u, w) at the rounding of an exact point of its input segment s: the shell or
  // middle fraction first; when its rounding falls outside the thin triangle beside the edge,
  // fractions moved along the segment by (fw - fu) 2^-k, k = 44 ... 14 (the rounding moves
  // with them; the shell radius by at most 2^-14 of the piece), each side. The vertex made and
  // its fraction, or none.
  std::pair<CdtVertexId, double> split_point(CdtVertexId u, CdtVertexId w, std::uint32_t s) {
    const double fu = fraction(u, s), fw = fraction(w, s);
    const double f0 = split_fraction(u, w, s);
    for (int k = 45; k >= 14; --k) {
      for (const double sign : {1.0, -1.0}) {
        const double f = k == 45 ? f0 : f0 + sign * std::ldexp(fw - fu, -k);
        if ((f - fu) * (fw - f) <= 0.0) continue;
        const CdtVertexId v = cdt_.split_constraint(u, w, detail::point_on_segment(end_a(s), end_b(s), f));
        if (v != none) return {v, f};
        if (k == 45) break;
      }
    }
    return {none, 0.0};
  }

  void split(CdtVertexId u, CdtVertexId w) {
    if (at_cap()) return;
    const auto found = index_of_.find(cdt_edge_key(u, w));
    if (found == index_of_.end()) return;
    const std::uint32_t index = found->second;
    const std::uint32_t s = subsegments_[index].segment;
    const int left = label_left_of(u, w), right = label_left_of(w, u);
    const auto [v, f] = split_point(u, w, s);
    if (v != none) {
      labels_.resize(cdt_.triangle_slot_count(), -1);
      label_sector(v, w, u, left);   // left of u -> v -> w: from w round to u
      label_sector(v, u, w, right);
    }
    if (v == none) {
      ++stats_.refused_splits;
      refused_.insert(cdt_edge_key(u, w));
      return;
    }
    ++stats_.inserted;
    ++stats_.segment_splits;
    places_.resize(cdt_.vertex_count());
    places_[v] = {s, f};
    index_of_.erase(found);
    subsegments_[index] = {u, v, s};
    index_of_.emplace(cdt_edge_key(u, v), index);
    index_of_.emplace(cdt_edge_key(v, w), static_cast<std::uint32_t>(subsegments_.size()));
    subsegments_.push_back({v, w, s});
    after_insertion(v);
    check_encroached(u, v);
    check_encroached(v, w);
  }

  int label_left_of(CdtVertexId u, CdtVertexId w) const {
    const CdtTriangleId t = cdt_.triangle_left_of(u, w);
    return t != none && cdt_.is_live(t) ? labels_[t] : -1;
  }

  // Labels the live triangles around v counterclockwise from the edge (v, from) to the edge
  // (v, to), both constrained: from both ends, as a hull gap may cut the sweep.
  void label_sector(CdtVertexId v, CdtVertexId from, CdtVertexId to, int label) {
    for (CdtTriangleId t = cdt_.triangle_left_of(v, from); t != none;) {
      labels_[t] = label;
      const auto c = cdt_.vertices(t);
      const int k = c[0] == v ? 0 : (c[1] == v ? 1 : 2);
      if (c[static_cast<std::size_t>((k + 2) % 3)] == to) break;
      t = cdt_.neighbour(t, (k + 1) % 3);
    }
    for (CdtTriangleId t = cdt_.triangle_left_of(to, v); t != none;) {
      labels_[t] = label;
      const auto c = cdt_.vertices(t);
      const int k = c[0] == v ? 0 : (c[1] == v ? 1 : 2);
      if (c[static_cast<std::size_t>((k + 1) % 3)] == from) break;
      t = cdt_.neighbour(t, (k + 2) % 3);
    }
  }

  // The live triangles around v (every triangle an insertion creates is one of them).
  std::vector<CdtTriangleId> star(CdtVertexId v) const {
    std::vector<CdtTriangleId> out;
    const CdtTriangleId first = cdt_.incident_triangle(v);
    for (int direction = 1; direction <= 2 && first != none; ++direction) {
      CdtTriangleId t = first;
      do {
        if (direction == 1 || t != first) out.push_back(t);
        const auto c = cdt_.vertices(t);
        const int k = c[0] == v ? 0 : (c[1] == v ? 1 : 2);
        t = cdt_.neighbour(t, (k + direction) % 3);
      } while (t != none && t != first);
      if (t == first) break;
    }
    return out;
  }

  // New triangles are considered; the subsegments opposite v are checked against v.
  void after_insertion(CdtVertexId v) {
    for (const CdtTriangleId t : star(v)) {
      consider(t);
      const auto c = cdt_.vertices(t);
      const int k = c[0] == v ? 0 : (c[1] == v ? 1 : 2);
      const CdtVertexId a = c[static_cast<std::size_t>((k + 1) % 3)], b = c[static_cast<std::size_t>((k + 2) % 3)];
      if (cdt_.is_constrained(t, k) && is_subsegment(a, b)) check_encroached(a, b);
    }
  }

  void final_statistics() {
    bool first = true, first_exempt = true;
    for (CdtTriangleId t = 0; t < cdt_.triangle_slot_count(); ++t) {
      if (!is_inside(t)) continue;
      const Corners c(cdt_, t);
      const double angle = smallest_angle_degrees(c[0], c[1], c[2]);
      if (angle < min_angle_ && exempt(cdt_.vertices(t), c)) {
        ++stats_.exempt;
        if (first_exempt || angle < stats_.smallest_exempt_angle) stats_.smallest_exempt_angle = angle;
        first_exempt = false;
        continue;
      }
      if (angle < min_angle_) ++stats_.below_min_angle;
      if (first || angle < stats_.smallest_angle) stats_.smallest_angle = angle;
      first = false;
    }
  }

  ConstrainedDelaunay2& cdt_;
  std::vector<int>& labels_;
  std::vector<Subsegment2>& subsegments_;
  const QualityRefinementOptions& options_;
  const double min_angle_;
  std::vector<Place> places_;                               // by vertex id
  std::unordered_map<std::uint64_t, std::uint32_t> index_of_;  // subsegment -> index (lookups only)
  std::unordered_set<std::uint64_t> refused_;         // subsegments that cannot be split
  struct Encroached {
    CdtVertexId u, w;
    bool by_circumcentre;  // a rejected circumcentre: split even if no vertex encroaches it
  };
  std::deque<Encroached> encroached_;
  detail::WorstFirstQueue triangles_;
  std::vector<CdtTriangleId> visited_;
  QualityRefinementStats stats_;
};

}  // namespace

double smallest_angle_degrees(const Point2& a, const Point2& b, const Point2& c) {
  const Point2 p[3] = {a, b, c};
  double smallest = 180.0;
  for (int i = 0; i < 3; ++i) {
    const Point2 &o = p[i], &u = p[(i + 1) % 3], &w = p[(i + 2) % 3];
    const double cross = (u.x - o.x) * (w.y - o.y) - (u.y - o.y) * (w.x - o.x);
    smallest = std::min(smallest, std::atan2(std::fabs(cross), dot_about(o, u, w)) / degree);
  }
  return smallest;
}

QualityRefinementStats refine_quality_2(ConstrainedDelaunay2& cdt, std::vector<int>& labels,
                                        std::vector<Subsegment2>& subsegments, const QualityRefinementOptions& options,
                                        const ProgressCallback& progress) {
  return QualityRefiner(cdt, labels, subsegments, options).run(progress);
}

}  // namespace certimesh::generators
