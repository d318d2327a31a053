// Geometry shared by the two Delaunay refinements (delaunay_refinement_2.h,
// quality_refinement_2.h): approximate lengths and circumcentres (they steer where points go),
// and the exact straight walk that decides whether a point is reachable inside a region.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <queue>
#include <tuple>

#include "certimesh/generators/delaunay/constrained_delaunay_2.h"
#include "certimesh/predicates/orient2d.h"

namespace certimesh::generators::detail {

inline int orient(const Point2& a, const Point2& b, const Point2& c) {
  return predicates::to_int(predicates::orient2d(a, b, c));
}

inline double distance(const Point2& a, const Point2& b) { return std::hypot(a.x - b.x, a.y - b.y); }

inline Point2 circumcentre(const Point2& a, const Point2& b, const Point2& c) {
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double d = 2.0 * (bx * cy - by * cx);
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  return {a.x + (cy * b2 - by * c2) / d, a.y + (bx * c2 - cx * b2) / d};
}

// The corners of a live triangle, counterclockwise.
struct Corners {
  std::array<Point2, 3> p;
  Corners(const ConstrainedDelaunay2& cdt, ConstrainedDelaunay2::TriangleId t) {
    const auto v = cdt.vertices(t);
    for (std::size_t i = 0; i < 3; ++i) p[i] = cdt.point(v[i]);
  }
  const Point2& operator[](int i) const { return p[static_cast<std::size_t>(i)]; }
  double side(int i) const { return distance((*this)[(i + 1) % 3], (*this)[(i + 2) % 3]); }  // opposite corner i
  double shortest() const { return std::min({side(0), side(1), side(2)}); }
  Point2 centroid() const { return {(p[0].x + p[1].x + p[2].x) / 3.0, (p[0].y + p[1].y + p[2].y) / 3.0}; }
};

// Where a straight walk from the centroid of t towards c ended: the triangle holding c, or
// (triangle `none`) the constrained edge it met first, given by the triangle before it and
// the edge's local index; `blocked` without an edge when it met a vertex or the hull.
struct WalkEnd {
  ConstrainedDelaunay2::TriangleId holder = ConstrainedDelaunay2::none;
  ConstrainedDelaunay2::TriangleId before = ConstrainedDelaunay2::none;
  int edge = -1;
};

/// Walks straight from the centroid of t to c, never crossing a constrained edge; every sign
/// exact.
inline WalkEnd straight_walk(const ConstrainedDelaunay2& cdt, ConstrainedDelaunay2::TriangleId t, const Point2& c) {
  constexpr auto none = ConstrainedDelaunay2::none;
  const Corners start(cdt, t);
  const Point2 g = start.centroid();
  for (int i = 0; i < 3; ++i)
    if (orient(start[i], start[(i + 1) % 3], g) <= 0) return {};
  for (std::size_t step = 0; step < 4 * cdt.triangle_slot_count() + 16; ++step) {
    const Corners here(cdt, t);
    int exit = -1;
    bool beyond = false;
    for (int i = 0; i < 3 && exit < 0; ++i) {
      const Point2 &a = here[(i + 1) % 3], &b = here[(i + 2) % 3];
      if (orient(a, b, c) >= 0) continue;
      beyond = true;
      const int oa = orient(g, c, a), ob = orient(g, c, b);
      if (oa == 0 || ob == 0) return {};
      if (oa != ob) exit = i;
    }
    if (exit < 0) return beyond ? WalkEnd{} : WalkEnd{t, none, -1};
    if (cdt.is_constrained(t, exit)) return {none, t, exit};
    t = cdt.neighbour(t, exit);
    if (t == none) return {};
  }
  return {};
}

// Bad triangles, worst first; ties broken by the sorted vertex ids, which also tell, when an
// entry is popped, whether its slot still holds the triangle queued (deterministic).
class WorstFirstQueue {
 public:
  using TriangleId = ConstrainedDelaunay2::TriangleId;
  void push(const ConstrainedDelaunay2& cdt, TriangleId t, double badness) {
    auto v = cdt.vertices(t);
    std::sort(v.begin(), v.end());
    queue_.push({badness, v, t});
  }
  bool empty() const { return queue_.empty(); }
  /// Pops the worst entry; `none` when its triangle is gone.
  TriangleId pop(const ConstrainedDelaunay2& cdt) {
    const Entry e = queue_.top();
    queue_.pop();
    if (!cdt.is_live(e.t)) return ConstrainedDelaunay2::none;
    auto v = cdt.vertices(e.t);
    std::sort(v.begin(), v.end());
    return v == e.vertices ? e.t : ConstrainedDelaunay2::none;
  }

 private:
  struct Entry {
    double badness;
    std::array<ConstrainedDelaunay2::VertexId, 3> vertices;
    TriangleId t;
    bool operator<(const Entry& o) const { return std::tie(badness, vertices) < std::tie(o.badness, o.vertices); }
  };
  std::priority_queue<Entry> queue_;
};

}  // namespace certimesh::generators::detail
