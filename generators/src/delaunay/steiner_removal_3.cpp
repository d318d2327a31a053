// Stage 4 of boundary recovery, the monograph's Algorithm 19 (digest C section 2.3): every
// Steiner point v of stages 1-2 (all on the surface), first those on surface edges, then those
// inside surface triangles, is taken off the surface:
//   - the boundary faces around v lie in v's triangle (or, for a point on an edge, in the
//     edge's two triangles); per triangle they form a planar polygon (a fan around v) whose
//     vertices are exact points of the triangle's plane;
//   - the polygon without v is triangulated by diagonals (exactly, in the triangle's plane
//     projected along an axis the plane is not parallel to); each new triangle and v make a
//     new tetrahedron, flat while v is still in the plane;
//   - v moves to a double point inside its star where every incident tetrahedron is positive,
//     checked by exact orient3d: along the inward direction (the bisector of the two inward
//     normals for an edge point), then towards the centroid of its star, halving the step.
// A position always exists exactly (a small enough step inward keeps the old tetrahedra
// positive and makes the new ones positive); that a double one exists is not guaranteed:
// proofs/boundary_recovery_3.md section 5 says when it can fail, and then this says so.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "certimesh/predicates/orient3d.h"
#include "recovery_mesh_3.h"

namespace certimesh::generators::detail {

namespace {

using Polygon = std::vector<VertexId>;
using Triangle = std::array<VertexId, 3>;

// The exact 2D coordinates of the triangle's plane projected along `axis`.
struct Plane2 {
  int axis = 2;
  int sign = 1;  // the sign of the triangle's own orientation in the projection
  mpq_class orient(const QPoint& a, const QPoint& b, const QPoint& c) const {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    return (a[i] - c[i]) * (b[j] - c[j]) - (a[j] - c[j]) * (b[i] - c[i]);
  }
  bool lexicographically_less(const QPoint& a, const QPoint& b) const {
    const int i = (axis + 1) % 3, j = (axis + 2) % 3;
    return a[i] != b[i] ? a[i] < b[i] : a[j] < b[j];
  }
};

Plane2 plane_of(const RecoverySurface3& s, std::uint32_t triangle) {
  const auto& t = s.triangles[triangle];
  const Point3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
  const double n[3] = {(b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y),
                       (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z),
                       (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)};
  // The axis of the largest approximate normal component, if its exact one is not zero.
  int order[3] = {0, 1, 2};
  std::sort(order, order + 3, [&](int x, int y) { return std::fabs(n[x]) > std::fabs(n[y]); });
  for (const int axis : order) {
    Plane2 p{axis, 1};
    const int o = sgn(p.orient(to_q(a), to_q(b), to_q(c)));
    if (o != 0) {
      p.sign = o;
      return p;
    }
  }
  recovery_invariant_broken("surface triangle " + std::to_string(triangle) + " is degenerate");
}

// Triangulation of a simple polygon (its vertices in the triangle's orientation, possibly
// with straight angles) by diagonals, into non-degenerate triangles of the same orientation:
// the lexicographically smallest vertex v is strictly convex; if the triangle of v and its
// neighbours holds no other vertex it is an ear, else the diagonal from v to the vertex in it
// farthest from the neighbours' line splits the polygon in two (no vertex lies on that
// diagonal, and it is inside the polygon). Each step makes the polygons smaller.
std::vector<Triangle> triangulate(const RecoveryMesh& m, const Plane2& plane, Polygon polygon) {
  auto q = [&](VertexId v) -> const QPoint& { return m.vertices[v.value].exact; };
  auto o = [&](VertexId a, VertexId b, VertexId c) { return plane.sign * sgn(plane.orient(q(a), q(b), q(c))); };
  std::vector<Triangle> out;
  std::vector<Polygon> pending{std::move(polygon)};
  while (!pending.empty()) {
    Polygon p = std::move(pending.back());
    pending.pop_back();
    if (p.size() < 3) recovery_invariant_broken("a polygon piece with fewer than three corners");
    std::size_t k = 0;
    for (std::size_t i = 1; i < p.size(); ++i)
      if (plane.lexicographically_less(q(p[i]), q(p[k]))) k = i;
    const std::size_t n = p.size();
    const VertexId u = p[(k + n - 1) % n], v = p[k], w = p[(k + 1) % n];
    if (o(u, v, w) <= 0) recovery_invariant_broken("the lowest corner of a surface polygon is not convex");
    if (n == 3) {
      out.push_back({u, v, w});
      continue;
    }
    std::size_t best = n;
    mpq_class best_height;
    for (std::size_t i = 0; i < n; ++i) {
      const VertexId x = p[i];
      if (x == u || x == v || x == w) continue;
      if (o(u, v, x) < 0 || o(v, w, x) < 0 || o(w, u, x) < 0) continue;
      const mpq_class height = plane.sign * plane.orient(q(w), q(u), q(x));
      if (best == n || height > best_height) best = i, best_height = height;
    }
    if (best == n) {  // an ear
      out.push_back({u, v, w});
      p.erase(p.begin() + static_cast<std::ptrdiff_t>(k));
      pending.push_back(std::move(p));
      continue;
    }
    Polygon first, second;  // v .. x and x .. v
    for (std::size_t i = k;; i = (i + 1) % n) {
      first.push_back(p[i]);
      if (i == best) break;
    }
    for (std::size_t i = best;; i = (i + 1) % n) {
      second.push_back(p[i]);
      if (i == k) break;
    }
    pending.push_back(std::move(first));
    pending.push_back(std::move(second));
  }
  return out;
}

struct Fan {
  std::uint32_t triangle = 0;
  std::map<std::uint32_t, VertexId> next;  // link edge x -> y of the boundary face (v, x, y)
};

// The boundary faces at v grouped by the surface triangle they lie in.
std::vector<Fan> fans_of(const RecoveryMesh& m, const RecoverySurface3& s, VertexId v) {
  std::vector<Fan> fans;
  for (const ElementId t : m.star(v)) {
    const auto c = m.mesh.vertices(t);
    for (int j = 0; j < 4; ++j) {
      if (c[static_cast<std::size_t>(j)] == v || !m.mesh.neighbour(t, j).is_none()) continue;
      auto f = m.mesh.facet(t, j);
      while (f[0] != v) std::rotate(f.begin(), f.begin() + 1, f.end());
      const std::int64_t triangle = surface_triangle_of(m, s, f[0], f[1], f[2]);
      if (triangle < 0) recovery_invariant_broken("a boundary face at a Steiner point is in no surface triangle");
      auto fan = std::find_if(fans.begin(), fans.end(), [&](const Fan& x) { return x.triangle == triangle; });
      if (fan == fans.end()) fan = fans.insert(fans.end(), Fan{static_cast<std::uint32_t>(triangle), {}});
      if (!fan->next.emplace(f[1].value, f[2]).second) recovery_invariant_broken("a pinched surface at a Steiner point");
    }
  }
  return fans;
}

// The polygon of a fan without v: its link, a cycle (v inside the triangle) or a path whose
// ends are v's neighbours on its surface edge (the closing side then passes through v).
Polygon polygon_of(const Fan& fan) {
  std::map<std::uint32_t, int> incoming;
  for (const auto& [x, y] : fan.next) incoming[y.value]++;
  VertexId start{fan.next.begin()->first};  // a cycle starts anywhere
  for (const auto& [x, y] : fan.next)
    if (!incoming.count(x)) {  // a path starts where no link edge comes in
      start = VertexId{x};
      break;
    }
  Polygon p{start};
  for (auto it = fan.next.find(start.value); it != fan.next.end() && it->second != start;
       it = fan.next.find(it->second.value)) {
    p.push_back(it->second);
    if (p.size() > fan.next.size() + 1) recovery_invariant_broken("a broken link at a Steiner point");
  }
  return p;
}

Point3 normalized(const Point3& p) {
  const double l = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
  return l > 0 ? Point3{p.x / l, p.y / l, p.z / l} : Point3{0, 0, 0};
}

Point3 inward_normal(const RecoverySurface3& s, std::uint32_t triangle) {
  const auto& t = s.triangles[triangle];
  const Point3 &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
  // Scaled by the largest coordinate difference first, so no product under- or overflows.
  const double scale = std::max({std::fabs(b.x - a.x), std::fabs(b.y - a.y), std::fabs(b.z - a.z),
                                 std::fabs(c.x - a.x), std::fabs(c.y - a.y), std::fabs(c.z - a.z)});
  const Point3 u{(b.x - a.x) / scale, (b.y - a.y) / scale, (b.z - a.z) / scale};
  const Point3 w{(c.x - a.x) / scale, (c.y - a.y) / scale, (c.z - a.z) / scale};
  return normalized({-(u.y * w.z - u.z * w.y), -(u.z * w.x - u.x * w.z), -(u.x * w.y - u.y * w.x)});
}

using Tetrahedron = topology::TetrahedralMesh3::Element;

// Whether every tetrahedron of `star` is positive with v at p (exact).
bool positive_with(const RecoveryMesh& m, const std::vector<Tetrahedron>& star, VertexId v, const Point3& p) {
  for (Tetrahedron c : star) {
    const std::size_t k = static_cast<std::size_t>(std::find(c.begin(), c.end(), v) - c.begin());
    // volume(c) = -orient(c); with v moved to the last place by one swap, +orient.
    int sign;
    if (k == 3) {
      sign = -m.orient(c[0], c[1], c[2], p);
    } else {
      c[k] = c[3];
      sign = m.orient(c[0], c[1], c[2], p);
    }
    if (sign <= 0) return false;
  }
  return true;
}

// Whether the box of doubles next to p (which holds p's half-ulp rounding box) is strictly on
// the inner side of each of the triangles' planes: the certificate (design decision 2) takes a
// vertex whose rounding box meets a surface triangle as lying on it, and a moved Steiner point
// must not (exact orient3d on the box's corners).
bool clear_of(const RecoverySurface3& s, const std::vector<std::uint32_t>& triangles, const Point3& p) {
  const double xs[2] = {std::nextafter(p.x, -INFINITY), std::nextafter(p.x, INFINITY)};
  const double ys[2] = {std::nextafter(p.y, -INFINITY), std::nextafter(p.y, INFINITY)};
  const double zs[2] = {std::nextafter(p.z, -INFINITY), std::nextafter(p.z, INFINITY)};
  for (const std::uint32_t t : triangles) {
    const auto& c = s.triangles[t];
    for (const double x : xs)
      for (const double y : ys)
        for (const double z : zs)
          if (predicates::orient3d(s.points[c[0]], s.points[c[1]], s.points[c[2]], {x, y, z}) != predicates::Sign::positive)
            return false;
  }
  return true;
}

// A double point for v inside its star, or false. Along each direction the good positions
// are an interval (0, e_max) of steps (the star's kernel is convex and v is on its boundary);
// halving from the star's reach finds a step in (e_max / 2, e_max], and half of it, in
// (e_max / 4, e_max / 2], keeps a margin from both ends.
bool find_position(const RecoveryMesh& m, const RecoverySurface3& s, const std::vector<std::uint32_t>& triangles, VertexId v,
                   const std::vector<Tetrahedron>& star, const Point3& inward, Point3* out) {
  auto good = [&](const Point3& p) { return positive_with(m, star, v, p) && clear_of(s, triangles, p); };
  if (star.empty()) recovery_invariant_broken("a Steiner point in no tetrahedron");
  const Point3 at = m.vertices[v.value].approx;
  Point3 centroid{0, 0, 0};
  double reach = 0;
  std::size_t count = 0;
  for (const Tetrahedron& t : star)
    for (const VertexId c : t) {
      if (c == v) continue;
      const Point3& p = m.vertices[c.value].approx;
      centroid = {centroid.x + p.x, centroid.y + p.y, centroid.z + p.z};
      ++count;
      reach = std::max(reach, std::max({std::fabs(p.x - at.x), std::fabs(p.y - at.y), std::fabs(p.z - at.z)}));
    }
  centroid = {centroid.x / double(count), centroid.y / double(count), centroid.z / double(count)};
  const Point3 directions[2] = {
      {inward.x * reach, inward.y * reach, inward.z * reach},
      {centroid.x - at.x, centroid.y - at.y, centroid.z - at.z}};
  auto candidate = [&](const Point3& d, double step) {
    return Point3{at.x + step * d.x, at.y + step * d.y, at.z + step * d.z};
  };
  for (const Point3& d : directions) {
    double step = 1.0;
    // At most ~1100 halvings take any finite step below the smallest subnormal.
    for (int i = 0; i < 1100 && step > 0; ++i, step *= 0.5) {
      const Point3 p = candidate(d, step);
      if (p.x == at.x && p.y == at.y && p.z == at.z) break;  // below the double spacing at v
      if (!good(p)) continue;
      const Point3 half = candidate(d, step / 2);
      *out = good(half) ? half : p;
      return true;
    }
  }
  return false;
}

// Takes v off the surface, or returns false and changes nothing when its star holds no
// double position now (a later round may find one, after its neighbours moved).
bool take_off_surface(RecoveryMesh& m, const RecoverySurface3& s, VertexId v, BoundaryRecoveryCounts& counts,
                      std::vector<std::uint32_t>* on_triangles) {
  const bool on_edge = m.vertices[v.value].origin == RecoveryVertex::Origin::on_edge;
  Point3 inward{0, 0, 0};
  std::vector<std::uint32_t> triangles;
  std::vector<Tetrahedron> star, added;
  for (const ElementId t : m.star(v)) star.push_back(m.mesh.vertices(t));
  for (const Fan& fan : fans_of(m, s, v)) {
    triangles.push_back(fan.triangle);
    const Plane2 plane = plane_of(s, fan.triangle);
    const Point3 n = inward_normal(s, fan.triangle);
    inward = {inward.x + n.x, inward.y + n.y, inward.z + n.z};
    const Polygon polygon = polygon_of(fan);
    if (polygon.size() != fan.next.size() + (on_edge ? 1 : 0))
      recovery_invariant_broken("the surface around Steiner point " + std::to_string(v.value) + " is not a fan");
    for (const Triangle& t : triangulate(m, plane, polygon)) added.push_back({t[1], t[0], t[2], v});
  }
  star.insert(star.end(), added.begin(), added.end());
  inward = normalized(inward);
  Point3 p;
  if (!find_position(m, s, triangles, v, star, inward, &p)) return false;
  for (const Tetrahedron& t : added) m.mesh.add_element(t);
  m.set_double_point(v, p, RecoveryVertex::Origin::interior);
  *on_triangles = std::move(triangles);
  ++counts.moved_inside;
  return true;
}

// Moves an earlier-moved Steiner point w towards the centroid of its star (half way, or less
// if that is not good), to give a neighbour that found no position more room.
void recentre(RecoveryMesh& m, const RecoverySurface3& s, VertexId w, const std::vector<std::uint32_t>& triangles) {
  std::vector<Tetrahedron> star;
  for (const ElementId t : m.star(w)) star.push_back(m.mesh.vertices(t));
  if (star.empty()) return;
  const Point3 at = m.vertices[w.value].approx;
  Point3 c{0, 0, 0};
  double count = 0;
  for (const Tetrahedron& t : star)
    for (const VertexId x : t)
      if (x != w) {
        const Point3& p = m.vertices[x.value].approx;
        c = {c.x + p.x, c.y + p.y, c.z + p.z};
        count += 1;
      }
  c = {c.x / count, c.y / count, c.z / count};
  for (double step = 0.5; step > 0x1p-60; step *= 0.5) {
    const Point3 p{at.x + step * (c.x - at.x), at.y + step * (c.y - at.y), at.z + step * (c.z - at.z)};
    if (positive_with(m, star, w, p) && clear_of(s, triangles, p)) {
      m.set_double_point(w, p, RecoveryVertex::Origin::interior);
      return;
    }
  }
}

[[noreturn]] void cannot_move(const RecoveryMesh& m, VertexId v) {
  const RecoveryVertex& r = m.vertices[v.value];
  const Point3& a = r.approx;
  throw BoundaryRecoveryError(
      "error: boundary recovery cannot take the Steiner point near (" + std::to_string(a.x) + ", " +
      std::to_string(a.y) + ", " + std::to_string(a.z) + ") on surface " +
      (r.origin == RecoveryVertex::Origin::on_edge ? "edge " : "triangle ") + std::to_string(r.on) +
      " off the surface: no double point inside its star keeps every tetrahedron positive (the surface has "
      "features there closer than the double spacing); --refine-surface keeps it on the surface");
}

}  // namespace

void remove_surface_steiner_points(RecoveryMesh& m, const RecoverySurface3& s, BoundaryRecoveryCounts& counts) {
  // In rounds, each an independent set of the Steiner points still on the surface (no two in
  // one tetrahedron): a point must end deeper than the surface points of its polygon, so a
  // chain of points taken one after the other would force depths shrinking geometrically
  // along it (proofs/boundary_recovery_3.md section 5); rounds bound the chain by their number.
  std::vector<std::uint32_t> pending;
  for (std::uint32_t v = 0; v < m.vertices.size(); ++v)
    if (m.vertices[v].origin == RecoveryVertex::Origin::on_edge || m.vertices[v].origin == RecoveryVertex::Origin::on_face)
      pending.push_back(v);
  std::vector<char> taken(m.vertices.size(), 0);
  std::map<std::uint32_t, std::vector<std::uint32_t>> moved_from;  // a moved point's surface triangles
  while (!pending.empty()) {  // each round moves at least one point: at most |pending| rounds
    std::vector<std::uint32_t> round, rest;
    for (const std::uint32_t v : pending) {
      bool free = true;
      for (const ElementId t : m.star(VertexId{v}))
        for (const VertexId c : m.mesh.vertices(t)) free = free && !taken[c.value];
      if (free) {
        taken[v] = 1;
        round.push_back(v);
      } else {
        rest.push_back(v);
      }
    }
    std::size_t moved = 0;
    std::vector<std::uint32_t> failed;
    for (const std::uint32_t v : round) {
      bool done = take_off_surface(m, s, VertexId{v}, counts, &moved_from[v]);
      if (!done) {  // give it room: recentre the moved Steiner points of its star, then retry once
        for (const ElementId t : m.star(VertexId{v}))
          for (const VertexId w : m.mesh.vertices(t))
            if (moved_from.count(w.value) && !moved_from[w.value].empty()) recentre(m, s, w, moved_from[w.value]);
        done = take_off_surface(m, s, VertexId{v}, counts, &moved_from[v]);
      }
      if (done)
        ++moved;
      else
        failed.push_back(v);
    }
    for (const std::uint32_t v : round) taken[v] = 0;
    // A point that found no position waits for a later round; a round that moves nothing
    // would repeat itself, so the measure |pending| must fall every round.
    if (moved == 0) cannot_move(m, VertexId{failed.front()});
    rest.insert(rest.begin(), failed.begin(), failed.end());
    pending = std::move(rest);
  }
}

}  // namespace certimesh::generators::detail
