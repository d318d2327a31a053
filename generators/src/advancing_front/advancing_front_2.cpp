// Algorithm 10 (digest B §3.2): one outer step per triangle, the shortest front edge first --
// among the input front's edges while any is left, then among the grown ones (kInputRank).
//
// Candidate order (the listing leaves it open, digest B §3.2 [CAVEAT]), in three groups:
//   0. front vertices on the left of e12 within 0.7 s of the ideal apex v0, nearest first,
//      except a front neighbour of v1 or v2 across a corner wider than 82 degrees;
//   1. v0 itself, when the h and r radii allow it;
//   2. the other front vertices in the search box, best triangle shape first.
// Why: a front vertex near v0 is where the front wants to close; inserting v0 beside it
// (the book's r = s/2 still allows a new node at 0.5 s) leaves a short edge and a thin
// triangle for a later step. Measured on the unit square (h = 0.005): ordering every
// candidate by its shape with v0 in the same list gave a worst quality of 0.00-0.46 (an
// early good triangle leaves slivers where fronts meet); these groups give 0.59-0.62 with a
// mean of 0.998. With the boundary advanced first and bisector apexes at front corners
// (corner_apex), 0.7 s does better than 0.8 s (a vertex at 0.73 s from v0 is the neighbour
// row's apex near a corner: taking it squeezes the first layer). Ties: the smaller vertex
// id. Ordering decides nothing about validity: each candidate must still pass the sign tests.
//
// Local search: Ω is the axis-aligned box of half-width R = 1.25 max(s, r, |v0 v1|, |v0 v2|)
// around v0 (a convex neighbourhood of v1, v2 and v0, as §3.3 needs; membership is decided by
// exact coordinate comparisons, and the R-tree of front_grid_2.h returns a superset of the
// edges meeting it). When
// it finds nothing, the global retry repeats the step over the whole front with exact
// predicates, where Lemma 3.3.1 guarantees a suitable triangle.
#include "certimesh/generators/advancing_front/advancing_front_2.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "certimesh/predicates/intersection/triangle_segment_2d.h"
#include "certimesh/predicates/orient2d.h"
#include "front_2.h"
#include "front_grid_2.h"
#include "front_measure_2.h"
#include "front_sizing_2.h"

