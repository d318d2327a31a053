// The cone test at one vertex (vertex_fans.h). Every sign is an exact orient3d.
#include "vertex_fans.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>

#include "certimesh/predicates/orient3d.h"

namespace certimesh::certificate::detail {
namespace {

using predicates::Point3;
using predicates::Sign;

// Angles of half-planes around the line v c, measured from the half-plane of r: a point's
// "y" is orient3d(v, c, r, a), its "x" sigma * orient3d(v, c, s, a) with s off the plane (v,
// c, r); angles in [0, pi) first, then one orient3d orders two points of the same half.
struct Axis {
  Point3 v, c, r, s;
  int sigma = 0;
  // 0 for angles in [0, pi), 1 for [pi, 2 pi), -1 for a point on the line (no angle).
  int half(const Point3& a) const {
    const Sign y = predicates::orient3d(v, c, r, a);
    if (y == Sign::positive) return 0;
    if (y == Sign::negative) return 1;
    const int x = sigma * static_cast<int>(predicates::orient3d(v, c, s, a));
    return x > 0 ? 0 : x < 0 ? 1 : -1;
  }
};

struct Ray {  // a half-plane around the line, given by a point in it
  Point3 p;
  int half;
};

// One point twice (a vertex shared by two triangles: most comparisons) is decided without
// orient3d, whose exact stage a zero would reach.
bool equal_points(const Point3& a, const Point3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

bool less(const Axis& ax, const Ray& a, const Ray& b) {
  if (a.half != b.half) return a.half < b.half;
  if (equal_points(a.p, b.p)) return false;
  return predicates::orient3d(ax.v, ax.c, a.p, b.p) == Sign::positive;
}
bool same(const Axis& ax, const Ray& a, const Ray& b) {
  return a.half == b.half && (equal_points(a.p, b.p) || predicates::orient3d(ax.v, ax.c, a.p, b.p) == Sign::zero);
}

bool try_axis(const MeshView& m, const FacetSet& set, Index v, const std::vector<std::size_t>& fan, const Point3& c,
              std::int64_t c_id, const std::function<bool(std::size_t, std::size_t)>& meet) {
  Axis ax;
  ax.v = m.p3(v);
  ax.c = c;
  // r and s: v moved along the two axes least parallel to the line (any points off the line
  // and off each other's plane through it would do; that is checked exactly below).
  const double d[3] = {c.x - ax.v.x, c.y - ax.v.y, c.z - ax.v.z};
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int i, int j) { return std::fabs(d[i]) < std::fabs(d[j]); });
  const double span = std::max({std::fabs(d[0]), std::fabs(d[1]), std::fabs(d[2])});
  auto moved = [&](int axis) {
    double p[3] = {ax.v.x, ax.v.y, ax.v.z};
    p[axis] += span;
    return Point3{p[0], p[1], p[2]};
  };
  ax.r = moved(order[0]);
  ax.s = moved(order[1]);
  // Near the largest double, c - v or v moved by it can overflow, and orient3d refuses an
  // infinity (it would throw on a valid mesh): undecided instead, the grid decides.
  auto finite = [](const Point3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); };
  if (!std::isfinite(span) || !finite(ax.r) || !finite(ax.s)) return false;
  ax.sigma = static_cast<int>(predicates::orient3d(ax.v, ax.c, ax.s, ax.r));
  if (ax.sigma == 0) return false;

