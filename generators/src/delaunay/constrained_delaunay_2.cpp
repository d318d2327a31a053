// Incremental Bowyer-Watson insertion in a biased randomized Hilbert order (hilbert_order.h)
// over a triangulation closed by ghost triangles; constraints recovered by flips (Sloan's
// method: flip crossing edges of convex quadrilaterals until none crosses, then Lawson flips
// restore the constrained Delaunay property). Every sign is exact; symbolic perturbation
// makes the input generic, so the triangulation is unique and the same for every input
// order.
#include "certimesh/generators/delaunay/constrained_delaunay_2.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <sstream>

#include "certimesh/generators/delaunay/perturbed_predicates.h"
#include "certimesh/predicates/orient2d.h"
#include "hilbert_order.h"

namespace certimesh::generators {

namespace {

using predicates::to_int;

constexpr std::uint32_t ghost = ConstrainedDelaunay2::none;

using detail::incircle_perturbed;
using detail::orient_perturbed;

int orient_exact(const Point2& a, const Point2& b, const Point2& c) {
  return to_int(predicates::orient2d(a, b, c));
}

// For p collinear with a and b: whether p lies strictly between them (coordinate
// comparisons along an axis where a and b differ: exact).
bool strictly_between(const Point2& a, const Point2& b, const Point2& p) {
  if (a.x != b.x) return std::min(a.x, b.x) < p.x && p.x < std::max(a.x, b.x);
  return std::min(a.y, b.y) < p.y && p.y < std::max(a.y, b.y);
}

std::string describe_point2(const Point2& p) {
  std::ostringstream out;
  out.precision(17);
  out << '(' << p.x << ' ' << p.y << ')';
  return out.str();
}

constexpr std::uint32_t next_local(std::uint32_t i) { return i == 2 ? 0 : i + 1; }
constexpr std::uint32_t prev_local(std::uint32_t i) { return i == 0 ? 2 : i - 1; }

}  // namespace

ConstrainedDelaunay2::ConstrainedDelaunay2(std::span<const Point2> points, const ProgressCallback& progress) {
  build(points, progress);
}

void ConstrainedDelaunay2::throw_duplicate(VertexId a, VertexId b) const {
  const VertexId ea = external_[a], eb = external_[b];
  throw DelaunayError("delaunay: points " + std::to_string(std::min(ea, eb)) + " and " +
                      std::to_string(std::max(ea, eb)) + " are the same point " + describe_point2(points_[a]));
}

std::string ConstrainedDelaunay2::constraint_name(VertexId a, VertexId b) const {
  return "constraint " + std::to_string(external_[a]) + "-" + std::to_string(external_[b]) + " " +
         describe_point2(pt(a)) + "-" + describe_point2(pt(b));
}

void ConstrainedDelaunay2::build(std::span<const Point2> input, const ProgressCallback& progress) {
  for (std::size_t i = 0; i < input.size(); ++i)
    if (!std::isfinite(input[i].x) || !std::isfinite(input[i].y))
      throw DelaunayError("delaunay: point " + std::to_string(i) + " " + describe_point2(input[i]) + " is not finite");
  if (input.size() >= ghost) throw DelaunayError("delaunay: too many points");
  // Internal ids follow the insertion order.
  external_ = detail::hilbert_order(input);
  internal_.assign(input.size(), none);
  points_.resize(input.size());
  for (std::size_t k = 0; k < input.size(); ++k) {
    internal_[external_[k]] = static_cast<VertexId>(k);
    points_[k] = input[external_[k]];
  }
  vertex_triangle_.assign(points_.size(), none);
  // Internal ids are the insertion order. The first triangle: the first two points and the
  // first point off their line.
  const std::size_t n = points_.size();
  std::size_t third = n;
  if (n >= 2 && pt(0) == pt(1)) throw_duplicate(0, 1);
  for (std::size_t k = 2; k < n; ++k)
    if (orient_exact(pt(0), pt(1), pt(static_cast<VertexId>(k))) != 0) {
      third = k;
      break;
    }
  if (third == n) {  // all collinear: no triangle, but duplicates are still refused
    std::vector<std::uint32_t> sorted(n);  // internal ids
    for (std::size_t k = 0; k < n; ++k) sorted[k] = static_cast<std::uint32_t>(k);
    std::sort(sorted.begin(), sorted.end(), [&](std::uint32_t i, std::uint32_t j) {
      return pt(i).x != pt(j).x ? pt(i).x < pt(j).x : (pt(i).y != pt(j).y ? pt(i).y < pt(j).y : i < j);
    });
    for (std::size_t k = 1; k < sorted.size(); ++k)
      if (pt(sorted[k - 1]) == pt(sorted[k])) throw_duplicate(sorted[k - 1], sorted[k]);
    return;
  }
  flags_.reserve(2 * points_.size() + 8);
  corner_.reserve(3 * flags_.capacity());
  adjacent_.reserve(3 * flags_.capacity());
  make_first_triangle(0, 1, static_cast<VertexId>(third));
  for (std::size_t k = 2; k < n; ++k) {
    if (k == third) continue;
    insert_vertex(static_cast<VertexId>(k), last_, false);
    if ((k & 0xffff) == 0) report(progress, "delaunay", k, n);
  }
  report(progress, "delaunay", n, n);
}

ConstrainedDelaunay2::TriangleId ConstrainedDelaunay2::new_slot() {
  if (!free_slots_.empty()) {
    const TriangleId t = free_slots_.back();
    free_slots_.pop_back();
    return t;
  }
  const auto t = static_cast<TriangleId>(flags_.size());
  flags_.push_back(0);
  // push_back, not resize: resize fills (a memset of the whole growth) and was ~10 % of
  // the construction time; the entries are written right after anyway.
  for (int i = 0; i < 3; ++i) corner_.push_back(none), adjacent_.push_back(none);
  return t;
}

void ConstrainedDelaunay2::link(std::uint32_t half_edge_a, std::uint32_t half_edge_b) {
  adjacent_[half_edge_a] = half_edge_b;
  adjacent_[half_edge_b] = half_edge_a;
}

void ConstrainedDelaunay2::make_first_triangle(VertexId a, VertexId b, VertexId c) {
  if (orient_exact(pt(a), pt(b), pt(c)) < 0) std::swap(a, b);
  const TriangleId t = new_slot();
  const std::array<VertexId, 3> q{a, b, c};
  for (std::uint32_t i = 0; i < 3; ++i) corner_[3 * t + i] = q[i];
  // Ghost i lies across the edge opposite corner i: (q[i+2], q[i+1], ghost).
  std::array<TriangleId, 3> g{};
  for (std::uint32_t i = 0; i < 3; ++i) {
    g[i] = new_slot();
    flags_[g[i]] = ghost_flag;
    corner_[3 * g[i]] = q[prev_local(i)];
    corner_[3 * g[i] + 1] = q[next_local(i)];
    corner_[3 * g[i] + 2] = ghost;
    link(3 * t + i, 3 * g[i] + 2);
  }
  for (std::uint32_t i = 0; i < 3; ++i) link(3 * g[i], 3 * g[prev_local(i)] + 1);
  for (VertexId v : q) vertex_triangle_[v] = t;
  last_ = t;
}

inline bool ConstrainedDelaunay2::in_circle(TriangleId t, const Point2& p, VertexId pid) const {
  const VertexId* c = &corner_[3 * std::size_t{t}];
  if (flags_[t] & ghost_flag) {
    // The limit of the circumcircle through the hull edge (u, v) and the infinite vertex:
    // the open half-plane outside the hull.
    const std::uint32_t k = c[0] == ghost ? 0 : (c[1] == ghost ? 1 : 2);
    const VertexId u = c[next_local(k)], v = c[prev_local(k)];
    const int s = orient_perturbed(pt(u), pt(v), p);
    if (s == 0) throw_duplicate(pt(u) == p ? u : v, pid);
    return s > 0;
  }
  const int s = incircle_perturbed(pt(c[0]), pt(c[1]), pt(c[2]), p);
  if (s == 0) throw_duplicate(pt(c[0]) == p ? c[0] : (pt(c[1]) == p ? c[1] : c[2]), pid);
  return s > 0;
}

// Stochastic order of the edge tests: a deterministic visibility walk may cycle in a
// constrained (non-Delaunay) triangulation; a seeded generator keeps the result
// reproducible. With `remember` it is the remembering stochastic walk (Devillers, Pion and
// Teillaud, "Walking in a triangulation"): it skips the edge it came through, which has p on
// its inner side already, so each step after the first tests at most two edges; it stops
// where the plain walk would (p inside or on the triangle, or across a hull edge), by the
// same exact signs. It terminates in a Delaunay triangulation; for any other (a constrained
// one) its step count is capped, and past the cap the plain walk continues, whose
// termination with probability 1 holds in any triangulation.
ConstrainedDelaunay2::TriangleId ConstrainedDelaunay2::walk(const Point2& p, TriangleId start,
                                                            VertexId* equal_vertex, bool remember) const {
  TriangleId t = start;
  if (t == none || t >= flags_.size() || (flags_[t] & dead_flag)) t = last_;
  if (flags_[t] & ghost_flag) {
    const std::uint32_t k = corner_[3 * t] == ghost ? 0 : (corner_[3 * t + 1] == ghost ? 1 : 2);
    t = adjacent_[3 * t + k] / 3;
  }
  static constexpr std::uint32_t plus[5] = {0, 1, 2, 0, 1};  // (i + k) % 3 for i, k < 3
  const std::size_t cap = 4 * flags_.size() + 64;
  std::uint32_t state = 0x9e3779b9u;
  std::uint32_t entry = 3;  // with `remember`: the local index of the edge crossed into t
  for (std::size_t step = 0;; ++step) {
    if (flags_[t] & ghost_flag) return t;
    if (step > cap) remember = false, entry = 3;
    state ^= state << 13, state ^= state >> 17, state ^= state << 5;
    const std::uint32_t first = state % 3;
    const VertexId* c = &corner_[3 * std::size_t{t}];
    bool moved = false;
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t i = plus[first + k];
      if (i == entry) continue;
      const VertexId a = c[plus[i + 1]], b = c[plus[i + 2]];
      const int s = orient_perturbed(pt(a), pt(b), p);
      if (s < 0) {
        const std::uint32_t h = adjacent_[3 * t + i];
        t = h / 3;
        if (remember) entry = h % 3;
        moved = true;
        break;
      }
      if (s == 0) [[unlikely]] {
        *equal_vertex = pt(a) == p ? a : b;
        return t;
      }
    }
    if (!moved) return t;
  }
}