namespace certimesh::generators {
namespace {

using namespace advancing_front_detail;
using predicates::IntersectionMode;

constexpr double kSearchRadiusFactor = 1.25;  // R = 1.25 max(s, r): inside the book's (s, 2s]
constexpr double kNearRadius = 0.7;  // group 0 of the candidate order, in units of s
// Front corners split by a bisector apex (corner_apex): from the angle where one closing
// triangle and two half-angle ones have equal quality (about 82 degrees) to where the
// isosceles apex does as well (150).
constexpr double kCosMinBisectedAngle = 0.13917310096006544;   // cos 82 degrees
constexpr double kCosMaxBisectedAngle = -0.86602540378443865;  // cos 150 degrees
constexpr double kCosFlatCorner = -0.99999998;                 // cos 179.989 degrees (flat_corner)
// The input front (the boundary) is advanced first, its shortest edge first, then the rest
// shortest first: the first layer then follows the boundary all along it, instead of being
// squeezed where the layers grown from a neighbouring side arrive first (they left right
// triangles against fixed boundary vertices that no later smoothing could repair).
constexpr std::uint32_t kInputRank = 0;
constexpr std::uint32_t kGrownRank = 1;

double squared_distance_2(const Point2& p, const Point2& q) {
  const double dx = p.x - q.x, dy = p.y - q.y;
  return dx * dx + dy * dy;
}

/// Approximate squared distance from p to the segment ab (it steers spacing only).
double squared_distance_to_segment(const Point2& p, const Point2& a, const Point2& b) {
  const double ux = b.x - a.x, uy = b.y - a.y;
  const double length2 = ux * ux + uy * uy;
  double t = length2 > 0.0 ? ((p.x - a.x) * ux + (p.y - a.y) * uy) / length2 : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return squared_distance_2(p, Point2{a.x + t * ux, a.y + t * uy});
}

/// Shape quality 12√3 S / P² (approximate: it only orders candidates).
double triangle_shape_quality(const Point2& a, const Point2& b, const Point2& c) {
  const double twice_area = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  const double perimeter = std::sqrt(squared_distance_2(a, b)) + std::sqrt(squared_distance_2(b, c)) +
                           std::sqrt(squared_distance_2(c, a));
  return 6.0 * 1.73205080756887729353 * twice_area / (perimeter * perimeter);
}

bool boxes_apart(const Point2& a, const Point2& b, const Point2& c, const Point2& p, const Point2& q) {
  return std::max({a.x, b.x, c.x}) < std::min(p.x, q.x) || std::max(p.x, q.x) < std::min({a.x, b.x, c.x}) ||
         std::max({a.y, b.y, c.y}) < std::min(p.y, q.y) || std::max(p.y, q.y) < std::min({a.y, b.y, c.y});
}

struct Candidate {
  std::uint32_t vertex;  // the apex has the id it would get
  int group;             // tried in increasing group order
  double score;          // then in decreasing score
};

bool better(const Candidate& x, const Candidate& y) {
  if (x.group != y.group) return x.group < y.group;
  if (x.score != y.score) return x.score > y.score;
  return x.vertex < y.vertex;
}

/// The step in progress: e12, its apex and sizes.
struct Step {
  std::uint32_t edge, v1, v2, apex_id;
  Point2 p1, p2, apex;
  ApexSize size;
};

class AdvancingFront {
 public:
  AdvancingFront(std::span<const Point2> points, std::span<const FrontEdge> front,
                 const AdvancingFrontOptions& options, const ProgressCallback& progress)
      : measure_(measure_front(points, front)),
        sizing_(options.size, measure_.least_distance),
        user_cap_(options.max_triangles),
        retry_cap_(options.max_global_retries),
        retry_work_cap_(options.max_global_retry_work),
        progress_(progress) {
    result_.points.assign(points.begin(), points.end());
    for (const FrontEdge& e : front) sizing_.at(edge_length(e.a, e.b), midpoint(e.a, e.b));
    update_bound();
    const std::size_t reserve = static_cast<std::size_t>(std::min<std::uint64_t>(limit_ / 3 + 16, 1u << 22));
    result_.points.reserve(points.size() + reserve / 2);
    result_.triangles.reserve(reserve);
    front_.reserve(points.size() + reserve / 2, 2 * front.size() + 1024);  // slots are reused: the front, not the mesh
    grow_vertices();
    for (const FrontEdge& e : front) insert_edge(e.a, e.b, kInputRank);
  }

  AdvancingFrontResult run() {
    const std::uint64_t report_every = std::max<std::uint64_t>(limit_ / 100, 1);
    for (std::uint32_t e = front_.shortest(); e != no_id; e = front_.shortest()) {
      if (triangles() >= limit_) {
        assert(user_cap_ != 0 && user_cap_ <= triangles() && "the (3.3.4) bound was reached");
        break;
      }
      if (result_.points.size() >= no_id - 1) break;  // vertex ids are 32-bit: return the rest
      if (!advance(e)) break;  // impossible with exact signs (Lemma 3.3.1); the rest is returned
      if (triangles() % report_every == 0) report(progress_, "advancing front", triangles(), limit_);
    }
    return finish();
  }

 private:
  std::uint64_t triangles() const { return result_.triangles.size(); }
  const Point2& point(std::uint32_t v) const { return result_.points[v]; }
  double edge_length(std::uint32_t a, std::uint32_t b) const {
    return std::sqrt(squared_distance_2(point(a), point(b)));
  }
  Point2 midpoint(std::uint32_t a, std::uint32_t b) const {
    return Point2{0.5 * (point(a).x + point(b).x), 0.5 * (point(a).y + point(b).y)};
  }

  void update_bound() {
    bound_ = triangle_bound(measure_, sizing_.delta());
    limit_ = user_cap_ != 0 ? std::min(bound_, user_cap_) : bound_;
  }

  void grow_vertices() {
    front_.grow_vertices(result_.points.size());
    vertex_stamp_.resize(result_.points.size(), 0);
  }

  // `rank`: kInputRank for the input front, kGrownRank for the edges the front grows.
  void insert_edge(std::uint32_t a, std::uint32_t b, std::uint32_t rank) {
    const std::uint32_t e = front_.insert(a, b, rank, squared_distance_2(point(a), point(b)));
    grid_.insert(e, point(a), point(b));
    if (e >= edge_stamp_.size()) edge_stamp_.push_back(0);
  }

