// The sweep of segments_near_points_2d.h. The sweep line is y = const, moving up; the status
// holds the non-horizontal segments that cross it, left to right, in a balanced tree whose
// order is decided once, at the later lower end of two segments (as in sweep_2d.cpp), and stays
// right while they do not cross. At each height, in this order: the points there search the
// lower half-band (status: lower end below, upper end at or above), the segments ending there
// leave, those starting there enter, and the points search the upper half-band (lower end at or
// below, upper end above). Every sign is exact (orient2d).
#include "segments_near_points_2d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

#include "certimesh/predicates/orient2d.h"
#include "next_double.h"
#include "sweep_2d.h"

namespace certimesh::certificate::detail {
namespace {

using predicates::Point2;
using predicates::Sign;

struct Span {  // a non-horizontal segment, lower end first
  Point2 lo, hi;
  std::uint32_t id;
};

// +1 when p is left of f (f directed upward), -1 right, 0 on its line; f's own ends are 0
// without the predicate.
Sign span_side(const Span& f, const Point2& p) {
  if (p == f.lo || p == f.hi) return Sign::zero;
  return predicates::orient2d(f.lo, f.hi, p);
}

struct LeftToRight {
  using is_transparent = void;
  bool operator()(const Span& e, const Span& f) const {
    if (e.id == f.id) return false;
    const bool e_later = !sweep_less(e.lo, f.lo);  // decide at the later lower end
    const Span& later = e_later ? e : f;
    const Span& other = e_later ? f : e;
    Sign s = span_side(other, later.lo);
    if (s == Sign::zero) s = span_side(other, later.hi);  // the same lower end: the upper ends decide
    if (s == Sign::zero) return e.id < f.id;         // collinear overlap: not in a valid domain
    return (s == Sign::positive) == e_later;
  }
  bool operator()(const Span& f, const Point2& p) const { return span_side(f, p) == Sign::negative; }
  bool operator()(const Point2& p, const Span& f) const { return span_side(f, p) != Sign::negative; }
};

using SpanStatus = std::set<Span, LeftToRight>;

double toward(double x, double direction) {
  const double y = next_double(x, direction > 0 ? 1 : -1);
  return std::isfinite(y) ? y : x;  // the rounding box ends at x there
}

// Whether f's line lies strictly on side `want` of both points (f spans their heights).
bool strictly_beyond(const Span& f, const Point2& c1, const Point2& c2, Sign want) {
  return span_side(f, c1) == want && span_side(f, c2) == want;
}

class NearSweep {
 public:
  NearSweep(const std::vector<Segment2>& segments, const std::vector<Point2>& points) : points_(points) {
    for (std::uint32_t s = 0; s < segments.size(); ++s) {
      const Segment2& g = segments[s];
      if (g.a.y == g.b.y) {
        horizontals_.push_back({g.a.y, std::min(g.a.x, g.b.x), std::max(g.a.x, g.b.x), s});
      } else {
        spans_.push_back(sweep_less(g.a, g.b) ? Span{g.a, g.b, s} : Span{g.b, g.a, s});
      }
    }
    std::sort(horizontals_.begin(), horizontals_.end());
  }