ConstrainedDelaunay2::TriangleId ConstrainedDelaunay2::locate(const Point2& p, TriangleId hint) const {
  if (flags_.empty() || !std::isfinite(p.x) || !std::isfinite(p.y)) return none;
  VertexId equal = none;
  return walk(p, hint, &equal);
}

void ConstrainedDelaunay2::insert_vertex(VertexId v, TriangleId start, bool respect_constraints) {
  const Point2 p = pt(v);
  VertexId equal = none;
  const TriangleId first = walk(p, start, &equal, true);
  if (equal != none) throw_duplicate(equal, v);
  // The cavity: the triangles whose (perturbed) circumcircle holds p, reachable from the
  // one containing p -- without crossing a constrained edge when constraints count. A
  // depth-first search that looks across the edges of each triangle in counterclockwise
  // order, after the one it entered by, meets the cavity's boundary edges in
  // counterclockwise order around p (the cavity is a disk), so consecutive new triangles
  // are neighbours. A triangle tested twice (it shares two edges with the cavity) gets the
  // same exact answer both times; the cavity flag keeps the search a search on a graph
  // whatever the cavity's shape.
  cavity_.clear();
  boundary_.clear();
  dig_.clear();
  dig_.push_back({first, 0, 3});
  flags_[first] |= cavity_flag;
  cavity_.push_back(first);
  try {
    dig_cavity(p, v, respect_constraints);
  } catch (...) {  // a duplicate point: leave no flag behind
    for (TriangleId t : cavity_) flags_[t] = static_cast<std::uint8_t>(flags_[t] & ~cavity_flag);
    throw;
  }
  finish_star(v);
}