  void erase_edge(std::uint32_t e) {
    grid_.erase(e, point(front_.edge(e).a), point(front_.edge(e).b));
    front_.erase(e);
  }

  Step make_step(std::uint32_t e) {
    Step st{};
    st.edge = e;
    st.v1 = front_.edge(e).a;
    st.v2 = front_.edge(e).b;
    st.p1 = point(st.v1);
    st.p2 = point(st.v2);
    const double l = edge_length(st.v1, st.v2);
    const Point2 mid = midpoint(st.v1, st.v2);
    st.size = sizing_.at(l, mid);
    if (sizing_.take_delta_change()) update_bound();
    const double height = 2.0 * st.size.h;  // hc
    st.apex = Point2{mid.x - (st.p2.y - st.p1.y) / l * height, mid.y + (st.p2.x - st.p1.x) / l * height};
    st.apex_id = static_cast<std::uint32_t>(result_.points.size());
    corner_apex(st);
    return st;
  }

  // The only other front edge at v (out of v when `out`, else into v), or no_id when v has
  // several (a pinch vertex).
  std::uint32_t single_neighbour(std::uint32_t v, bool out) const {
    const std::uint32_t e = out ? front_.first_out(v) : front_.first_in(v);
    if (e == no_id) return no_id;
    const Front2::Edge& edge = front_.edge(e);
    if ((out ? edge.next_out : edge.next_in) != no_id) return no_id;
    return out ? edge.b : edge.a;
  }

  // At a convex front corner of v1 or v2 whose angle lies between kMinBisectedAngle and
  // kMaxBisectedAngle (the sharper one when both do), the ideal apex goes on the corner's
  // bisector at distance s: the corner is split into two triangles of half its angle. At the
  // right angle of a square's corner this gives two triangles of quality 0.96, where the
  // isosceles apex gives an equilateral triangle and a 30-degree one beside it that the
  // smoothing cannot repair (the corner is fixed). In the lattice of a uniform front (angles
  // of 120 degrees) the bisector point is the isosceles apex itself. Geometry only steers:
  // the apex still passes every test.
  void corner_apex(Step& st) const {
    struct Corner {
      double cosine = -2.0;  // below every angle's: no corner
      Point2 apex;
    };
    const auto corner_at = [&](const Point2& corner, const Point2& along, std::uint32_t other) {
      Corner c;
      if (other == no_id) return c;
      const Point2& q = point(other);
      if (orientation(st.p1, st.p2, q, false) <= 0) return c;  // not convex (or not certainly)
      const double ux = along.x - corner.x, uy = along.y - corner.y, wx = q.x - corner.x, wy = q.y - corner.y;
      const double lu = std::sqrt(ux * ux + uy * uy), lw = std::sqrt(wx * wx + wy * wy);
      const double cosine = (ux * wx + uy * wy) / (lu * lw);
      if (!(cosine <= kCosMinBisectedAngle && cosine >= kCosMaxBisectedAngle)) return c;
      const double bx = ux / lu + wx / lw, by = uy / lu + wy / lw, lb = std::sqrt(bx * bx + by * by);
      return Corner{cosine, Point2{corner.x + st.size.s * bx / lb, corner.y + st.size.s * by / lb}};
    };
    const Corner at2 = corner_at(st.p2, st.p1, single_neighbour(st.v2, true));
    const Corner at1 = corner_at(st.p1, st.p2, single_neighbour(st.v1, false));
    const Corner& sharper = at1.cosine > at2.cosine ? at1 : at2;
    if (sharper.cosine > -2.0) st.apex = sharper.apex;
  }

  bool advance(std::uint32_t e) {
    const Step st = make_step(e);
    if (search(st, false)) return true;
    if (retry_cap_ != 0 && result_.stats.global_retries >= retry_cap_) return false;  // the rest is returned
    if (retry_work_cap_ != 0 && retry_work_ + front_.live_count() > retry_work_cap_) return false;
    ++result_.stats.global_retries;
    retry_work_ += front_.live_count();
    return search(st, true);
  }

