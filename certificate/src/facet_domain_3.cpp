// TetGen's polygonal facets and regions for the 3D domain check (facet_domain_3.h). Every sign
// is exact: orient2d / orient3d on input doubles, GMP rationals where a point is constructed
// (a facet hole projected onto its facet, a point of a facet for the void test).
#include "facet_domain_3.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <numeric>
#include <string>

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "close_pairs.h"
#include "rational.h"

namespace certimesh::certificate::detail {
namespace {

using FacetEdge = PolygonalFacets::Edge;
using predicates::Point2;
using predicates::Sign;

struct Q2 {
  Q u, v;
};

int sign_of(const Q& x) { return sgn(x); }
int orient_q(const Q2& a, const Q2& b, const Q2& c) { return sign_of((b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u)); }
bool between(const Q& x, const Q& a, const Q& b) { return (a <= x && x <= b) || (b <= x && x <= a); }

// +1 strictly inside the closed loop, 0 on it, -1 outside (a ray to +u, half-open crossings).
int point_in_loop(const std::vector<Q2>& loop, const Q2& x) {
  bool inside = false;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Q2& a = loop[i];
    const Q2& b = loop[(i + 1) % loop.size()];
    const int o = orient_q(a, b, x);
    if (o == 0 && between(x.u, a.u, b.u) && between(x.v, a.v, b.v)) return 0;
    if ((a.v > x.v) != (b.v > x.v) && (b.v > a.v ? o > 0 : o < 0)) inside = !inside;
  }
  return inside ? 1 : -1;
}

Finding invalid_facet(std::size_t f, const std::string& why) {
  return finding(Defect::invalid_domain, -1, static_cast<std::int64_t>(f), -1,
                 "the domain's facet " + std::to_string(f) + " " + why);
}

// One facet's vertices projected to the coordinate plane that drops the normal's largest axis:
// exact (a coordinate is dropped, none computed) and one-to-one on the facet's plane.
struct Projected {
  int u = 0, v = 1;
  Vec origin, normal;
  std::vector<Index> id;      // facet-local vertex -> domain vertex
  std::vector<Point2> at;     // its projection
  std::vector<std::vector<int>> loops;  // polygons, facet-local vertices
};

bool same(const Point2& a, const Point2& b) { return a.x == b.x && a.y == b.y; }
Sign orient(const Projected& p, int a, int b, int c) { return predicates::orient2d(p.at[std::size_t(a)], p.at[std::size_t(b)], p.at[std::size_t(c)]); }

// Whether closed segments ab and cd meet (exact).
bool segments_meet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int o1 = static_cast<int>(predicates::orient2d(a, b, c)), o2 = static_cast<int>(predicates::orient2d(a, b, d));
  const int o3 = static_cast<int>(predicates::orient2d(c, d, a)), o4 = static_cast<int>(predicates::orient2d(c, d, b));
  if (o1 * o2 > 0 || o3 * o4 > 0) return false;
  if (o1 != 0 || o2 != 0) return true;  // proper, or an endpoint on the other segment
  auto within = [](double x, double p, double q) { return std::min(p, q) <= x && x <= std::max(p, q); };
  auto on = [&](const Point2& x, const Point2& p, const Point2& q) { return within(x.x, p.x, q.x) && within(x.y, p.y, q.y); };
  return on(c, a, b) || on(d, a, b) || on(a, c, d) || on(b, c, d);  // collinear: overlapping ranges
}

// Whether M inside the polygon's interior angle at poly[i] (counterclockwise polygon).
bool locally_inside(const Projected& p, const std::vector<int>& poly, std::size_t i, const Point2& m) {
  const std::size_t n = poly.size();
  const Point2& a = p.at[std::size_t(poly[(i + n - 1) % n])];
  const Point2& v = p.at[std::size_t(poly[i])];
  const Point2& b = p.at[std::size_t(poly[(i + 1) % n])];
  const bool left_in = predicates::orient2d(a, v, m) == Sign::positive, right_in = predicates::orient2d(v, b, m) == Sign::positive;
  return predicates::orient2d(a, v, b) == Sign::positive ? left_in && right_in : left_in || right_in;
}