void ConstrainedDelaunay2::dig_cavity(const Point2& p, VertexId v, bool respect_constraints) {
  while (!dig_.empty()) {
    DigFrame& f = dig_.back();
    if (f.left == 0) {
      dig_.pop_back();
      continue;
    }
    const TriangleId t = f.t;
    const std::uint32_t i = f.local;
    f.local = next_local(i);
    --f.left;
    const std::uint32_t h = 3 * t + i;
    const std::uint32_t across = adjacent_[h];
    const TriangleId n = across / 3;
    const bool constrained = (flags_[t] >> i) & 1u;
    if (!(respect_constraints && constrained)) {
      if (flags_[n] & cavity_flag) continue;  // an edge inside the cavity
      if (in_circle(n, p, v)) {
        flags_[n] |= cavity_flag;
        cavity_.push_back(n);
        dig_.push_back({n, next_local(across % 3), 2});
        continue;
      }
    }
    boundary_.push_back({corner_[3 * t + next_local(i)], corner_[3 * t + prev_local(i)], across, constrained});
  }
}

void ConstrainedDelaunay2::finish_star(VertexId v) {
  // The star of p: one triangle (p, a, b) per boundary edge, in the cavity's slots first.
  const std::size_t m = boundary_.size();
  for (std::size_t k = m; k < cavity_.size(); ++k) {  // not for a disk (m = cavity + 2)
    flags_[cavity_[k]] = dead_flag;
    free_slots_.push_back(cavity_[k]);
  }
  cavity_.resize(m, none);
  TriangleId real = none;
  for (std::size_t k = 0; k < m; ++k) {
    const BoundaryEdge& e = boundary_[k];
    if (cavity_[k] == none) cavity_[k] = new_slot();
    const TriangleId t = cavity_[k];
    corner_[3 * t] = v;
    corner_[3 * t + 1] = e.a;
    corner_[3 * t + 2] = e.b;
    const bool is_ghost_triangle = e.a == ghost || e.b == ghost;
    flags_[t] = static_cast<std::uint8_t>((e.constrained ? 1u : 0u) | (is_ghost_triangle ? ghost_flag : 0u));
    link(3 * t, e.outer);
    if (e.a != ghost) vertex_triangle_[e.a] = t;
    if (!is_ghost_triangle) real = t;
  }
  // Triangle k's edge (b, p) is triangle k + 1's edge (p, a): b_k = a_(k+1).
  for (std::size_t k = 0; k < m; ++k) {
    const std::size_t next = k + 1 == m ? 0 : k + 1;
    if (boundary_[k].b != boundary_[next].a) throw std::logic_error("delaunay: the cavity is not a disk");
    link(3 * cavity_[k] + 1, 3 * cavity_[next] + 2);
  }
  const TriangleId some = real != none ? real : cavity_[m - 1];
  vertex_triangle_[v] = some;
  last_ = some;
}

