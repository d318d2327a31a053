// The flips of boundary recovery (recovery_mesh_3.h): local re-triangulations that keep the
// vertex set, tried before a split so that a surface edge or triangle that the Delaunay
// tetrahedralization missed is recovered without a Steiner point wherever the neighbourhood
// allows it (TetGen's order: flips first, Steiner points only where no flip applies).
// Each flip is done only when every new tetrahedron is positive by an exact sign and the new
// tetrahedra fill exactly the region of the old ones (proofs/boundary_recovery_3.md §1a).
#include <algorithm>
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

bool all_positive(const RecoveryMesh& m, const std::vector<Element>& tetrahedra) {
  return std::all_of(tetrahedra.begin(), tetrahedra.end(),
                     [&](const Element& t) { return m.volume(t[0], t[1], t[2], t[3]) > 0; });
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

}  // namespace

bool on_one_surface_edge(const RecoveryMesh& m, const Surface3& s, VertexId v, VertexId w) {
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

bool try_remove_edge(RecoveryMesh& m, VertexId x, VertexId y, VertexId apex) {
  const EdgeRing r = ring_of(m, x, y);
  const std::size_t n = r.ring.size();
  const auto at = std::find(r.ring.begin(), r.ring.end(), apex);
  if (n < 3 || at == r.ring.end()) return false;
  if (!r.closed && !hull_quad_flips(m, x, y, r.ring.front(), r.ring.back(), r.ring[1])) return false;
  // The fan from the apex over the ring polygon (closed by the hull side (rk, r0) when open):
  // one triangle per polygon side not through the apex, each with x and with y.
  const std::size_t j = static_cast<std::size_t>(at - r.ring.begin());
  std::vector<Element> fresh;
  for (std::size_t s = 0; s < n; ++s) {
    const VertexId p = r.ring[s], q = r.ring[(s + 1) % n];
    if (p == apex || q == apex) continue;
    // (x, y, p, q) positive with p, q in ring order: so are (apex, p, q, y) and (p, apex, q, x)
    // when the new tetrahedra are a valid replacement (checked below).
    fresh.push_back({r.ring[j], p, q, y});
    fresh.push_back({p, r.ring[j], q, x});
  }
  if (!all_positive(m, fresh)) return false;
  replace(m, r.tetrahedra, fresh);
  return true;
}

}  // namespace certimesh::generators::detail
