// The 2D plane sweep (sweep_2d.h). Events in lexicographic (y, x) order: at each point, the
// segments ending there leave the status, those starting there enter it, then the queries
// there are answered. The status is a red-black tree (GNU pb_ds) ordered left to right along
// the sweep line. The signed crossings of a leftward ray (weights +1 for a segment oriented
// downward, -1 upward, 0 horizontal) are a prefix sum over the status; instead of keeping
// subtree sums in the tree (their update, every ancestor of every inserted or erased node,
// was half of the sweep), each segment records once, when its entering event is complete,
// the prefix sum up to and including itself (`right_of`): its left neighbour's record plus
// its own weight. For a closed set of segments (every vertex entered as often as left, as the
// mesh boundary is from condition 4) that record stays the prefix sum for every later query
// point right of the segment until it leaves: a vertex event left of it changes the sum only
// where horizontal segments there leave and enter unevenly, and over a connected run of
// horizontal segments (all on one line left of it, processed one after the other, with only
// points on the run in between) those changes cancel. So the answer for a query is its left
// neighbour's record. For a set that is not closed (the domain's segments may dangle) the
// winding is not meaningful; only `left_facet` and `on_facet` are read there.
//
// Why the order is consistent: until the first contact, the segments in the status are
// pairwise disjoint apart from shared endpoints, and two such segments that both cross the
// sweep line keep their left-to-right order; the order is decided at the later lower endpoint
// (orient2d of that point against the other segment, then of the upper endpoint when the two
// start at the same point). A contact that the comparison itself sees (a lower endpoint on
// another segment, two segments from one point along one line) is recorded at once; every
// other contact makes its two segments neighbours before the sweep passes it.
#include "sweep_2d.h"

#include <ext/pb_ds/assoc_container.hpp>
#include <ext/pb_ds/tree_policy.hpp>

#include <algorithm>
#include <utility>

#include "certimesh/predicates/orient2d.h"
#include "stages.h"

namespace certimesh::certificate::detail {
namespace {

using predicates::Point2;
using predicates::Sign;

bool lex_less(const Point2& a, const Point2& b) { return sweep_less(a, b); }

struct Segment {
  Point2 lo, hi;  // lexicographically lower and upper end
  int weight;     // leftward-ray crossing sign of the oriented segment
};

struct SweepKey {  // the segment itself, not only its index: a comparison touches no other memory
  std::uint32_t segment;
  int weight;
  Segment s;
};

// The comparison needs the segments and a place to record a contact it notices.
struct Context {
  const std::vector<Segment>* segments = nullptr;
  std::int64_t contact_a = -1, contact_b = -1;
  bool query = false;  // comparing the query point (segment index UINT32_MAX) with segments
  Point2 point{0, 0};
};

// Whether a point is left of segment f along the sweep line through it (f spans that line):
// +1 left, -1 right, 0 on f's line (the point is then on f, f spanning the sweep there).
// An end of f itself is decided without the predicate (its filter cannot certify a zero, so the
// exact stage would run): the common case at shared endpoints.
[[gnu::always_inline]] inline Sign sweep_side(const Segment& f, const Point2& p) {  // in the tree's comparisons: keep it inlined
  if (p == f.lo || p == f.hi) return Sign::zero;
  return predicates::orient2d(f.lo, f.hi, p);
}

struct LeftOf {
  Context* context = nullptr;
  bool operator()(const SweepKey& a, const SweepKey& b) const {
    if (a.segment == b.segment) return false;
    if (a.segment == UINT32_MAX) return point_left_of(b);
    if (b.segment == UINT32_MAX) return !point_left_of(a);
    const Segment& e = a.s;
    const Segment& f = b.s;
    // Decide at the later lower end: it lies on the sweep line where both cross it.
    const bool e_later = !lex_less(e.lo, f.lo);
    const Segment& later = e_later ? e : f;
    const Segment& other = e_later ? f : e;
    const bool same_start = later.lo == other.lo;
    Sign s = sweep_side(other, later.lo);
    if (s == Sign::zero) {
      if (!same_start) note(a.segment, b.segment);  // a lower end inside the other
      s = sweep_side(other, later.hi);
      if (s == Sign::zero) note(a.segment, b.segment), s = a.segment < b.segment ? Sign::positive : Sign::negative;
    }
    return (s == Sign::positive) == e_later;  // the later one is left of the other
  }
  bool point_left_of(const SweepKey& k) const {
    const Segment& f = k.s;
    const Sign s = sweep_side(f, context->point);
    return s != Sign::negative;  // on f: at its lower end (or inside it), a point just left of it
  }
  void note(std::uint32_t a, std::uint32_t b) const {
    if (context->contact_a < 0) context->contact_a = a, context->contact_b = b;
  }
};

using SweepStatus = __gnu_pbds::tree<SweepKey, __gnu_pbds::null_type, LeftOf, __gnu_pbds::rb_tree_tag, __gnu_pbds::null_node_update>;

class Sweep {
 public:
  Sweep(const MeshView& m, const FacetSet& set, const std::vector<Index>* vertex_order)
      : m_(m), set_(set), vertex_order_(vertex_order), status_(LeftOf{&context_}) {
    context_.segments = &segments_;
    segments_.reserve(set.size());
    for (std::size_t f = 0; f < set.size(); ++f) {
      const Index u = set.facet(f)[0], w = set.facet(f)[1];
      const Point2 a = m.p2(u), b = m.p2(w);
      const int weight = a.y > b.y ? 1 : (a.y < b.y ? -1 : 0);
      segments_.push_back(lex_less(a, b) ? Segment{a, b, weight} : Segment{b, a, weight});
    }
  }