bool ConstrainedDelaunay2::is_live(TriangleId t) const {
  if (t >= flags_.size() || (flags_[t] & (dead_flag | ghost_flag))) return false;
  const Point2 &a = pt(corner_[3 * t]), &b = pt(corner_[3 * t + 1]), &c = pt(corner_[3 * t + 2]);
  return orient_exact(a, b, c) != 0;
}

ConstrainedDelaunay2::TriangleId ConstrainedDelaunay2::neighbour(TriangleId t, int i) const {
  const TriangleId n = adjacent_[3 * std::size_t{t} + static_cast<std::size_t>(i)] / 3;
  return is_live(n) ? n : none;
}

ConstrainedDelaunay2::TriangleId ConstrainedDelaunay2::incident_triangle(VertexId public_v) const {
  const VertexId v = internal_[public_v];
  const TriangleId start = vertex_triangle_[v];
  if (start == none) return none;
  TriangleId t = start;
  do {
    if (is_live(t)) return t;
    const std::uint32_t k = corner_[3 * t] == v ? 0 : (corner_[3 * t + 1] == v ? 1 : 2);
    t = adjacent_[3 * t + next_local(k)] / 3;  // across the edge (c[k+2], v): the next around v
  } while (t != start);
  return none;
}

std::uint32_t ConstrainedDelaunay2::find_half_edge(VertexId u, VertexId v) const {
  const TriangleId start = vertex_triangle_[u];
  if (start == none) return none;
  TriangleId t = start;
  do {
    const std::uint32_t k = corner_[3 * t] == u ? 0 : (corner_[3 * t + 1] == u ? 1 : 2);
    if (corner_[3 * t + next_local(k)] == v) return 3 * t + prev_local(k);
    t = adjacent_[3 * t + next_local(k)] / 3;
  } while (t != start);
  return none;
}

