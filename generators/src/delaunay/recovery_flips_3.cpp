// The flips of boundary recovery (recovery_mesh_3.h): local re-triangulations that keep the
// vertex set, tried before a split so that a surface edge or triangle that the Delaunay
// tetrahedralization missed is recovered without a Steiner point wherever the neighbourhood
// allows it (TetGen's order: flips first, Steiner points only where no flip applies).
// Each flip is done only when every new tetrahedron is positive by an exact sign and the new
// tetrahedra fill exactly the region of the old ones (proofs/boundary_recovery_3.md §1a).
#include <algorithm>
#include <cstdint>
#include <optional>
#include <utility>

#include "recovery_mesh_3.h"

namespace certimesh::generators::detail {

namespace {

using Element = topology::TetrahedralMesh3::Element;

// The tetrahedra around edge (x, y) as a ring: ring[i] and ring[i + 1] are the other two
// corners of one tetrahedron, ordered so that (x, y, ring[i], ring[i + 1]) is positive.
// `closed` when the tetrahedra go all the way round; else ring.front() and ring.back() are
// the apexes of the two hull faces through (x, y). Empty if (x, y) is not an edge or the
// tetrahedra do not form one fan (never in a valid mesh).
struct EdgeRing {
  std::vector<VertexId> ring;
  std::vector<ElementId> tetrahedra;
  bool closed = false;
};

EdgeRing ring_of(const RecoveryMesh& m, VertexId x, VertexId y) {
  EdgeRing r;
  r.tetrahedra = m.around_edge(x, y);
  std::vector<std::pair<VertexId, VertexId>> next;  // (p, q): (x, y, p, q) positive
  for (const ElementId t : r.tetrahedra) {
    VertexId other[2];
    int k = 0;
    for (const VertexId v : m.mesh.vertices(t))
      if (v != x && v != y) other[k++] = v;
    if (m.volume(x, y, other[0], other[1]) < 0) std::swap(other[0], other[1]);
    next.emplace_back(other[0], other[1]);
  }
  if (next.empty()) return {};
  // The start: a p that is no q (open ring), else the first tetrahedron's p.
  VertexId start = next[0].first;
  for (const auto& [p, q] : next)
    if (std::none_of(next.begin(), next.end(), [&](const auto& e) { return e.second == p; })) start = p;
  r.ring.push_back(start);
  for (std::size_t steps = 0; steps < next.size(); ++steps) {
    const auto it = std::find_if(next.begin(), next.end(), [&](const auto& e) { return e.first == r.ring.back(); });
    if (it == next.end()) return {};
    r.ring.push_back(it->second);
  }
  r.closed = r.ring.back() == r.ring.front();
  if (r.closed) r.ring.pop_back();
  if (r.ring.size() != (r.closed ? next.size() : next.size() + 1)) return {};
  return r;
}

void replace(RecoveryMesh& m, const std::vector<ElementId>& old, const std::vector<Element>& fresh) {
  for (const ElementId t : old) m.mesh.remove_element(t);
  for (const Element& t : fresh) m.mesh.add_element(t);
}

// For a ring open on the hull: the hull faces (x, y, r0) and (x, y, rk) become (x, r0, rk)
// and (y, r0, rk), the same region exactly when x, y, r0, rk are coplanar and the quadrilateral
// x r0 y rk is strictly convex (its diagonals cross). `off` is a ring vertex off that plane.
bool hull_quad_flips(const RecoveryMesh& m, VertexId x, VertexId y, VertexId r0, VertexId rk, VertexId off) {
  if (m.orient(x, y, r0, rk) != 0) return false;
  const int s0 = m.orient(x, y, off, r0), sk = m.orient(x, y, off, rk);
  const int sx = m.orient(r0, rk, off, x), sy = m.orient(r0, rk, off, y);
  return s0 != 0 && s0 == -sk && sx != 0 && sx == -sy;
}

// Triangulations of the polygon of an edge's ring (closed by the hull side r_{n-1} r_0 when the
// ring is open): each triangle (r_i, r_j, r_k), i < j < k in ring order, stands for the
// tetrahedra (r_i, r_j, r_k, y) and (r_j, r_i, r_k, x), positive with (x, y, r_i, r_{i+1}) for
// a valid replacement; a triangulation is usable when all of its tetrahedra are positive.
class RingTriangulation {
 public:
  static constexpr std::size_t max_ring = 16;  // the search is cubic in the ring's length