  // The first contact, as (segment, segment), or (-1, -1); answers the queries on the way.
  // The events are the segments' endpoints in sweep order: the endpoints sorted once, each
  // with its segments ending and starting there (a counting sort), and the queries merged in.
  std::pair<std::int64_t, std::int64_t> run(const std::vector<std::array<double, 2>>& queries, std::vector<SweepAnswer>& answers) {
    const EndpointEvents events = endpoint_events();
    std::vector<std::uint32_t> by_point(queries.size());
    for (std::uint32_t q = 0; q < queries.size(); ++q) by_point[q] = q;
    auto query_at = [&](std::uint32_t q) { return Point2{queries[q][0], queries[q][1]}; };
    std::sort(by_point.begin(), by_point.end(), [&](std::uint32_t a, std::uint32_t b) {
      return query_at(a) == query_at(b) ? a < b : lex_less(query_at(a), query_at(b));
    });
    answers.assign(queries.size(), {});
    where_.assign(segments_.size(), status_.end());
    right_of_.assign(segments_.size(), 0);
    fresh_.assign(segments_.size(), 0);
    std::size_t next_query = 0;
    auto answer_until = [&](auto&& before_or_at) {
      for (; next_query < by_point.size() && before_or_at(query_at(by_point[next_query])); ++next_query)
        answers[by_point[next_query]] = answer(query_at(by_point[next_query]));
    };
    for (std::size_t i = 0, j = 0; i < events.order.size(); i = j) {
      const Point2 here = m_.p2(events.order[i]);
      while (j < events.order.size() && m_.p2(events.order[j]) == here) ++j;  // one point, maybe several ids
      answer_until([&](const Point2& q) { return lex_less(q, here); });
      if (j == i + 1 && pass_through(events.at(0, events.order[i]), events.at(1, events.order[i]))) {
        if (found_a_ >= 0) return {found_a_, found_b_};
        answer_until([&](const Point2& q) { return q == here; });
        continue;
      }
      entered_.clear();
      for (int kind = 0; kind < 2; ++kind)  // at one point: the segments ending there leave, then those starting enter
        for (std::size_t k = i; k < j; ++k)
          for (std::uint32_t f : events.at(kind, events.order[k])) {
            kind == 0 ? leave(f) : enter(f);
            if (found_a_ >= 0) return {found_a_, found_b_};
            if (context_.contact_a >= 0) return {context_.contact_a, context_.contact_b};
          }
      record_entered();
      answer_until([&](const Point2& q) { return q == here; });
    }
    answer_until([](const Point2&) { return true; });
    return {found_a_, found_b_};
  }

