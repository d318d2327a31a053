// validate_domain: structural checks (finiteness, indices, duplicates, isolated vertices) by
// sorting, then the geometric checks on every pair of segments whose bounding boxes meet.
// Bounding boxes of double end points are exact (min and max do not round), so the broad phase
// never misses a pair; the narrow phase is the exact segment_segment_2d test, then orient2d
// and coordinate comparisons say which kind of contact it is.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/predicates/intersection/segment_segment_2d.h"
#include "certimesh/predicates/orient2d.h"
#include "domain_text.h"

namespace certimesh::generators {

namespace {

using detail::id_list_text;
using detail::point_text;
using detail::segment_text;
using predicates::Sign;

// Collects problems up to the cap; every check stops early once it is full.
class ProblemList {
 public:
  explicit ProblemList(std::size_t cap) : cap_(cap) {}
  bool full() const { return problems_.size() >= cap_; }
  void add(DomainProblemKind kind, std::vector<std::uint32_t> segments,
           std::vector<std::uint32_t> vertices, std::string message) {
    if (full()) return;
    problems_.push_back(DomainProblem{kind, std::move(segments), std::move(vertices), std::move(message)});
  }
  std::vector<DomainProblem> take() { return std::move(problems_); }

 private:
  std::size_t cap_;
  std::vector<DomainProblem> problems_;
};

bool is_finite(const Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// Lexicographic order of points; for collinear points it is the order along their line.
bool lex_less(const Point2& p, const Point2& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); }

// What the structural checks learn about each segment: may the geometric checks use it?
struct SegmentUsability {
  std::vector<bool> usable;  // both ends in range and finite, not of zero length
};

void check_non_finite(const PlanarDomain& d, ProblemList& out) {
  for (std::uint32_t v = 0; v < d.points.size() && !out.full(); ++v) {
    if (is_finite(d.points[v])) continue;
    out.add(DomainProblemKind::non_finite_coordinate, {}, {v},
            "vertex " + std::to_string(v) + " has a non-finite coordinate " + point_text(d.points[v]));
  }
  for (std::size_t h = 0; h < d.holes.size() && !out.full(); ++h) {
    if (is_finite(d.holes[h])) continue;
    out.add(DomainProblemKind::non_finite_coordinate, {}, {},
            "hole point " + std::to_string(h) + " has a non-finite coordinate " + point_text(d.holes[h]));
  }
  for (std::size_t r = 0; r < d.regions.size() && !out.full(); ++r) {
    if (is_finite(d.regions[r].point)) continue;
    out.add(DomainProblemKind::non_finite_coordinate, {}, {},
            "region point " + std::to_string(r) + " has a non-finite coordinate " +
                point_text(d.regions[r].point));
  }
}

void check_indices(const PlanarDomain& d, ProblemList& out) {
  const std::size_t n = d.points.size();
  for (std::uint32_t s = 0; s < d.segments.size() && !out.full(); ++s) {
    for (const DomainVertex v : {d.segments[s].a, d.segments[s].b}) {
      if (v < n) continue;
      out.add(DomainProblemKind::vertex_index_out_of_range, {s}, {v},
              "segment " + std::to_string(s) + " names vertex " + std::to_string(v) +
                  ", but the domain has only " + std::to_string(n) + " vertices");
      break;
    }
  }
}

bool ends_in_range(const PlanarDomain& d, const DomainSegment& s) {
  return s.a < d.points.size() && s.b < d.points.size();
}

void check_zero_length(const PlanarDomain& d, ProblemList& out) {
  for (std::uint32_t s = 0; s < d.segments.size() && !out.full(); ++s) {
    const DomainSegment& seg = d.segments[s];
    if (!ends_in_range(d, seg)) continue;
    if (seg.a == seg.b) {
      out.add(DomainProblemKind::zero_length_segment, {s}, {seg.a},
              "segment " + std::to_string(s) + " has zero length: both ends are vertex " +
                  std::to_string(seg.a) + " " + point_text(d.points[seg.a]));
    } else if (d.points[seg.a] == d.points[seg.b]) {
      out.add(DomainProblemKind::zero_length_segment, {s}, {seg.a, seg.b},
              "segment " + std::to_string(s) + " has zero length: its ends, vertices " +
                  std::to_string(seg.a) + " and " + std::to_string(seg.b) + ", are both at " +
                  point_text(d.points[seg.a]));
    }
  }
}

// Distinct ids at the same point (0 and -0 are the same point: the predicates see one point).
void check_duplicate_vertices(const PlanarDomain& d, ProblemList& out) {
  std::vector<std::uint32_t> order;
  for (std::uint32_t v = 0; v < d.points.size(); ++v) {
    if (is_finite(d.points[v])) order.push_back(v);
  }
  std::sort(order.begin(), order.end(), [&](std::uint32_t u, std::uint32_t v) {
    if (d.points[u] == d.points[v]) return u < v;
    return lex_less(d.points[u], d.points[v]);
  });
  for (std::size_t i = 0; i < order.size() && !out.full();) {
    std::size_t j = i + 1;
    while (j < order.size() && d.points[order[j]] == d.points[order[i]]) ++j;
    if (j - i > 1) {
      std::vector<std::uint32_t> ids(order.begin() + static_cast<std::ptrdiff_t>(i),
                                     order.begin() + static_cast<std::ptrdiff_t>(j));
      std::string message = "vertices ";
      message += id_list_text(ids);
      message += ids.size() > 2 ? " are all at " : " are both at ";
      message += point_text(d.points[order[i]]);
      out.add(DomainProblemKind::duplicate_vertices, {}, std::move(ids), message);
    }
    i = j;
  }
}

void check_duplicate_segments(const PlanarDomain& d, ProblemList& out) {
  struct Key {
    DomainVertex lo, hi;
    std::uint32_t id;
  };
  std::vector<Key> keys;
  for (std::uint32_t s = 0; s < d.segments.size(); ++s) {
    const DomainSegment& seg = d.segments[s];
    if (seg.a == seg.b) continue;
    keys.push_back({std::min(seg.a, seg.b), std::max(seg.a, seg.b), s});
  }
  std::sort(keys.begin(), keys.end(), [](const Key& p, const Key& q) {
    return std::tie(p.lo, p.hi, p.id) < std::tie(q.lo, q.hi, q.id);
  });
  for (std::size_t i = 0; i < keys.size() && !out.full();) {
    std::size_t j = i + 1;
    while (j < keys.size() && keys[j].lo == keys[i].lo && keys[j].hi == keys[i].hi) ++j;
    if (j - i > 1) {
      std::vector<std::uint32_t> ids;
      for (std::size_t k = i; k < j; ++k) ids.push_back(keys[k].id);
      // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "literal" + string&&.
      std::string message = "segments ";
      message += id_list_text(ids);
      message += ids.size() > 2 ? " all join vertices " : " both join vertices ";
      message += std::to_string(keys[i].lo) + " and " + std::to_string(keys[i].hi);
      if (keys[i].hi < d.points.size()) {
        message += ' ';
        message += point_text(d.points[keys[i].lo]);
        message += '-';
        message += point_text(d.points[keys[i].hi]);
      }
      out.add(DomainProblemKind::duplicate_segments, std::move(ids), {keys[i].lo, keys[i].hi}, message);
    }
    i = j;
  }
}

// The vertices on no segment: isolated points the user wants as mesh vertices.
std::vector<bool> on_some_segment(const PlanarDomain& d) {
  std::vector<bool> used(d.points.size(), false);
  for (const DomainSegment& s : d.segments) {
    if (s.a < used.size()) used[s.a] = true;
    if (s.b < used.size()) used[s.b] = true;
  }
  return used;
}

// ---- the geometric pair checks ------------------------------------------------------------

struct SegmentBox {
  double xmin, xmax, ymin, ymax;
  std::uint32_t segment;  // kIsolated for the box of an isolated vertex
  std::uint32_t vertex = 0;
};
constexpr std::uint32_t kIsolated = UINT32_MAX;

// Is p, collinear with segment (a, b), strictly between a and b?
bool strictly_inside_collinear(const Point2& p, const Point2& a, const Point2& b) {
  return lex_less(a, b) ? (lex_less(a, p) && lex_less(p, b)) : (lex_less(b, p) && lex_less(p, a));
}

std::string pair_text(const PlanarDomain& d, std::uint32_t s, std::uint32_t t) {
  return "segments " + segment_text(d, s) + " and " + segment_text(d, t);
}

// Two segments sharing vertex `v`, other ends p (of s) and q (of t): they intersect beyond v
// only when collinear and pointing the same way (an overlap). Anything else the exact test
// reports with a shared vertex is two distinct ids at the same point: already reported.
void classify_with_shared_vertex(const PlanarDomain& d, std::uint32_t s, std::uint32_t t, DomainVertex v,
                                 DomainVertex p, DomainVertex q, ProblemList& out) {
  const Point2& pv = d.points[v];
  const Point2& pp = d.points[p];
  const Point2& pq = d.points[q];
  if (predicates::orient2d(pv, pp, pq) != Sign::zero) return;
  if (lex_less(pv, pp) != lex_less(pv, pq)) return;
  out.add(DomainProblemKind::segments_overlap, {s, t}, {v},
          pair_text(d, s, t) + " overlap: collinear from their common vertex " + std::to_string(v));
}

void classify_collinear(const PlanarDomain& d, std::uint32_t s, std::uint32_t t, ProblemList& out) {
  const DomainSegment& a = d.segments[s];
  const DomainSegment& b = d.segments[t];
  auto lo = [&](const DomainSegment& g) { return std::min(d.points[g.a], d.points[g.b], lex_less); };
  auto hi = [&](const DomainSegment& g) { return std::max(d.points[g.a], d.points[g.b], lex_less); };
  const Point2 start = std::max(lo(a), lo(b), lex_less);
  const Point2 end = std::min(hi(a), hi(b), lex_less);
  if (!lex_less(start, end)) return;  // one common point: duplicate vertices, reported
  out.add(DomainProblemKind::segments_overlap, {s, t}, {}, pair_text(d, s, t) + " overlap");
}

// No shared vertex id and the exact test says they meet: a T-junction, a crossing, a
// collinear overlap, or a touch through duplicate vertices (already reported).
void classify_disjoint_ids(const PlanarDomain& d, std::uint32_t s, std::uint32_t t, ProblemList& out) {
  const DomainSegment& a = d.segments[s];
  const DomainSegment& b = d.segments[t];
  const Point2 &a0 = d.points[a.a], &a1 = d.points[a.b], &b0 = d.points[b.a], &b1 = d.points[b.b];
  const Sign o_b0 = predicates::orient2d(a0, a1, b0), o_b1 = predicates::orient2d(a0, a1, b1);
  const Sign o_a0 = predicates::orient2d(b0, b1, a0), o_a1 = predicates::orient2d(b0, b1, a1);
  if (o_b0 == Sign::zero && o_b1 == Sign::zero) {
    classify_collinear(d, s, t, out);
    return;
  }
  bool junction = false;
  auto vertex_inside = [&](Sign o, DomainVertex v, std::uint32_t owner, std::uint32_t host) {
    const DomainSegment& h = d.segments[host];
    if (o != Sign::zero || !strictly_inside_collinear(d.points[v], d.points[h.a], d.points[h.b])) return;
    junction = true;
    out.add(DomainProblemKind::vertex_on_segment, {host, owner}, {v},
            "vertex " + std::to_string(v) + " " + point_text(d.points[v]) + " of segment " +
                std::to_string(owner) + " lies inside segment " + segment_text(d, host));
  };
  vertex_inside(o_b0, b.a, t, s);
  vertex_inside(o_b1, b.b, t, s);
  vertex_inside(o_a0, a.a, s, t);
  vertex_inside(o_a1, a.b, s, t);
  if (junction) return;
  if (a0 == b0 || a0 == b1 || a1 == b0 || a1 == b1) return;  // duplicate vertices, reported
  out.add(DomainProblemKind::segments_cross, {s, t}, {}, pair_text(d, s, t) + " cross");
}

void classify_pair(const PlanarDomain& d, std::uint32_t s, std::uint32_t t, ProblemList& out) {
  const DomainSegment& a = d.segments[s];
  const DomainSegment& b = d.segments[t];
  const std::array<predicates::Vertex2, 2> sa{{{d.points[a.a], a.a}, {d.points[a.b], a.b}}};
  const std::array<predicates::Vertex2, 2> sb{{{d.points[b.a], b.a}, {d.points[b.b], b.b}}};
  if (predicates::segment_segment_2d(sa, sb, predicates::IntersectionMode::exact) ==
      predicates::Overlap::disjoint) {
    return;
  }
  const bool same_pair = std::minmax(a.a, a.b) == std::minmax(b.a, b.b);
  if (same_pair) return;  // a duplicate segment, reported
  if (a.a == b.a) return classify_with_shared_vertex(d, s, t, a.a, a.b, b.b, out);
  if (a.a == b.b) return classify_with_shared_vertex(d, s, t, a.a, a.b, b.a, out);
  if (a.b == b.a) return classify_with_shared_vertex(d, s, t, a.b, a.a, b.b, out);
  if (a.b == b.b) return classify_with_shared_vertex(d, s, t, a.b, a.a, b.a, out);
  classify_disjoint_ids(d, s, t, out);
}

std::vector<SegmentBox> usable_segment_boxes(const PlanarDomain& d) {
  std::vector<SegmentBox> boxes;
  boxes.reserve(d.segments.size());
  for (std::uint32_t s = 0; s < d.segments.size(); ++s) {
    const DomainSegment& seg = d.segments[s];
    if (!ends_in_range(d, seg) || seg.a == seg.b) continue;
    const Point2& p = d.points[seg.a];
    const Point2& q = d.points[seg.b];
    if (!is_finite(p) || !is_finite(q) || p == q) continue;
    boxes.push_back({std::min(p.x, q.x), std::max(p.x, q.x), std::min(p.y, q.y), std::max(p.y, q.y), s});
  }
  const std::vector<bool> used = on_some_segment(d);
  for (std::uint32_t v = 0; v < d.points.size(); ++v) {
    const Point2& p = d.points[v];
    if (!used[v] && is_finite(p)) boxes.push_back({p.x, p.x, p.y, p.y, kIsolated, v});
  }
  return boxes;
}

// An isolated vertex strictly inside a segment would be a T-junction: refused as one. (At a
// segment's end it has the coordinates of another vertex: a duplicate, reported.)
void classify_isolated(const PlanarDomain& d, std::uint32_t s, DomainVertex v, ProblemList& out) {
  const DomainSegment& seg = d.segments[s];
  const Point2& p = d.points[v];
  if (predicates::orient2d(d.points[seg.a], d.points[seg.b], p) != Sign::zero) return;
  if (!strictly_inside_collinear(p, d.points[seg.a], d.points[seg.b])) return;
  out.add(DomainProblemKind::vertex_on_segment, {s}, {v},
          "vertex " + std::to_string(v) + " " + point_text(p) + ", on no segment, lies inside segment " +
              segment_text(d, s));
}

void classify_boxes(const PlanarDomain& d, const SegmentBox& p, const SegmentBox& q, ProblemList& out) {
  if (p.segment == kIsolated && q.segment == kIsolated) return;  // two points: duplicates, reported
  if (p.segment == kIsolated) return classify_isolated(d, q.segment, p.vertex, out);
  if (q.segment == kIsolated) return classify_isolated(d, p.segment, q.vertex, out);
  classify_pair(d, std::min(p.segment, q.segment), std::max(p.segment, q.segment), out);
}

// Sweep along x over boxes sorted by xmin: every pair whose closed boxes meet is examined once.
void check_segment_pairs(const PlanarDomain& d, ProblemList& out) {
  std::vector<SegmentBox> boxes = usable_segment_boxes(d);
  std::sort(boxes.begin(), boxes.end(), [](const SegmentBox& p, const SegmentBox& q) {
    return std::tie(p.xmin, p.segment, p.vertex) < std::tie(q.xmin, q.segment, q.vertex);
  });
  for (std::size_t i = 0; i < boxes.size() && !out.full(); ++i) {
    const SegmentBox& bi = boxes[i];
    for (std::size_t j = i + 1; j < boxes.size() && boxes[j].xmin <= bi.xmax && !out.full(); ++j) {
      const SegmentBox& bj = boxes[j];
      if (bj.ymin > bi.ymax || bi.ymin > bj.ymax) continue;
      classify_boxes(d, bi, bj, out);
    }
  }
}

}  // namespace

std::vector<DomainProblem> validate_domain(const PlanarDomain& domain, std::size_t max_problems) {
  ProblemList out(max_problems);
  check_non_finite(domain, out);
  check_indices(domain, out);
  check_zero_length(domain, out);
  check_duplicate_vertices(domain, out);
  check_duplicate_segments(domain, out);
  check_segment_pairs(domain, out);
  return out.take();
}

}  // namespace certimesh::generators