  std::vector<std::pair<std::uint32_t, std::uint32_t>> run() {
    // Events by height; at one height: lower searches, removals, insertions, upper searches.
    enum Kind : std::uint8_t { search_lower, remove, insert, search_upper };
    struct Event {
      double y;
      Kind kind;
      std::uint32_t index;
    };
    std::vector<Event> events;
    events.reserve(2 * spans_.size() + 2 * points_.size());
    for (std::uint32_t i = 0; i < spans_.size(); ++i) events.push_back({spans_[i].lo.y, insert, i}), events.push_back({spans_[i].hi.y, remove, i});
    for (std::uint32_t q = 0; q < points_.size(); ++q) events.push_back({points_[q].y, search_lower, q}), events.push_back({points_[q].y, search_upper, q});
    std::sort(events.begin(), events.end(), [](const Event& a, const Event& b) {
      return a.y != b.y ? a.y < b.y : (a.kind != b.kind ? a.kind < b.kind : a.index < b.index);
    });
    out_.clear();
    std::vector<SpanStatus::iterator> where(spans_.size(), status_.end());
    // A point's two searches start from the same place when no segment ends or starts at its
    // height (the common case: a Steiner point between a segment's ends): one tree search.
    std::vector<SpanStatus::iterator> found(points_.size(), status_.end());
    std::vector<std::uint64_t> found_at(points_.size(), 0);
    std::uint64_t changes = 1;  // status modifications so far; 0 marks "not searched"
    for (const Event& e : events) {
      if (e.kind == insert) where[e.index] = status_.insert(spans_[e.index]).first, ++changes;
      else if (e.kind == remove) status_.erase(where[e.index]), ++changes;
      else {
        const bool same = e.kind == search_upper && found_at[e.index] == changes;
        const SpanStatus::iterator first = same ? found[e.index] : status_.lower_bound(points_[e.index]);
        found[e.index] = first, found_at[e.index] = changes;
        search(e.index, e.kind == search_upper, first);
      }
    }
    for (std::uint32_t q = 0; q < points_.size(); ++q) horizontal_candidates(q);
    std::sort(out_.begin(), out_.end());  // by point, then segment; a segment of both halves once
    out_.erase(std::unique(out_.begin(), out_.end()), out_.end());
    return std::move(out_);
  }

 private:
  struct Horizontal {
    double y, lo, hi;
    std::uint32_t id;
    bool operator<(const Horizontal& o) const { return y != o.y ? y < o.y : lo < o.lo; }
  };

  // Walks out from p in the status over the half-band [y0, y1] (p.y is one end), collecting
  // segments until one lies strictly beyond p's box of neighbouring doubles across it.
  // `first`: the first segment with p left of or on it (status_.lower_bound(p)).
  void search(std::uint32_t q, bool upper, SpanStatus::iterator first) {
    const Point2 p = points_[q];
    const double inf = std::numeric_limits<double>::infinity();
    const double y0 = upper ? p.y : toward(p.y, -inf), y1 = upper ? toward(p.y, inf) : p.y;
    const double left = toward(p.x, -inf), right = toward(p.x, inf);
    for (auto it = first; it != status_.end(); ++it) {
      if (strictly_beyond(*it, {right, y0}, {right, y1}, Sign::positive)) break;
      out_.push_back({q, it->id});
    }
    for (auto it = first; it != status_.begin();) {
      --it;
      if (strictly_beyond(*it, {left, y0}, {left, y1}, Sign::negative)) break;
      out_.push_back({q, it->id});
    }
  }

  // Horizontal segments at height p.y whose x-range holds p.x: they are disjoint but for
  // shared ends, so the last two starting at or left of p.x are the only ones that can.
  void horizontal_candidates(std::uint32_t q) {
    const Point2 p = points_[q];
    auto it = std::upper_bound(horizontals_.begin(), horizontals_.end(), Horizontal{p.y, p.x, p.x, 0});
    for (int k = 0; k < 2 && it != horizontals_.begin(); ++k) {
      --it;
      if (it->y != p.y) break;
      if (it->hi >= p.x) out_.push_back({q, it->id});
    }
  }

  const std::vector<Point2>& points_;
  std::vector<Span> spans_;
  std::vector<Horizontal> horizontals_;
  SpanStatus status_;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out_;  // (point, segment)
};

}  // namespace

std::vector<std::pair<std::uint32_t, std::uint32_t>> segments_near_points_2d(const std::vector<Segment2>& segments,
                                                                             const std::vector<Point2>& points) {
  return NearSweep(segments, points).run();
}

}  // namespace certimesh::certificate::detail