 private:
  // The endpoints in sweep order, and of each its segments ending (kind 0) and starting
  // (kind 1) there, in segment order.
  struct EndpointEvents {
    std::vector<Index> order;
    std::vector<std::uint32_t> first[2], segment[2];  // per vertex id: segment[kind][first[kind][v] ..]
    struct Span {
      const std::uint32_t *first, *last;
      const std::uint32_t* begin() const { return first; }
      const std::uint32_t* end() const { return last; }
    };
    Span at(int kind, Index v) const { return {segment[kind].data() + first[kind][v], segment[kind].data() + first[kind][v + 1]}; }
  };
  EndpointEvents endpoint_events() const {
    EndpointEvents ev;
    const std::size_t n = m_.vertex_count;
    for (int kind = 0; kind < 2; ++kind) ev.first[kind].assign(n + 1, 0);
    std::vector<char> used(n, 0);
    auto end_of = [&](std::size_t f, int kind) {  // kind 0: the upper end (leave), 1: the lower (enter)
      const Index u = set_.facet(f)[0], w = set_.facet(f)[1];
      const bool u_lower = lex_less(m_.p2(u), m_.p2(w));
      return kind == 1 ? (u_lower ? u : w) : (u_lower ? w : u);
    };
    for (std::size_t f = 0; f < segments_.size(); ++f)
      for (int kind = 0; kind < 2; ++kind) {
        const Index v = end_of(f, kind);
        ++ev.first[kind][v + 1];
        if (!used[v]) used[v] = 1, ev.order.push_back(v);
      }
    for (int kind = 0; kind < 2; ++kind) {
      for (std::size_t v = 0; v < n; ++v) ev.first[kind][v + 1] += ev.first[kind][v];
      ev.segment[kind].resize(segments_.size());
      std::vector<std::uint32_t> fill(ev.first[kind].begin(), ev.first[kind].end() - 1);
      for (std::size_t f = 0; f < segments_.size(); ++f) ev.segment[kind][fill[end_of(f, kind)]++] = static_cast<std::uint32_t>(f);
    }
    if (vertex_order_ != nullptr) {  // the endpoints in the given order: no sort
      ev.order.clear();
      for (Index v : *vertex_order_)
        if (used[v]) ev.order.push_back(v);
      return ev;
    }
    // Sorted as contiguous (y, x, id) keys: an index sort would read two points per comparison.
    struct SortKey {
      double y, x;
      Index id;
    };
    std::vector<SortKey> keys(ev.order.size());
    for (std::size_t i = 0; i < keys.size(); ++i) keys[i] = {m_.coord(ev.order[i], 1), m_.coord(ev.order[i], 0), ev.order[i]};
    std::sort(keys.begin(), keys.end(), [](const SortKey& a, const SortKey& b) {
      return a.y != b.y ? a.y < b.y : (a.x != b.x ? a.x < b.x : a.id < b.id);
    });
    for (std::size_t i = 0; i < keys.size(); ++i) ev.order[i] = keys[i].id;
    return ev;
  }