// Joins hole loop `hole` (clockwise) to `poly` (counterclockwise) by a segment from the hole's
// lexicographically largest vertex to a vertex of poly that sees it, crossing no edge of poly
// or of `others` (the holes still to join). False when no such vertex is found.
bool bridge(const Projected& p, std::vector<int>& poly, const std::vector<int>& hole, const std::vector<std::vector<int>>& others) {
  std::size_t m = 0;
  for (std::size_t k = 1; k < hole.size(); ++k) {
    const Point2& a = p.at[std::size_t(hole[k])];
    const Point2& b = p.at[std::size_t(hole[m])];
    if (a.x > b.x || (a.x == b.x && a.y > b.y)) m = k;
  }
  const Point2 mp = p.at[std::size_t(hole[m])];
  std::vector<std::size_t> order(poly.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto distance = [&](std::size_t i) {
    const Point2& q = p.at[std::size_t(poly[i])];
    return (q.x - mp.x) * (q.x - mp.x) + (q.y - mp.y) * (q.y - mp.y);  // only an order to try them in
  };
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return distance(a) < distance(b); });
  auto clear = [&](const std::vector<int>& loop, const Point2& v) {
    for (std::size_t k = 0; k < loop.size(); ++k) {
      const Point2& a = p.at[std::size_t(loop[k])];
      const Point2& b = p.at[std::size_t(loop[(k + 1) % loop.size()])];
      const bool at_end = same(a, v) || same(b, v) || same(a, mp) || same(b, mp);
      if (at_end) {
        if (predicates::orient2d(a, b, v) == Sign::zero && predicates::orient2d(a, b, mp) == Sign::zero &&
            !(same(a, v) && same(b, mp)) && !(same(b, v) && same(a, mp)) && segments_meet(a, b, v, mp)) {
          const Point2& other = same(a, v) || same(a, mp) ? b : a;  // collinear: the far end must not lie on vm
          if (segments_meet(other, other, v, mp)) return false;
        }
        continue;
      }
      if (segments_meet(a, b, v, mp)) return false;
    }
    return true;
  };
  for (std::size_t i : order) {
    const Point2& v = p.at[std::size_t(poly[i])];
    if (!same(v, mp) && !locally_inside(p, poly, i, mp)) continue;
    if (!same(v, mp) && !(clear(poly, v) && std::all_of(others.begin(), others.end(), [&](const std::vector<int>& o) { return clear(o, v); })))
      continue;
    std::vector<int> joined(poly.begin(), poly.begin() + static_cast<std::ptrdiff_t>(i) + 1);
    for (std::size_t k = 0; k <= hole.size(); ++k) joined.push_back(hole[(m + k) % hole.size()]);
    if (same(v, mp)) joined.pop_back();  // the hole touches poly at this vertex: no bridge edge
    else joined.push_back(poly[i]);
    joined.insert(joined.end(), poly.begin() + static_cast<std::ptrdiff_t>(i) + 1, poly.end());
    poly = std::move(joined);
    return true;
  }
  return false;
}

// Ear clipping of a counterclockwise, weakly simple polygon: an ear is a strictly convex corner
// whose triangle holds no other vertex of the polygon (copies of its own corners aside).
bool clip_ears(const Projected& p, std::vector<int> poly, std::vector<std::array<int, 3>>& out) {
  std::size_t i = 0;
  while (poly.size() > 3) {
    const std::size_t n = poly.size();
    bool clipped = false;
    for (std::size_t step = 0; step < n && !clipped; ++step, i = (i + 1) % n) {
      const int a = poly[(i + n - 1) % n], b = poly[i], c = poly[(i + 1) % n];
      if (orient(p, a, b, c) != Sign::positive) continue;
      bool empty = true;
      for (std::size_t k = 0; k < n && empty; ++k) {
        const int x = poly[k];
        const Index id = p.id[std::size_t(x)];
        if (id == p.id[std::size_t(a)] || id == p.id[std::size_t(b)] || id == p.id[std::size_t(c)]) continue;
        empty = !(orient(p, a, b, x) != Sign::negative && orient(p, b, c, x) != Sign::negative && orient(p, c, a, x) != Sign::negative);
      }
      if (!empty) continue;
      out.push_back({a, b, c});
      poly.erase(poly.begin() + static_cast<std::ptrdiff_t>(i));
      if (i >= poly.size()) i = 0;
      clipped = true;
      break;
    }
    if (!clipped) return false;
  }
  if (orient(p, poly[0], poly[1], poly[2]) != Sign::positive) return false;
  out.push_back({poly[0], poly[1], poly[2]});
  return true;
}