void ConstrainedDelaunay2::flip(std::uint32_t h) {
  const TriangleId t1 = h / 3, t2 = adjacent_[h] / 3;
  const std::uint32_t i = h % 3, j = adjacent_[h] % 3;
  const VertexId x = corner_[3 * t1 + i], u = corner_[3 * t1 + next_local(i)], v = corner_[3 * t1 + prev_local(i)];
  const VertexId y = corner_[3 * t2 + j];
  auto outer = [&](TriangleId t, std::uint32_t l) {
    return std::pair{adjacent_[3 * t + l], static_cast<std::uint8_t>((flags_[t] >> l) & 1u)};
  };
  const auto a = outer(t1, next_local(i)), b = outer(t1, prev_local(i));  // (v, x), (x, u)
  const auto c = outer(t2, next_local(j)), d = outer(t2, prev_local(j));  // (u, y), (y, v)
  // t1 becomes (x, u, y), t2 becomes (y, v, x); the new edge (x, y) is unconstrained.
  corner_[3 * t1] = x, corner_[3 * t1 + 1] = u, corner_[3 * t1 + 2] = y;
  corner_[3 * t2] = y, corner_[3 * t2 + 1] = v, corner_[3 * t2 + 2] = x;
  flags_[t1] = static_cast<std::uint8_t>(c.second | (b.second << 2));
  flags_[t2] = static_cast<std::uint8_t>(a.second | (d.second << 2));
  link(3 * t1, c.first);
  link(3 * t1 + 2, b.first);
  link(3 * t2, a.first);
  link(3 * t2 + 2, d.first);
  link(3 * t1 + 1, 3 * t2 + 1);
  vertex_triangle_[x] = t1, vertex_triangle_[u] = t1, vertex_triangle_[y] = t1, vertex_triangle_[v] = t2;
  last_ = t1;
}

void ConstrainedDelaunay2::restore_delaunay(std::vector<std::array<VertexId, 2>> edges) {
  while (!edges.empty()) {
    const auto [u, v] = edges.back();
    edges.pop_back();
    const std::uint32_t h = find_half_edge(u, v);
    if (h == none) continue;  // flipped away meanwhile
    const TriangleId t1 = h / 3, t2 = adjacent_[h] / 3;
    if (((flags_[t1] >> (h % 3)) & 1u) || ((flags_[t1] | flags_[t2]) & ghost_flag)) continue;
    const VertexId x = corner_[h], y = corner_[adjacent_[h]];
    if (incircle_perturbed(pt(x), pt(u), pt(v), pt(y)) <= 0) continue;
    flip(h);
    edges.push_back({u, y});
    edges.push_back({y, v});
    edges.push_back({v, x});
    edges.push_back({x, u});
  }
}