  struct Wedge {
    Ray start, end;
    std::size_t facet;
  };
  struct Plane {
    Ray at;
    std::size_t facet;
  };
  std::vector<Wedge> wedges;
  std::vector<Plane> planes;  // triangles with the line's point c as a vertex
  for (std::size_t f : fan) {
    const Index* t = set.facet(f);
    Index a = 0, b = 0;
    int k = 0;
    for (int i = 0; i < 3; ++i)
      if (t[i] != v) (k++ == 0 ? a : b) = t[i];
    if (k != 2) return false;
    const Point3 pa = m.p3(a), pb = m.p3(b);
    const Sign o = predicates::orient3d(ax.v, ax.c, pa, pb);
    if (o == Sign::zero) {
      const Index other = static_cast<std::int64_t>(a) == c_id ? b : static_cast<std::int64_t>(b) == c_id ? a : v;
      if (other == v) return false;  // the line lies in the triangle's plane: no wedge
      const Ray at{m.p3(other), ax.half(m.p3(other))};
      if (at.half < 0) return false;  // a degenerate triangle along the line
      planes.push_back({at, f});
      continue;
    }
    Ray ra{pa, ax.half(pa)}, rb{pb, ax.half(pb)};  // neither on the line: o != 0
    if (o == Sign::negative) std::swap(ra, rb);
    wedges.push_back({ra, rb, f});
  }
  // Open wedges pairwise disjoint: sorted by start, each ends before the next starts (only
  // the last may pass angle 0, and must end before the first starts).
  std::sort(wedges.begin(), wedges.end(), [&](const Wedge& x, const Wedge& y) { return less(ax, x.start, y.start); });
  const std::size_t w = wedges.size();
  auto wraps = [&](const Wedge& x) { return less(ax, x.end, x.start); };
  for (std::size_t i = 0; i < w; ++i) {
    const Wedge& x = wedges[i];
    if (i + 1 < w) {
      if (!less(ax, x.start, wedges[i + 1].start) || wraps(x) || less(ax, wedges[i + 1].start, x.end)) return false;
    } else if (w > 1 && wraps(x) && less(ax, wedges[0].start, x.end)) {
      return false;
    }
  }
  // No triangle's half-plane strictly inside a wedge; and the pairs with a common bounding
  // half-plane, tested exactly. With the open wedges disjoint and sorted, starts and ends both
  // increase, so a wedge's end can equal only the next wedge's start (the last's, the first's);
  // a triangle's half-plane can equal the bounds of the wedge starting at or before it and of
  // the one before that, and other such half-planes (sorted among themselves).
  auto test = [&](std::size_t f, std::size_t g) { return f != g && meet(f, g); };
  for (std::size_t i = 0; i < w; ++i) {
    const Wedge &x = wedges[i], &y = wedges[(i + 1) % w];
    if (w > 1 && same(ax, x.end, y.start) && test(x.facet, y.facet)) return false;
  }
  for (const Plane& p : planes) {
    const auto it = std::upper_bound(wedges.begin(), wedges.end(), p.at, [&](const Ray& r, const Wedge& x) { return less(ax, r, x.start); });
    const std::size_t at = static_cast<std::size_t>(it - wedges.begin());  // wedges[at - 1] starts at or before p
    if (at > 0) {
      const Wedge& x = wedges[at - 1];
      if (less(ax, x.start, p.at) && (wraps(x) || less(ax, p.at, x.end))) return false;
    } else if (w > 0 && wraps(wedges[w - 1]) && less(ax, p.at, wedges[w - 1].end)) {
      return false;
    }
    for (std::size_t back = 1; back <= std::min<std::size_t>(2, w); ++back) {
      const Wedge& x = wedges[(at + w - back) % w];
      if ((same(ax, x.start, p.at) || same(ax, x.end, p.at)) && test(x.facet, p.facet)) return false;
    }
  }
  std::sort(planes.begin(), planes.end(), [&](const Plane& x, const Plane& y) { return less(ax, x.at, y.at); });
  for (std::size_t first = 0, end = 0; first < planes.size(); first = end) {
    for (end = first + 1; end < planes.size() && same(ax, planes[first].at, planes[end].at);) ++end;
    for (std::size_t i = first; i < end; ++i)
      for (std::size_t j = i + 1; j < end; ++j)
        if (test(planes[i].facet, planes[j].facet)) return false;
  }
  return true;
}

}  // namespace

bool fan_is_embedded(const MeshView& m, const FacetSet& set, Index v, const std::vector<std::size_t>& fan,
                     const std::function<bool(std::size_t, std::size_t)>& meet) {
  // First line: along the fan's summed normal (through a convex or flat fan it leaves every
  // cone a proper wedge); then through the neighbour in most of the triangles (a spine).
  const Point3 pv = m.p3(v);
  double n[3] = {0, 0, 0}, len = 0;
  std::unordered_map<Index, int> count;
  for (std::size_t f : fan) {
    const Index* t = set.facet(f);
    const int i = t[0] == v ? 0 : t[1] == v ? 1 : 2;
    const Point3 a = m.p3(t[(i + 1) % 3]), b = m.p3(t[(i + 2) % 3]);
    const double u[3] = {a.x - pv.x, a.y - pv.y, a.z - pv.z}, w[3] = {b.x - pv.x, b.y - pv.y, b.z - pv.z};
    n[0] += u[1] * w[2] - u[2] * w[1], n[1] += u[2] * w[0] - u[0] * w[2], n[2] += u[0] * w[1] - u[1] * w[0];
    for (double x : u) len = std::max(len, std::fabs(x));
    ++count[t[(i + 1) % 3]], ++count[t[(i + 2) % 3]];
  }
  const double nmax = std::max({std::fabs(n[0]), std::fabs(n[1]), std::fabs(n[2])});
  if (std::isfinite(nmax) && nmax > 0 && std::isfinite(len) && len > 0) {
    const double s = len / nmax;
    const Point3 c{pv.x + n[0] * s, pv.y + n[1] * s, pv.z + n[2] * s};
    if (std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z) && try_axis(m, set, v, fan, c, -1, meet)) return true;
  }
  Index spine = v;
  int most = 2;
  for (const auto& [id, k] : count)
    if (k > most || (k == most && spine != v && id < spine)) spine = id, most = k;
  return spine != v && try_axis(m, set, v, fan, m.p3(spine), spine, meet);
}

}  // namespace certimesh::certificate::detail