  // Gathers the local front (every edge of the whole front when global) and the front
  // vertices in the box, deduplicated by stamps.
  bool gather(const Step& st, bool global, Box2& box) {
    // A corner apex (corner_apex) may stand farther than s from v1 or v2: the box grows to
    // keep both inside.
    const double reach = std::sqrt(std::max(squared_distance_2(st.apex, st.p1), squared_distance_2(st.apex, st.p2)));
    const double radius = kSearchRadiusFactor * std::max({st.size.s, st.size.r, reach});
    box = Box2{st.apex.x - radius, st.apex.y - radius, st.apex.x + radius, st.apex.y + radius};
    if (!global && !(box.contains(st.p1) && box.contains(st.p2))) return false;
    ++stamp_;
    local_edges_.clear();
    nearby_.clear();
    const auto take = [&](std::uint32_t e) {
      if (edge_stamp_[e] == stamp_) return;
      edge_stamp_[e] = stamp_;
      local_edges_.push_back(e);
      const std::uint32_t a = front_.edge(e).a;
      if (vertex_stamp_[a] == stamp_) return;
      vertex_stamp_[a] = stamp_;
      if (global || box.contains(point(a))) nearby_.push_back(a);
    };
    if (global) {
      for (std::uint32_t e = 0; e < front_.slot_count(); ++e)
        if (front_.edge(e).alive) take(e);
    } else {
      grid_.for_each_edge_near(box, take);
    }
    return true;
  }

  int orientation(const Point2& a, const Point2& b, const Point2& c, bool exact) const {
    return exact ? predicates::to_int(predicates::orient2d(a, b, c))
                 : predicates::to_int(predicates::orient2d_filtered(a, b, c));
  }

  // Step 9: v0 is a candidate when no front vertex is within r and the front misses the
  // h-disc (distances approximate: they steer spacing, not validity).
  bool apex_allowed(const Step& st, bool exact) const {
    const double r2 = st.size.r * st.size.r, h2 = st.size.h * st.size.h;
    for (const std::uint32_t v : nearby_)
      if (squared_distance_2(point(v), st.apex) < r2) return false;
    for (const std::uint32_t e : local_edges_)
      if (squared_distance_to_segment(st.apex, point(front_.edge(e).a), point(front_.edge(e).b)) < h2)
        return false;
    return orientation(st.p1, st.p2, st.apex, exact) > 0;
  }

  // Whether v is a front neighbour of v1 or v2 at a front angle too wide to close with one
  // triangle (above kMinBisectedAngle): closing a right angle makes a triangle of quality
  // 0.89 at best, the bisector apex two of 0.96 (corner_apex).
  bool wide_corner(const Step& st, std::uint32_t v) const { return corner_cosine_below(st, v, kCosMinBisectedAngle); }

  // Whether v is a front neighbour of v2 (edge v2 -> v) or of v1 (edge v -> v1) and the front
  // corner there has a cosine below `cosine`.
  bool corner_cosine_below(const Step& st, std::uint32_t v, double cosine) const {
    const auto cos_at = [&](const Point2& o, const Point2& p, const Point2& q) {
      const double ux = p.x - o.x, uy = p.y - o.y, wx = q.x - o.x, wy = q.y - o.y;
      return (ux * wx + uy * wy) / std::sqrt((ux * ux + uy * uy) * (wx * wx + wy * wy));
    };
    if (front_.find(st.v2, v) != no_id && cos_at(st.p2, st.p1, point(v)) < cosine) return true;
    return front_.find(v, st.v1) != no_id && cos_at(st.p1, st.p2, point(v)) < cosine;
  }

  // Whether v is a front neighbour of v1 or v2 across a corner within about 0.01 degree of a
  // straight angle. Closing such a corner makes a triangle whose third side runs along the two
  // front edges: on a discretized boundary segment the Steiner points are roundings of points
  // of the segment (design decision 2), the middle one a hair inside, and that side would lie
  // along the segment inside the rounding boxes -- an interior edge on the domain boundary,
  // which the certificate refuses (measured on a 2000-spike star with the graded size). The
  // local search leaves the corner to a later step; the global retry may still close it (a
  // last triangle can need it).
  bool flat_corner(const Step& st, std::uint32_t v) const { return corner_cosine_below(st, v, kCosFlatCorner); }