Q2 q2_of(const Projected& p, int x) { return {p.at[std::size_t(x)].x, p.at[std::size_t(x)].y}; }

// The facet's polygons, planar, projected; the first Finding on a malformed facet.
Finding project_facet(const io::MeshData& d, std::size_t f, Projected& p) {
  const io::FacetList& F = d.facets;
  auto point = [&](Index v) { return predicates::Point3{d.coordinates[3 * std::size_t(v)], d.coordinates[3 * std::size_t(v) + 1], d.coordinates[3 * std::size_t(v) + 2]}; };
  auto vec = [&](Index v) { return Vec{point(v).x, point(v).y, point(v).z}; };
  std::vector<Index> all;
  for (std::uint64_t q = F.polygon_begin(f); q < F.facet_end[f]; ++q) {
    const std::uint64_t k = F.polygon_end[q] - F.corner_begin(q);
    if (k < 3)
      return invalid_facet(f, "has a polygon of " + std::to_string(k) + " corner" + (k == 1 ? "" : "s") +
                                   " (a point or segment inside a facet), which the certificate does not read yet");
    std::vector<Index> corners(F.corners.begin() + static_cast<std::ptrdiff_t>(F.corner_begin(q)), F.corners.begin() + static_cast<std::ptrdiff_t>(F.polygon_end[q]));
    std::vector<Index> sorted = corners;
    std::sort(sorted.begin(), sorted.end());
    if (std::adjacent_find(sorted.begin(), sorted.end()) != sorted.end()) return invalid_facet(f, "has a polygon that repeats a corner");
    all.insert(all.end(), corners.begin(), corners.end());
  }
  if (all.empty()) return invalid_facet(f, "has no polygon");
  const Index a = all[0];
  std::size_t j = 1;
  while (j < all.size() && vec(all[j]) == vec(a)) ++j;
  std::size_t k = j + 1;
  while (j < all.size() && k < all.size() && cross(minus(vec(all[j]), vec(a)), minus(vec(all[k]), vec(a))) == Vec{0, 0, 0}) ++k;
  if (j >= all.size() || k >= all.size()) return invalid_facet(f, "has all its corners on one line");
  const Index b = all[j], c = all[k];
  for (Index x : all)
    if (predicates::orient3d(point(a), point(b), point(c), point(x)) != Sign::zero)
      return invalid_facet(f, "is not planar: corner " + std::to_string(x) + " is off the plane through corners " + std::to_string(a) +
                                  ", " + std::to_string(b) + " and " + std::to_string(c));
  p.origin = vec(a);
  p.normal = cross(minus(vec(b), vec(a)), minus(vec(c), vec(a)));
  int drop = 0;
  for (int axis = 1; axis < 3; ++axis)
    if (abs(p.normal[std::size_t(axis)]) > abs(p.normal[std::size_t(drop)])) drop = axis;
  p.u = (drop + 1) % 3;
  p.v = (drop + 2) % 3;
  for (std::uint64_t q = F.polygon_begin(f); q < F.facet_end[f]; ++q) {
    std::vector<int> loop;
    for (std::uint64_t i = F.corner_begin(q); i < F.polygon_end[q]; ++i) {
      const Index v = F.corners[i];
      loop.push_back(static_cast<int>(p.id.size()));
      p.id.push_back(v);
      const double* x = d.coordinates.data() + 3 * std::size_t(v);
      p.at.push_back({x[p.u], x[p.v]});
    }
    p.loops.push_back(std::move(loop));
  }
  return {};
}

Q area2(const Projected& p, const std::vector<int>& loop) {
  Q sum = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Q2 a = q2_of(p, loop[i]), b = q2_of(p, loop[(i + 1) % loop.size()]);
    sum += a.u * b.v - a.v * b.u;
  }
  return sum;
}