std::vector<std::array<ConstrainedDelaunay2::VertexId, 2>> ConstrainedDelaunay2::crossing_edges(VertexId a,
                                                                                              VertexId b) const {
  const Point2 &pa = pt(a), &pb = pt(b);
  auto on_segment = [&](VertexId w) {
    throw DelaunayError("delaunay: " + constraint_name(a, b) + " passes through point " + std::to_string(external_[w]) + " " +
                        describe_point2(pt(w)));
  };
  std::vector<std::array<VertexId, 2>> crossed;
  auto cross = [&](TriangleId t, std::uint32_t local, VertexId l, VertexId r) {
    if ((flags_[t] >> local) & 1u)
      throw DelaunayError("delaunay: " + constraint_name(a, b) + " crosses " + constraint_name(l, r));
    crossed.push_back({l, r});
  };
  // The triangle around a whose wedge holds the direction of b.
  TriangleId t = vertex_triangle_[a];
  const TriangleId start = t;
  std::uint32_t crossed_local = none;
  do {
    const std::uint32_t k = corner_[3 * t] == a ? 0 : (corner_[3 * t + 1] == a ? 1 : 2);
    if (!(flags_[t] & ghost_flag)) {
      const VertexId v1 = corner_[3 * t + next_local(k)], v2 = corner_[3 * t + prev_local(k)];
      const int o1 = orient_exact(pa, pb, pt(v1)), o2 = orient_exact(pa, pb, pt(v2));
      if (o1 == 0 && strictly_between(pa, pb, pt(v1))) on_segment(v1);
      if (o2 == 0 && strictly_between(pa, pb, pt(v2))) on_segment(v2);
      if (o1 < 0 && o2 > 0) {
        crossed_local = k;
        break;
      }
    }
    t = adjacent_[3 * t + next_local(k)] / 3;
  } while (t != start);
  if (crossed_local == none)
    throw DelaunayError("delaunay: " + constraint_name(a, b) + " leaves the triangulation");
  VertexId r = corner_[3 * t + next_local(crossed_local)], l = corner_[3 * t + prev_local(crossed_local)];
  std::uint32_t h = 3 * t + crossed_local;
  for (;;) {
    cross(h / 3, h % 3, r, l);
    const std::uint32_t across = adjacent_[h];
    const TriangleId n = across / 3;
    if (flags_[n] & ghost_flag)
      throw DelaunayError("delaunay: " + constraint_name(a, b) + " leaves the triangulation");
    const std::uint32_t apex_local = across % 3;
    const VertexId w = corner_[across];
    if (w == b) return crossed;
    const int o = orient_exact(pa, pb, pt(w));
    if (o == 0) on_segment(w);
    // In n = (w, l, r): the edge (r, w) is opposite l, the edge (w, l) opposite r.
    if (o > 0) {
      h = 3 * n + next_local(apex_local);  // opposite l: edge (r, w)
      l = w;
    } else {
      h = 3 * n + prev_local(apex_local);  // opposite r: edge (w, l)
      r = w;
    }
  }
}