  void collect_candidates(const Step& st, bool exact) {
    candidates_.clear();
    const double near2 = kNearRadius * kNearRadius * st.size.s * st.size.s;
    for (const std::uint32_t v : nearby_) {
      if (v == st.v1 || v == st.v2 || orientation(st.p1, st.p2, point(v), exact) <= 0) continue;
      if (!exact && flat_corner(st, v)) continue;  // the global retry may still close it
      const double d2 = squared_distance_2(point(v), st.apex);
      if (d2 < near2 && !wide_corner(st, v))
        candidates_.push_back(Candidate{v, 0, -d2});
      else
        candidates_.push_back(Candidate{v, 2, triangle_shape_quality(st.p1, st.p2, point(v))});
    }
    if (apex_allowed(st, exact)) candidates_.push_back(Candidate{st.apex_id, 1, 0.0});
    std::sort(candidates_.begin(), candidates_.end(), better);
  }

  // Condition (2) of a suitable triangle against the local front; (1) was checked when the
  // candidate was collected.
  bool meets_front(const Step& st, std::uint32_t v3, const Point2& p3, IntersectionMode mode) const {
    const std::array<predicates::Vertex2, 3> tri{predicates::Vertex2{st.p1, st.v1}, predicates::Vertex2{st.p2, st.v2},
                                                 predicates::Vertex2{p3, v3}};
    for (const std::uint32_t e : local_edges_) {
      const FrontEdge edge{front_.edge(e).a, front_.edge(e).b};
      const Point2 &a = point(edge.a), &b = point(edge.b);
      if (boxes_apart(st.p1, st.p2, p3, a, b)) continue;
      const std::array<predicates::Vertex2, 2> seg{predicates::Vertex2{a, edge.a}, predicates::Vertex2{b, edge.b}};
      if (predicates::triangle_segment_2d(tri, seg, mode) == predicates::Overlap::intersect) return true;
    }
    return false;
  }

  bool search(const Step& st, bool global) {
    Box2 box{};
    if (!gather(st, global, box)) return false;
    collect_candidates(st, global);
    const IntersectionMode mode = global ? IntersectionMode::exact : IntersectionMode::conservative;
    for (const Candidate& c : candidates_) {
      ++result_.stats.candidates_tested;
      const Point2& p3 = c.vertex == st.apex_id ? st.apex : point(c.vertex);
      if (meets_front(st, c.vertex, p3, mode)) continue;
      accept(st, c.vertex);
      return true;
    }
    return false;
  }

  // The front update rule (digest B §3.2 [DERIVED]) for the counterclockwise τ(v1, v2, v3).
  void accept(const Step& st, std::uint32_t v3) {
    if (v3 == st.apex_id) {
      result_.points.push_back(st.apex);
      grow_vertices();
      ++result_.stats.new_vertices;
    }
    result_.triangles.push_back({st.v1, st.v2, v3});
    erase_edge(st.edge);
    replace_side(st.v2, v3);
    replace_side(v3, st.v1);
  }

  // The triangle side a -> b: if the front holds a -> b it is now inside, else b -> a is new.
  void replace_side(std::uint32_t a, std::uint32_t b) {
    const std::uint32_t e = front_.find(a, b);
    if (e != no_id)
      erase_edge(e);
    else
      insert_edge(b, a, kGrownRank);
  }

  AdvancingFrontResult finish() {
    for (std::uint32_t e = 0; e < front_.slot_count(); ++e)
      if (front_.edge(e).alive) result_.remaining_front.push_back(FrontEdge{front_.edge(e).a, front_.edge(e).b});
    result_.stats.triangles = triangles();
    result_.stats.triangle_bound = bound_;
    result_.stats.completed = result_.remaining_front.empty();
    report(progress_, "advancing front", triangles(), limit_);
    return std::move(result_);
  }

  FrontMeasure measure_;
  FrontSizing2 sizing_;
  FrontGrid2 grid_;
  Front2 front_;
  std::uint64_t user_cap_ = 0, bound_ = 0, limit_ = 0;
  std::uint64_t retry_cap_ = 0;
  std::uint64_t retry_work_cap_ = 0, retry_work_ = 0;  // front edges enumerated by global retries
  const ProgressCallback& progress_;
  AdvancingFrontResult result_;
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> vertex_stamp_, edge_stamp_;
  std::vector<std::uint32_t> local_edges_, nearby_;
  std::vector<Candidate> candidates_;
};

}  // namespace

AdvancingFrontResult advance_front_2(std::span<const Point2> points, std::span<const FrontEdge> front,
                                     const AdvancingFrontOptions& options, const ProgressCallback& progress) {
  return AdvancingFront(points, front, options, progress).run();
}

}  // namespace certimesh::generators