// Whether loop `inner` lies inside loop `outer`: its first vertex off `outer` is inside.
bool inside_loop(const std::vector<Q2>& outer, const std::vector<Q2>& inner) {
  for (const Q2& x : inner)
    if (const int s = point_in_loop(outer, x); s != 0) return s > 0;
  return false;  // every vertex on `outer`: the same polygon, or one beside it
}

Finding cut_facet(const io::MeshData& d, std::size_t f, PolygonalFacets& out) {
  Projected p;
  if (Finding e = project_facet(d, f, p); e.defect != Defect::none) return e;
  const std::size_t L = p.loops.size();
  std::vector<std::vector<Q2>> q(L);
  std::vector<int> area_sign(L), depth(L, 0);
  for (std::size_t i = 0; i < L; ++i) {
    for (int x : p.loops[i]) q[i].push_back(q2_of(p, x));
    area_sign[i] = sign_of(area2(p, p.loops[i]));
    if (area_sign[i] == 0) return invalid_facet(f, "has a polygon of zero area");
  }
  for (std::size_t i = 0; i < L; ++i)
    for (std::size_t j = 0; j < L; ++j)
      if (i != j && inside_loop(q[j], q[i])) ++depth[i];
  // Facet holes, projected orthogonally (as TetGen says) onto the facet's plane.
  const io::FacetList& F = d.facets;
  std::vector<char> marked(L, 0);
  for (std::uint64_t h = F.hole_begin(f); h < F.hole_end[f]; ++h) {
    const Vec x{F.holes[3 * h], F.holes[3 * h + 1], F.holes[3 * h + 2]};
    const Q t = dot(p.normal, minus(x, p.origin)) / dot(p.normal, p.normal);
    const Vec y{x[0] - t * p.normal[0], x[1] - t * p.normal[1], x[2] - t * p.normal[2]};
    const Q2 at{y[std::size_t(p.u)], y[std::size_t(p.v)]};
    std::size_t count = 0, innermost = L;
    for (std::size_t i = 0; i < L; ++i) {
      const int s = point_in_loop(q[i], at);
      if (s == 0) return invalid_facet(f, "has facet hole " + std::to_string(h - F.hole_begin(f)) + " on one of its polygons");
      if (s > 0 && (++count, innermost == L || depth[i] > depth[innermost])) innermost = i;
    }
    if (count == 0) return invalid_facet(f, "has facet hole " + std::to_string(h - F.hole_begin(f)) + " outside all its polygons");
    if (count % 2 == 1)
      return invalid_facet(f, "has facet hole " + std::to_string(h - F.hole_begin(f)) +
                                  " inside its region (inside an odd number of its polygons; a hole is marked inside a polygon that lies in another)");
    marked[innermost] = 1;
  }
  for (std::size_t i = 0; i < L; ++i)
    if (depth[i] % 2 == 1 && !marked[i])
      return invalid_facet(f, "has polygon " + std::to_string(i) +
                                  " inside another of its polygons and no facet hole in it: certimesh reads a facet as the points inside an odd "
                                  "number of its polygons, so a polygon inside another must be a hole (a polygon kept inside a facet is not read yet)");
  // The facet's orientation: that of its first outer polygon as the file lists it.
  std::size_t first_outer = 0;
  while (first_outer < L && depth[first_outer] % 2 == 1) ++first_outer;
  if (first_outer == L) return invalid_facet(f, "has polygons that cross (each lies inside another)");
  const bool flip = area_sign[first_outer] < 0;
  std::vector<std::vector<int>> oriented = p.loops;
  for (std::size_t i = 0; i < L; ++i)
    if ((area_sign[i] > 0) != (depth[i] % 2 == 0)) std::reverse(oriented[i].begin(), oriented[i].end());
  std::vector<std::array<int, 3>> triangles;
  for (std::size_t i = 0; i < L; ++i) {
    if (depth[i] % 2 == 1) continue;
    std::vector<std::size_t> holes;
    for (std::size_t j = 0; j < L; ++j)
      if (depth[j] == depth[i] + 1 && inside_loop(q[i], q[j])) holes.push_back(j);
    auto top = [&](std::size_t j) {
      Point2 best = p.at[std::size_t(oriented[j][0])];
      for (int x : oriented[j]) {
        const Point2& a = p.at[std::size_t(x)];
        if (a.x > best.x || (a.x == best.x && a.y > best.y)) best = a;
      }
      return best;
    };
    std::stable_sort(holes.begin(), holes.end(), [&](std::size_t a, std::size_t b) {
      const Point2 x = top(a), y = top(b);
      return x.x > y.x || (x.x == y.x && x.y > y.y);
    });
    std::vector<int> poly = oriented[i];
    for (std::size_t k = 0; k < holes.size(); ++k) {
      std::vector<std::vector<int>> rest;
      for (std::size_t r = k; r < holes.size(); ++r) rest.push_back(oriented[holes[r]]);
      if (!bridge(p, poly, oriented[holes[k]], rest))
        return invalid_facet(f, "could not be cut into triangles: no vertex of polygon " + std::to_string(i) + " sees hole polygon " + std::to_string(holes[k]));
    }
    if (!clip_ears(p, poly, triangles))
      return invalid_facet(f, "could not be cut into triangles (are its polygons simple, and do they cross?)");
  }
  std::vector<FacetEdge> edges;
  for (const auto& loop : p.loops)
    for (std::size_t k = 0; k < loop.size(); ++k) edges.push_back(std::minmax(p.id[std::size_t(loop[k])], p.id[std::size_t(loop[(k + 1) % loop.size()])]));
  std::sort(edges.begin(), edges.end());
  std::vector<FacetEdge> boundary;
  for (std::size_t i = 0, j = 0; i < edges.size(); i = j) {
    while (j < edges.size() && edges[j] == edges[i]) ++j;
    if ((j - i) % 2 == 1) boundary.push_back(edges[i]);
  }
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  // The cut is checked, not trusted: its triangles' mod-2 boundary must be the region's.
  std::vector<FacetEdge> cut;
  for (const auto& t : triangles)
    for (int k = 0; k < 3; ++k) cut.push_back(std::minmax(p.id[std::size_t(t[std::size_t(k)])], p.id[std::size_t(t[std::size_t((k + 1) % 3)])]));
  std::sort(cut.begin(), cut.end());
  std::vector<FacetEdge> odd;
  for (std::size_t i = 0, j = 0; i < cut.size(); i = j) {
    while (j < cut.size() && cut[j] == cut[i]) ++j;
    if ((j - i) % 2 == 1) odd.push_back(cut[i]);
  }
  if (odd != boundary) return invalid_facet(f, "could not be cut into triangles: its polygons cross or overlap");
  for (const auto& t : triangles) {
    out.triangles.push_back(p.id[std::size_t(t[0])]);
    out.triangles.push_back(p.id[std::size_t(flip ? t[2] : t[1])]);
    out.triangles.push_back(p.id[std::size_t(flip ? t[1] : t[2])]);
    out.facet_of.push_back(static_cast<std::uint32_t>(f));
  }
  out.boundary.push_back(std::move(boundary));
  out.edges.push_back(std::move(edges));
  return {};
}