void ConstrainedDelaunay2::insert_constraint(VertexId public_a, VertexId public_b) {
  const VertexId a = public_a < internal_.size() ? internal_[public_a] : none;
  const VertexId b = public_b < internal_.size() ? internal_[public_b] : none;
  if (a == none || b == none)
    throw DelaunayError("delaunay: constraint " + std::to_string(public_a) + "-" + std::to_string(public_b) +
                        " names a point that does not exist");
  if (a == b) throw DelaunayError("delaunay: " + constraint_name(a, b) + " has zero length");
  if (flags_.empty() || vertex_triangle_[a] == none || vertex_triangle_[b] == none)
    throw DelaunayError("delaunay: " + constraint_name(a, b) + ": the triangulation has no triangle (fewer than three points, or all collinear)");
  auto mark = [&] {
    const std::uint32_t h = find_half_edge(a, b);
    if (h == none) return false;
    flags_[h / 3] = static_cast<std::uint8_t>(flags_[h / 3] | (1u << (h % 3)));
    const std::uint32_t twin = adjacent_[h];
    flags_[twin / 3] = static_cast<std::uint8_t>(flags_[twin / 3] | (1u << (twin % 3)));
    return true;
  };
  if (mark()) return;
  std::deque<std::array<VertexId, 2>> queue;
  for (const auto& e : crossing_edges(a, b)) queue.push_back(e);
  std::vector<std::array<VertexId, 2>> created;
  const Point2 &pa = pt(a), &pb = pt(b);
  // Sloan: each pass over the queue flips at least one edge (some crossing quadrilateral is
  // always convex), so queue.size()^2 attempts bound the loop.
  const std::size_t bound = (queue.size() + 2) * (queue.size() + 2) + 16;
  for (std::size_t attempt = 0; !queue.empty(); ++attempt) {
    if (attempt > bound) throw std::logic_error("delaunay: constraint recovery did not converge");
    const auto [u, v] = queue.front();
    queue.pop_front();
    const std::uint32_t h = find_half_edge(u, v);
    const VertexId x = corner_[h], y = corner_[adjacent_[h]];
    if (orient_exact(pt(x), pt(y), pt(u)) * orient_exact(pt(x), pt(y), pt(v)) >= 0) {
      queue.push_back({u, v});  // not strictly convex: later
      continue;
    }
    flip(h);
    const bool still_crosses = x != a && x != b && y != a && y != b &&
                               orient_exact(pa, pb, pt(x)) * orient_exact(pa, pb, pt(y)) < 0;
    if (still_crosses) queue.push_back({x, y});
    else created.push_back({x, y});
  }
  if (!mark()) throw std::logic_error("delaunay: constraint recovery lost the segment");
  restore_delaunay(std::move(created));
}

ConstrainedDelaunay2::VertexId ConstrainedDelaunay2::insert_point(const Point2& p, TriangleId hint) {
  if (flags_.empty() || !std::isfinite(p.x) || !std::isfinite(p.y) || points_.size() + 1 >= ghost) return none;
  VertexId equal = none;
  const TriangleId t = walk(p, hint, &equal);
  if (equal != none || !is_live(t)) return none;
  for (std::uint32_t i = 0; i < 3; ++i)
    if (is_constrained(t, static_cast<int>(i)) &&
        orient_exact(pt(corner_[3 * t + next_local(i)]), pt(corner_[3 * t + prev_local(i)]), p) == 0)
      return none;
  const auto v = static_cast<VertexId>(points_.size());
  points_.push_back(p);
  external_.push_back(v);
  internal_.push_back(v);
  vertex_triangle_.push_back(none);
  insert_vertex(v, t, true);
  return v;
}

void ConstrainedDelaunay2::set_constrained(std::uint32_t h, bool constrained) {
  for (const std::uint32_t e : {h, adjacent_[h]}) {
    const auto bit = static_cast<std::uint8_t>(1u << (e % 3));
    flags_[e / 3] = static_cast<std::uint8_t>(constrained ? flags_[e / 3] | bit : flags_[e / 3] & ~bit);
  }
}

// Whether p may be inserted on the side of half-edge h = (u, v) (seen from its triangle's
// interior) when it splits the constrained edge (u, v): strictly inside that triangle when it
// is live (the other two edges have p strictly on their inner side, exactly), anywhere when it
// is a ghost (p beyond a hull edge: the ghost's half-plane holds it), never when it is a flat
// triangle of a collinear hull piece.
bool ConstrainedDelaunay2::fits_beside(std::uint32_t h, const Point2& p) const {
  const TriangleId t = h / 3;
  if (flags_[t] & ghost_flag) return true;
  if (!is_live(t)) return false;
  const std::uint32_t i = h % 3;
  const Point2 &x = pt(corner_[3 * t + i]), &u = pt(corner_[3 * t + next_local(i)]), &v = pt(corner_[3 * t + prev_local(i)]);
  return orient_exact(v, x, p) > 0 && orient_exact(x, u, p) > 0;
}