  void test(SweepStatus::iterator a, SweepStatus::iterator b) {
    if (a == status_.end() || b == status_.end() || found_a_ >= 0) return;
    if (contact_of(m_, set_, a->segment, b->segment, Defect::t_junction, Defect::boundary_intersection, "").defect != Defect::none)
      found_a_ = a->segment, found_b_ = b->segment;
  }
  SweepStatus::iterator before(SweepStatus::iterator it) { return it == status_.begin() ? status_.end() : std::prev(it); }
  void enter(std::uint32_t f) {
    const auto it = status_.insert(SweepKey{f, segments_[f].weight, segments_[f]}).first;
    where_[f] = it;
    fresh_[f] = 1;
    entered_.push_back(f);
    test(before(it), it);
    test(it, std::next(it));
  }
  // Once a point's segments have all entered: the segments that entered there are neighbours
  // in the status (a segment between two of them would pass through the point: a contact,
  // found first), so each run of them takes its prefix sums from the record of the segment
  // left of the run, left to right. Each entered segment is visited once.
  void record_entered() {
    for (std::uint32_t f : entered_) {
      if (!fresh_[f]) continue;
      SweepStatus::iterator it = where_[f];
      while (it != status_.begin() && fresh_[std::prev(it)->segment]) --it;  // the run's first
      int sum = it == status_.begin() ? 0 : right_of_[std::prev(it)->segment];
      for (; it != status_.end() && fresh_[it->segment]; ++it) {
        sum += it->weight;
        right_of_[it->segment] = sum;
        fresh_[it->segment] = 0;
      }
    }
  }
  // At a vertex v where exactly one segment e ends and one f starts (a boundary chain passing
  // through v, the common case), f takes e's node: no tree search. The order stays right: every
  // other segment g in the status misses v (g ending or starting at v would be e or f) and,
  // there being no contact before v (the first contact is found before the sweep passes it),
  // lies on the side of v that it lies of e just before v, which is the side it lies of f just
  // after. A g through v's interior is a contact at v: the segments between g and e just before
  // v all pass through v (else a contact below v), so g's neighbour among them meets g at v,
  // and that pair was tested when it became adjacent. f is tested with its new neighbours, as
  // an insertion would, and records its prefix sum from its left neighbour's, as
  // record_entered does (the weights may differ: nothing else in the tree depends on them).
  template <class Span>
  bool pass_through(const Span& ending, const Span& starting) {
    if (ending.end() - ending.begin() != 1 || starting.end() - starting.begin() != 1) return false;
    const std::uint32_t e = *ending.begin(), f = *starting.begin();
    const SweepStatus::iterator it = where_[e];
    SweepKey& key = const_cast<SweepKey&>(*it);  // the node's own (non-const) value; the order is kept, as argued
    key.segment = f;
    key.weight = segments_[f].weight;
    key.s = segments_[f];
    where_[f] = it;
    where_[e] = status_.end();
    right_of_[f] = (it == status_.begin() ? 0 : right_of_[std::prev(it)->segment]) + key.weight;
    test(before(it), it);
    test(it, std::next(it));
    return true;
  }
  void leave(std::uint32_t f) {
    const SweepStatus::iterator it = where_[f];
    const SweepStatus::iterator left = before(it), right = std::next(it);
    status_.erase(it);
    test(left, right);
  }
  // One search: the first segment the point is left of or on; the one before it is the nearest
  // segment left of the point, and its record is the winding there. The point is on a segment
  // when one of those it is on (they follow each other) has it beyond its lower end.
  SweepAnswer answer(const Point2& q) {
    context_.point = q;
    SweepAnswer out;
    SweepStatus::iterator it = status_.lower_bound(SweepKey{UINT32_MAX, 0, {}});
    if (it != status_.begin()) {
      const SweepKey& left = *std::prev(it);
      out.left_facet = left.segment;
      out.winding = right_of_[left.segment];
    }
    for (; it != status_.end() && sweep_side(it->s, q) == Sign::zero; ++it)
      if (!(it->s.lo == q)) out.on_facet = true;
    return out;
  }

  const MeshView& m_;
  const FacetSet& set_;
  const std::vector<Index>* vertex_order_;  // every vertex in sweep order, or null
  std::vector<Segment> segments_;
  Context context_;
  SweepStatus status_;
  std::vector<SweepStatus::iterator> where_;
  std::vector<int> right_of_;                // per segment in the status: the prefix sum up to it
  std::vector<char> fresh_;                  // entered at the current point, not yet recorded
  std::vector<std::uint32_t> entered_;       // the segments that entered at the current point
  std::int64_t found_a_ = -1, found_b_ = -1;
};

}  // namespace

Finding sweep_2d(const MeshView& m, const FacetSet& set, Defect touching, Defect crossing, const std::string& what,
                 const std::vector<std::array<double, 2>>& queries, std::vector<SweepAnswer>& answers,
                 const std::vector<Index>* vertex_order) {
  Sweep sweep(m, set, vertex_order);
  const auto [a, b] = sweep.run(queries, answers);
  if (a < 0) return {};
  Finding f = contact_of(m, set, static_cast<std::size_t>(a), static_cast<std::size_t>(b), touching, crossing, what);
  if (f.defect == Defect::none)  // the comparison saw a lower end on the other's line: a contact all the same
    f = finding(touching, set.owner[static_cast<std::size_t>(a)], set.owner[static_cast<std::size_t>(b)], -1,
                what + "s " + std::to_string(a) + " and " + std::to_string(b) + " meet beyond their shared vertices");
  return f;
}

}  // namespace certimesh::certificate::detail