// orient3d on rational points: the sign of det[a-d, b-d, c-d].
int orient_q3(const Vec& a, const Vec& b, const Vec& c, const Vec& d) { return sign_of(dot(minus(a, d), cross(minus(b, d), minus(c, d)))); }

// Whether the closed segment pq meets the closed triangle abc; coplanar counts as meeting
// (conservative: a blocked path only makes the void test fail, never pass).
bool segment_meets_triangle(const Vec& p, const Vec& q, const Vec& a, const Vec& b, const Vec& c) {
  const int s1 = orient_q3(a, b, c, p), s2 = orient_q3(a, b, c, q);
  if (s1 * s2 > 0) return false;
  if (s1 == 0 && s2 == 0) return true;
  const int t1 = orient_q3(p, q, a, b), t2 = orient_q3(p, q, b, c), t3 = orient_q3(p, q, c, a);
  return (t1 >= 0 && t2 >= 0 && t3 >= 0) || (t1 <= 0 && t2 <= 0 && t3 <= 0);
}

}  // namespace

Finding triangulate_facets(const io::MeshData& domain, PolygonalFacets& out) {
  const io::FacetList& F = domain.facets;
  const std::size_t n = F.facet_count();
  bool consistent = F.hole_end.size() == n && F.holes.size() == 3 * (n == 0 ? 0 : F.hole_end.back()) &&
                    F.polygon_count() == (n == 0 ? 0 : F.facet_end.back()) &&
                    F.corners.size() == (F.polygon_count() == 0 ? 0 : F.polygon_end.back());
  for (std::size_t f = 0; consistent && f < n; ++f) consistent = F.polygon_begin(f) <= F.facet_end[f] && F.hole_begin(f) <= F.hole_end[f];
  for (std::size_t q = 0; consistent && q < F.polygon_count(); ++q) consistent = F.corner_begin(q) <= F.polygon_end[q];
  for (std::size_t i = 0; consistent && i < F.corners.size(); ++i) consistent = F.corners[i] < domain.point_count();
  if (!consistent)
    return finding(Defect::invalid_domain, -1, -1, -1, "the domain's facet list is inconsistent (an offset or a corner out of range)");
  for (std::size_t f = 0; f < domain.facets.facet_count(); ++f)
    if (Finding e = cut_facet(domain, f, out); e.defect != Defect::none) return e;
  return {};
}