ConstrainedDelaunay2::VertexId ConstrainedDelaunay2::split_constraint(VertexId public_a, VertexId public_b,
                                                                      const Point2& p) {
  if (public_a >= internal_.size() || public_b >= internal_.size() || flags_.empty()) return none;
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || points_.size() + 1 >= ghost) return none;
  const VertexId a = internal_[public_a], b = internal_[public_b];
  const std::uint32_t h = find_half_edge(a, b);  // in the triangle left of a -> b
  if (h == none || !((flags_[h / 3] >> (h % 3)) & 1u) || p == pt(a) || p == pt(b)) return none;
  // With (a, b) unconstrained, the cavity of p holds the triangle on p's side of the edge
  // (p inside it, or beyond the hull edge), or, p on the open edge, every live triangle of the
  // edge (an open chord is strictly inside the circle): a and b are on the cavity's boundary,
  // so the star of p has the edges (a, p) and (p, b). Everything else is the ordinary
  // constrained Delaunay insertion.
  const int side = orient_exact(pt(a), pt(b), p);
  if (side == 0 && (!strictly_between(pt(a), pt(b), p) || (!is_live(h / 3) && !is_live(adjacent_[h] / 3)))) return none;
  if (side > 0 && !fits_beside(h, p)) return none;
  if (side < 0 && !fits_beside(adjacent_[h], p)) return none;
  set_constrained(h, false);
  const auto v = static_cast<VertexId>(points_.size());
  points_.push_back(p);
  external_.push_back(v);
  internal_.push_back(v);
  vertex_triangle_.push_back(none);
  insert_vertex(v, side < 0 ? adjacent_[h] / 3 : h / 3, true);  // the walk starts on p's side
  const std::uint32_t to_a = find_half_edge(v, a), to_b = find_half_edge(v, b);
  if (to_a == none || to_b == none) throw std::logic_error("delaunay: a split constraint lost its edges");
  set_constrained(to_a, true);
  set_constrained(to_b, true);
  return v;
}

ConstrainedDelaunay2::TriangleId ConstrainedDelaunay2::triangle_left_of(VertexId public_a, VertexId public_b) const {
  if (public_a >= internal_.size() || public_b >= internal_.size()) return none;
  const std::uint32_t h = find_half_edge(internal_[public_a], internal_[public_b]);
  return h != none && is_live(h / 3) ? h / 3 : none;
}

std::vector<int> ConstrainedDelaunay2::classify(std::span<const Point2> holes,
                                                std::span<const RegionSeed> regions) const {
  constexpr int unvisited = -2;
  std::vector<int> label(flags_.size(), unvisited);
  std::vector<TriangleId> stack;
  auto flood = [&](int value) {
    while (!stack.empty()) {
      const TriangleId t = stack.back();
      stack.pop_back();
      for (std::uint32_t i = 0; i < 3; ++i) {
        if ((flags_[t] >> i) & 1u) continue;
        const TriangleId n = adjacent_[3 * t + i] / 3;
        if (label[n] != unvisited) continue;
        label[n] = value;
        stack.push_back(n);
      }
    }
  };
  for (TriangleId t = 0; t < flags_.size(); ++t) {
    if (flags_[t] & dead_flag) label[t] = -1;
    else if (flags_[t] & ghost_flag) label[t] = -1, stack.push_back(t);
  }
  flood(-1);
  for (const Point2& h : holes) {
    const TriangleId t = locate(h, none);
    if (t == none || label[t] != unvisited) continue;
    label[t] = -1;
    stack.push_back(t);
    flood(-1);
  }
  for (const RegionSeed& r : regions) {
    const TriangleId t = locate(r.point, none);
    if (t == none || label[t] != unvisited) continue;
    label[t] = static_cast<int>(r.label);
    stack.push_back(t);
    flood(static_cast<int>(r.label));
  }
  for (TriangleId t = 0; t < flags_.size(); ++t) {
    if (label[t] == unvisited) label[t] = 0;
    if (!is_live(t)) label[t] = -1;
  }
  return label;
}

std::vector<std::array<ConstrainedDelaunay2::VertexId, 3>> ConstrainedDelaunay2::triangles() const {
  std::vector<std::array<VertexId, 3>> out;
  out.reserve(flags_.size() / 2 + 1);
  for (TriangleId t = 0; t < flags_.size(); ++t)
    if (is_live(t)) out.push_back(vertices(t));
  return out;
}

}  // namespace certimesh::generators