  RingTriangulation(const RecoveryMesh& m, VertexId x, VertexId y, const std::vector<VertexId>& ring)
      : m_(m), x_(x), y_(y), ring_(ring), n_(ring.size()) {}

  /// The fan from ring vertex a, if usable.
  std::optional<std::vector<Element>> fan(std::size_t a) const {
    std::vector<Element> out;
    for (std::size_t s = 1; s + 1 < n_; ++s) {
      if (!usable(a, a + s, a + s + 1)) return std::nullopt;
      add(out, a, a + s, a + s + 1);
    }
    return out;
  }

  /// A usable triangulation that has the diagonal (a, b), found by dynamic programming over
  /// the sub-polygons on either side of it (Klincsek's scheme, as in Shewchuk's edge
  /// removal), if one exists.
  std::optional<std::vector<Element>> with_diagonal(std::size_t a, std::size_t b) {
    if (b < a) std::swap(a, b);
    choice_.assign(4 * n_ * n_, unknown);
    if (!solvable(a, b) || !solvable(b, a + n_)) return std::nullopt;
    std::vector<Element> out;
    collect(out, a, b);
    collect(out, b, a + n_);
    return out;
  }

 private:
  static constexpr std::size_t unknown = SIZE_MAX, none = SIZE_MAX - 1;

  VertexId at(std::size_t i) const { return ring_[i % n_]; }
  bool usable(std::size_t i, std::size_t j, std::size_t k) const {
    return m_.volume(at(i), at(j), at(k), y_) > 0 && m_.volume(at(j), at(i), at(k), x_) > 0;
  }
  void add(std::vector<Element>& out, std::size_t i, std::size_t j, std::size_t k) const {
    out.push_back({at(i), at(j), at(k), y_});
    out.push_back({at(j), at(i), at(k), x_});
  }
  // Whether the sub-polygon i, i+1, ..., k (unrolled indices, k - i < n) has a usable
  // triangulation; the apex chosen over the side (i, k) is kept in choice_.
  bool solvable(std::size_t i, std::size_t k) {
    if (k - i < 2) return true;
    std::size_t& c = choice_[i * 2 * n_ + k];
    if (c == unknown) {
      c = none;
      for (std::size_t j = i + 1; j < k && c == none; ++j)
        if (usable(i, j, k) && solvable(i, j) && solvable(j, k)) c = j;
    }
    return c != none;
  }
  void collect(std::vector<Element>& out, std::size_t i, std::size_t k) const {
    if (k - i < 2) return;
    const std::size_t j = choice_[i * 2 * n_ + k];
    add(out, i, j, k);
    collect(out, i, j);
    collect(out, j, k);
  }