namespace {

// The rational segment from `from` to `to` meets no domain triangle but `skip`.
bool clear_path(const MeshView& geo, const FacetSet& triangles, const Vec& from, const Vec& to, std::size_t skip) {
  for (std::size_t s = 0; s < triangles.size(); ++s) {
    if (s == skip) continue;
    const Index* y = triangles.facet(s);
    if (segment_meets_triangle(from, to, point_of(geo, y[0]), point_of(geo, y[1]), point_of(geo, y[2]))) return false;
  }
  return true;
}

// Whether from `from` a segment along an axis, in a direction d with sign(n . d) = side (any
// direction when n is zero), leaves the domain's bounding box meeting no domain triangle but `skip`.
bool escapes(const MeshView& geo, const FacetSet& triangles, const Vec& from, const Vec& n, int side, std::size_t skip) {
  double lo = 0, hi = 0;
  for (std::size_t i = 0; i < geo.vertex_count * 3; ++i) lo = std::min(lo, geo.xyz[i]), hi = std::max(hi, geo.xyz[i]);
  const bool any = n == Vec{0, 0, 0};
  for (int axis = 0; axis < 3; ++axis)
    for (int s : {1, -1}) {
      if (!any && sign_of(n[std::size_t(axis)]) * side != s) continue;
      Vec to = from;
      to[std::size_t(axis)] = s > 0 ? Q(Q(hi) + 1) : Q(Q(lo) - 1);
      if (from[std::size_t(axis)] * s < to[std::size_t(axis)] * s && clear_path(geo, triangles, from, to, skip)) return true;
    }
  return false;
}

}  // namespace

bool facet_void_on_both_sides(const MeshView& geo, const FacetSet& triangles, const PolygonalFacets& facets, std::uint32_t facet,
                              const std::vector<double>& holes) {
  std::size_t t = 0;
  while (t < facets.facet_of.size() && facets.facet_of[t] != facet) ++t;
  if (t == facets.facet_of.size()) return false;
  const Index* x = triangles.facet(t);
  const Vec a = point_of(geo, x[0]), b = point_of(geo, x[1]), c = point_of(geo, x[2]);
  const Vec centre{(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3, (a[2] + b[2] + c[2]) / 3};
  const Vec n = cross(minus(b, a), minus(c, a));
  for (int side : {1, -1}) {
    bool reached = false;
    for (std::size_t h = 0; !reached && h < holes.size() / 3; ++h) {
      const Vec to{holes[3 * h], holes[3 * h + 1], holes[3 * h + 2]};
      reached = sign_of(dot(n, minus(to, centre))) == side && clear_path(geo, triangles, centre, to, t);
    }
    if (!reached && !escapes(geo, triangles, centre, n, side, t)) return false;
  }
  return true;
}

bool point_escapes(const MeshView& geo, const FacetSet& triangles, const double* p) {
  return escapes(geo, triangles, Vec{p[0], p[1], p[2]}, Vec{0, 0, 0}, 1, triangles.size());
}

Finding region_labels(const MeshView& m, const io::MeshData& domain, const std::vector<char>& face_on_facet) {
  const std::size_t regions = domain.region_attributes.size();
  if (regions == 0 || m.dim != 3) return {};
  static constexpr int kFace[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};  // as facet_pairing.cpp
  // The regions of the mesh: tetrahedra joined across faces on no domain facet (union-find).
  std::vector<std::size_t> root(m.element_count);
  std::iota(root.begin(), root.end(), std::size_t{0});
  auto find = [&](std::size_t e) {
    while (root[e] != e) e = root[e] = root[root[e]];
    return e;
  };
  std::vector<std::pair<std::array<Index, 3>, std::size_t>> faces;
  for (std::size_t e = 0; e < m.element_count; ++e)
    for (int i = 0; i < 4; ++i) {
      if (face_on_facet[4 * e + std::size_t(i)]) continue;
      std::array<Index, 3> x{m.cell(e)[kFace[i][0]], m.cell(e)[kFace[i][1]], m.cell(e)[kFace[i][2]]};
      std::sort(x.begin(), x.end());
      faces.push_back({x, e});
    }
  std::sort(faces.begin(), faces.end());
  for (std::size_t i = 0; i + 1 < faces.size(); ++i)
    if (faces[i].first == faces[i + 1].first) root[find(faces[i].second)] = find(faces[i + 1].second);
  // Each region point's tetrahedron: closed containment by orient3d, candidates from the box grid.
  std::vector<Box> boxes;
  for (std::size_t e = 0; e < m.element_count; ++e) boxes.push_back(facet_box(m, m.cell(e), 4));
  for (std::size_t r = 0; r < regions; ++r) {
    const double* p = domain.region_points.data() + 3 * r;
    boxes.push_back(Box{{p[0], p[1], p[2]}, {p[0], p[1], p[2]}});
  }
  std::vector<std::int64_t> home(regions, -1);
  BoxGrid(boxes, 3).any_pair([&](std::size_t i, std::size_t j) {
    if (i >= m.element_count || j < m.element_count) return false;
    const std::size_t r = j - m.element_count;
    const double* p = domain.region_points.data() + 3 * r;
    const predicates::Point3 x{p[0], p[1], p[2]};
    for (const auto& f : kFace)
      if (predicates::orient3d(m.p3(m.cell(i)[f[0]]), m.p3(m.cell(i)[f[1]]), m.p3(m.cell(i)[f[2]]), x) == Sign::negative) return false;
    if (home[r] < 0 || static_cast<std::size_t>(home[r]) > i) home[r] = static_cast<std::int64_t>(i);
    return false;
  });
  std::vector<std::int64_t> region_of_root(m.element_count, -1);
  for (std::size_t r = 0; r < regions; ++r) {
    if (home[r] < 0)
      return finding(Defect::invalid_domain, -1, static_cast<std::int64_t>(r), -1,
                     "the domain's region point " + std::to_string(r) + " is outside the solid (in no tetrahedron of the mesh)");
    const std::size_t c = find(static_cast<std::size_t>(home[r]));
    const std::int64_t other = region_of_root[c];
    if (other >= 0 && domain.region_attributes[static_cast<std::size_t>(other)] != domain.region_attributes[r])
      return finding(Defect::invalid_domain, -1, static_cast<std::int64_t>(r), -1,
                     "the domain's region points " + std::to_string(other) + " and " + std::to_string(r) +
                         " lie in one region but give it different attributes");
    region_of_root[c] = static_cast<std::int64_t>(r);
  }
  for (std::size_t e = 0; e < m.element_count; ++e) {
    const std::int64_t r = region_of_root[find(e)];
    if (r < 0) continue;
    const double want = domain.region_attributes[static_cast<std::size_t>(r)];
    char shown[32];
    std::snprintf(shown, sizeof shown, "%.17g", want);
    const io::Label have = m.labels == nullptr ? 0 : m.labels[e];
    if (static_cast<double>(have) != want)
      return finding(Defect::region_label_mismatch, static_cast<std::int64_t>(e), r, -1,
                     "tetrahedron " + std::to_string(e) + " is labelled " + std::to_string(have) + " but lies in the region of region point " +
                         std::to_string(r) + ", whose attribute is " + shown +
                         (m.labels == nullptr ? " (the mesh has no labels: TetGen writes them with -A)" : ""));
  }
  return {};
}

}  // namespace certimesh::certificate::detail