  const RecoveryMesh& m_;
  VertexId x_, y_;
  const std::vector<VertexId>& ring_;
  std::size_t n_;
  std::vector<std::size_t> choice_;
};

}  // namespace

bool on_one_surface_edge(const RecoveryMesh& m, const RecoverySurface3& s, VertexId v, VertexId w) {
  const RecoveryVertex &rv = m.vertices[v.value], &rw = m.vertices[w.value];
  using Origin = RecoveryVertex::Origin;
  auto is_end = [&](std::uint32_t e, VertexId x) { return s.edges[e][0] == x.value || s.edges[e][1] == x.value; };
  if (rv.origin == Origin::input && rw.origin == Origin::input) {
    const std::array<std::uint32_t, 2> e{std::min(v.value, w.value), std::max(v.value, w.value)};
    return std::binary_search(s.edges.begin(), s.edges.end(), e);
  }
  if (rv.origin == Origin::on_edge && rw.origin == Origin::on_edge) return rv.on == rw.on;
  if (rv.origin == Origin::on_edge && rw.origin == Origin::input) return is_end(rv.on, w);
  if (rw.origin == Origin::on_edge && rv.origin == Origin::input) return is_end(rw.on, v);
  return false;
}

bool try_flip_2_3(RecoveryMesh& m, ElementId t, int i) {
  const ElementId beyond = m.mesh.neighbour(t, i);
  if (beyond.is_none()) return false;
  const VertexId u = m.mesh.vertices(t)[static_cast<std::size_t>(i)];
  const auto f = m.mesh.facet(t, i);
  const auto far = m.mesh.vertices(beyond);
  VertexId q = far[0];
  for (const VertexId v : far)
    if (std::find(f.begin(), f.end(), v) == f.end()) q = v;
  // (u, q) crosses the interior of f exactly when the three tetrahedra round (u, q) have one
  // non-zero orientation; then they fill the two old ones.
  std::vector<Element> fresh;
  int first = 0;
  for (int k = 0; k < 3; ++k) {
    Element n{u, q, f[static_cast<std::size_t>(k)], f[static_cast<std::size_t>((k + 1) % 3)]};
    const int sign = m.volume(n[0], n[1], n[2], n[3]);
    if (sign == 0 || (k > 0 && sign != first)) return false;
    first = sign;
    if (sign < 0) std::swap(n[2], n[3]);
    fresh.push_back(n);
  }
  replace(m, {t, beyond}, fresh);
  return true;
}

namespace {

bool remove_edge_now(RecoveryMesh& m, const EdgeRing& r, VertexId x, VertexId y, VertexId apex,
                     std::optional<VertexId> target) {
  const std::size_t n = r.ring.size();
  const auto at = std::find(r.ring.begin(), r.ring.end(), apex);
  if (n < 3 || at == r.ring.end()) return false;
  if (!r.closed && !hull_quad_flips(m, x, y, r.ring.front(), r.ring.back(), r.ring[1])) return false;
  const std::size_t a = static_cast<std::size_t>(at - r.ring.begin());
  const auto to = target ? std::find(r.ring.begin(), r.ring.end(), *target) : r.ring.end();
  RingTriangulation polygon(m, x, y, r.ring);
  std::optional<std::vector<Element>> fresh;
  if (to != r.ring.end() && to != at && n <= RingTriangulation::max_ring)
    fresh = polygon.with_diagonal(a, static_cast<std::size_t>(to - r.ring.begin()));
  else
    fresh = polygon.fan(a);
  if (!fresh) return false;
  replace(m, r.tetrahedra, *fresh);
  return true;
}

// One flip that takes a vertex r_i out of the ring of (x, y), r_i neither the apex nor the
// target (whose stars the walk relies on) nor, on an open ring, an end: the 2-3 flip of the
// face (x, y, r_i), else the removal of the edge (y, r_i) by the fan from x or of (x, r_i) by
// the fan from y (r_i is then no longer a neighbour of both), never of an edge on the surface.
bool shrink_ring(RecoveryMesh& m, const RecoverySurface3& s, const EdgeRing& r, VertexId x, VertexId y, VertexId apex,
                 std::optional<VertexId> target) {
  const std::size_t n = r.ring.size();
  for (std::size_t i = r.closed ? 0 : 1; i < (r.closed ? n : n - 1); ++i) {
    const VertexId v = r.ring[i];
    if (v == apex || (target && v == *target)) continue;
    // The tetrahedron (x, y, r_{i-1}, r_i) and its neighbour across face (x, y, r_i).
    for (const ElementId t : r.tetrahedra) {
      const auto c = m.mesh.vertices(t);
      const VertexId before = r.ring[(i + n - 1) % n];
      if (std::find(c.begin(), c.end(), before) == c.end() || std::find(c.begin(), c.end(), v) == c.end()) continue;
      const int opposite = static_cast<int>(std::find(c.begin(), c.end(), before) - c.begin());
      if (try_flip_2_3(m, t, opposite)) return true;
    }
    // Only where that edge's ring is (r_{i-1}, x or y, r_{i+1}) (a 3-2 flip, or a 2-2 flip on a
    // flat hull): then the ring of (x, y) loses r_i and gains nothing, so every round shrinks it.
    for (const auto& [w, other] : {std::pair(y, x), std::pair(x, y)})
      if (ring_of(m, w, v).ring.size() == 3 && !on_one_surface_edge(m, s, w, v) && try_remove_edge(m, w, v, other))
        return true;
  }
  return false;
}

}  // namespace

bool try_remove_edge(RecoveryMesh& m, VertexId x, VertexId y, VertexId apex, std::optional<VertexId> target,
                     const RecoverySurface3* shrink) {
  bool changed = false;
  for (;;) {  // every round takes one vertex out of the ring (shrink_ring), so it ends
    const EdgeRing r = ring_of(m, x, y);
    if (remove_edge_now(m, r, x, y, apex, target)) return true;
    if (!shrink || r.ring.size() <= 3 || !shrink_ring(m, *shrink, r, x, y, apex, target)) return changed;
    changed = true;
  }
}

}  // namespace certimesh::generators::detail
