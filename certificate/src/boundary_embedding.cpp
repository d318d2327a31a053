// Condition 4, second half: boundary facets meet only in shared vertices and edges. Broad
// phase: the box grid; narrow phase: the exact intersection predicates, which already treat
// shared vertices (same id, same point) as the allowed contact (intersection/mode.h).
#include <algorithm>
#include <array>
#include <cstdint>
#include <map>
#include <vector>

#include "certimesh/predicates/intersection/segment_segment_2d.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/intersection/triangle_segment_3d.h"
#include "certimesh/predicates/intersection/triangle_triangle_3d.h"
#include "close_pairs.h"
#include "stages.h"
#include "sweep_2d.h"
#include "vertex_fans.h"

namespace certimesh::certificate::detail {

using predicates::IntersectionMode;
using predicates::Overlap;

namespace {

std::array<predicates::Vertex3, 3> triangle(const MeshView& m, Index a, Index b, Index c) {
  return {{{m.p3(a), a}, {m.p3(b), b}, {m.p3(c), c}}};
}

// A fast certificate that triangles f and g meet at most in their shared vertices: in some
// coordinate projection, the line through an edge pq of one triangle has its third vertex
// strictly on one side and every vertex of the other triangle that is not p or q strictly on
// the other (certain filter signs only). The projections then meet only in shared vertices on
// that line, and the first triangle projects injectively (its third vertex is off the line),
// so the triangles meet only in shared vertices. Two convex polygons that touch at most in a
// common vertex or edge are separated by a line through an edge of one of them, so this
// usually succeeds; when it does not, the exact rules below decide.
bool separated_in_projection(const MeshView& m, const Index* f, const Index* g) {
  using predicates::FilteredSign;
  for (int drop = 0; drop < 3; ++drop) {
    const int u = drop == 0 ? 1 : 0, w = drop == 2 ? 1 : 2;
    auto p = [&](Index v) { return predicates::Point2{m.coord(v, u), m.coord(v, w)}; };
    for (int pass = 0; pass < 2; ++pass, std::swap(f, g))
      for (int i = 0; i < 3; ++i) {
        const Index a = f[i], b = f[(i + 1) % 3];
        const FilteredSign inner = predicates::orient2d_filtered(p(a), p(b), p(f[(i + 2) % 3]));
        bool apart = inner != FilteredSign::uncertain;
        for (int j = 0; j < 3 && apart; ++j)
          apart = g[j] == a || g[j] == b || predicates::orient2d_filtered(p(a), p(b), p(g[j])) == -inner;
        if (apart) return true;
      }
  }
  return false;
}

// Exact, after the fast certificate; the predicates treat shared ids as the allowed contact.
bool triangles_meet(const MeshView& m, const Index* f, const Index* g) {
  if (separated_in_projection(m, f, g)) return false;
  return predicates::triangle_triangle_3d(triangle(m, f[0], f[1], f[2]), triangle(m, g[0], g[1], g[2]),
                                          IntersectionMode::exact) == Overlap::intersect;
}

bool facets_meet(const MeshView& m, const Index* f, const Index* g) {
  if (m.dim == 3) return triangles_meet(m, f, g);
  // Two segments from one vertex (same id, so the same point) in directions that are not
  // collinear meet only there: one orient2d instead of the general test (the sweep tests every
  // pair of neighbours, and at a pinch or a fan those share their vertex).
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j)
      if (f[i] == g[j] && f[1 - i] != g[1 - j])
        return predicates::orient2d(m.p2(f[i]), m.p2(f[1 - i]), m.p2(g[1 - j])) == predicates::Sign::zero &&
               predicates::segment_segment_2d(std::array<predicates::Vertex2, 2>{{{m.p2(f[0]), f[0]}, {m.p2(f[1]), f[1]}}},
                                              std::array<predicates::Vertex2, 2>{{{m.p2(g[0]), g[0]}, {m.p2(g[1]), g[1]}}},
                                              IntersectionMode::exact) == Overlap::intersect;
  const std::array<predicates::Vertex2, 2> s{{{m.p2(f[0]), f[0]}, {m.p2(f[1]), f[1]}}};
  const std::array<predicates::Vertex2, 2> t{{{m.p2(g[0]), g[0]}, {m.p2(g[1]), g[1]}}};
  return predicates::segment_segment_2d(s, t, IntersectionMode::exact) == Overlap::intersect;
}

// Whether vertex v (not a vertex of f) lies on the closed facet f: a degenerate segment v-v.
bool vertex_on_facet(const MeshView& m, Index v, const Index* f) {
  if (m.dim == 2) {
    const std::array<predicates::Vertex2, 2> s{{{m.p2(f[0]), f[0]}, {m.p2(f[1]), f[1]}}};
    const std::array<predicates::Vertex2, 2> point{{{m.p2(v), v}, {m.p2(v), v}}};
    return predicates::segment_segment_2d(s, point, IntersectionMode::exact) == Overlap::intersect;
  }
  const std::array<predicates::Vertex3, 3> s{{{m.p3(f[0]), f[0]}, {m.p3(f[1]), f[1]}, {m.p3(f[2]), f[2]}}};
  const std::array<predicates::Vertex3, 2> point{{{m.p3(v), v}, {m.p3(v), v}}};
  return predicates::triangle_segment_3d(s, point, IntersectionMode::exact) == Overlap::intersect;
}

// A vertex of one facet lying on the other, not one of its vertices; -1 if none.
std::int64_t t_junction_vertex(const MeshView& m, const Index* f, const Index* g) {
  auto has = [&](const Index* h, Index v) {
    for (int i = 0; i < m.dim; ++i)
      if (h[i] == v) return true;
    return false;
  };
  for (int pass = 0; pass < 2; ++pass, std::swap(f, g))
    for (int i = 0; i < m.dim; ++i)
      if (!has(g, f[i]) && vertex_on_facet(m, f[i], g)) return f[i];
  return -1;
}

}  // namespace

Finding contact_of(const MeshView& m, const FacetSet& set, std::size_t i, std::size_t j, Defect touching, Defect crossing,
                   const std::string& what) {
  if (!facets_meet(m, set.facet(i), set.facet(j))) return {};
  const std::int64_t v = t_junction_vertex(m, set.facet(i), set.facet(j));
  if (v < 0)
    return finding(crossing, set.owner[i], set.owner[j], -1,
                   what + "s " + std::to_string(i) + " and " + std::to_string(j) + " intersect beyond their shared vertices");
  const std::size_t host = !std::count(set.facet(i), set.facet(i) + m.dim, static_cast<Index>(v)) ? i : j;
  const std::size_t guest = host == i ? j : i;
  return finding(touching, set.owner[host], set.owner[guest], v,
                 "vertex " + std::to_string(v) + " lies on " + what + " " + std::to_string(host) + " without being one of its vertices");
}

namespace {

// Fans of at least this many triangles at one vertex are decided by their cones (vertex_fans.h).
constexpr std::size_t kFanSize = 32;

// The broad phase, when some fans are decided, for the pairs with a triangle of a decided fan
// (proofs/mesh_certificate.md section 6; the other pairs go to the grid): a sweep along z. Pairs whose z ranges overlap in an open interval meet in the sweep's active set,
// kept in groups by the decided fan vertices of their triangles, and a group sharing a decided
// vertex with the entering triangle is skipped whole: such a pair was decided with the fan.
// Pairs whose z ranges meet in one value c lie, where they meet, in the plane z = c: a
// triangle that ends (starts) at c meets that plane in its top (bottom) face, so those pairs are
// found among the faces' xy boxes in that plane, with the flat triangles at c and, only when
// there are flat ones, the triangles spanning c. Calls visit(i, j) until it returns true.
template <class Visit>
bool sweep_pairs(const MeshView& m, const FacetSet& set, const std::vector<Box>& boxes,
                 const std::vector<std::array<std::int64_t, 3>>& decided, Visit visit) {
  const std::size_t n = set.size();
  auto in_fan = [&](std::size_t i) { return decided[i][2] >= 0; };  // sorted: -1 first
  auto disjoint = [&](std::size_t i, std::size_t j) {
    for (std::int64_t a : decided[i])
      for (std::int64_t b : decided[j])
        if (a >= 0 && a == b) return false;
    return true;
  };
  std::vector<std::size_t> by_lo(n), by_hi;
  for (std::size_t i = 0; i < n; ++i) by_lo[i] = i;
  std::sort(by_lo.begin(), by_lo.end(), [&](std::size_t a, std::size_t b) { return boxes[a].lo[2] < boxes[b].lo[2]; });
  for (std::size_t i : by_lo)
    if (boxes[i].lo[2] < boxes[i].hi[2]) by_hi.push_back(i);
  std::sort(by_hi.begin(), by_hi.end(), [&](std::size_t a, std::size_t b) { return boxes[a].hi[2] < boxes[b].hi[2]; });
  // Active triangles in groups of equal decided-vertex triples.
  std::map<std::array<std::int64_t, 3>, std::size_t> group_of_key;
  std::vector<std::vector<std::size_t>> groups;
  std::vector<std::size_t> group(n), slot(n);
  for (std::size_t i = 0; i < n; ++i) {
    auto [it, fresh] = group_of_key.try_emplace(decided[i], groups.size());
    if (fresh) groups.emplace_back();
    group[i] = it->second;
  }
  std::vector<std::size_t> live;  // groups with active members
  std::vector<std::size_t> live_slot(groups.size(), SIZE_MAX);
  auto remove = [&](std::size_t i) {
    std::vector<std::size_t>& g = groups[group[i]];
    const std::size_t last = g.back();
    g[slot[i]] = last, slot[last] = slot[i];
    g.pop_back();
    if (g.empty()) {
      const std::size_t at = live_slot[group[i]], other = live.back();
      live[at] = other, live_slot[other] = at;
      live.pop_back();
      live_slot[group[i]] = SIZE_MAX;
    }
  };
  auto add = [&](std::size_t i) {
    std::vector<std::size_t>& g = groups[group[i]];
    if (g.empty()) live_slot[group[i]] = live.size(), live.push_back(group[i]);
    slot[i] = g.size();
    g.push_back(i);
  };
  enum Kind : int { ends, starts, flat, spans };
  struct Item {
    Box box;
    std::size_t facet;
    Kind kind;
  };
  std::vector<Item> plane;
  std::vector<std::size_t> order, active;
  auto face_box = [&](std::size_t f, double c) {  // xy box of the triangle's vertices at z = c
    Box b;
    bool any = false;
    for (int k = 0; k < 3; ++k) {
      const Index v = set.facet(f)[k];
      if (m.coord(v, 2) != c) continue;
      for (int a = 0; a < 2; ++a) {
        const double x = m.coord(v, a);
        b.lo[a] = any ? std::min(b.lo[a], x) : x, b.hi[a] = any ? std::max(b.hi[a], x) : x;
      }
      any = true;
    }
    return b;
  };
  std::size_t next_lo = 0, next_hi = 0;
  while (next_lo < n || next_hi < by_hi.size()) {
    const double c = next_lo < n && (next_hi == by_hi.size() || boxes[by_lo[next_lo]].lo[2] <= boxes[by_hi[next_hi]].hi[2])
                         ? boxes[by_lo[next_lo]].lo[2]
                         : boxes[by_hi[next_hi]].hi[2];
    plane.clear();
    bool has_flat = false;
    for (; next_hi < by_hi.size() && boxes[by_hi[next_hi]].hi[2] == c; ++next_hi) {
      const std::size_t f = by_hi[next_hi];
      remove(f);
      plane.push_back({face_box(f, c), f, ends});
    }
    const std::size_t entering = next_lo;
    for (; next_lo < n && boxes[by_lo[next_lo]].lo[2] == c; ++next_lo) {
      const std::size_t g = by_lo[next_lo];
      const bool is_flat = boxes[g].hi[2] == c;
      has_flat = has_flat || is_flat;
      plane.push_back(is_flat ? Item{boxes[g], g, flat} : Item{face_box(g, c), g, starts});
    }
    if (has_flat)
      for (std::size_t l : live)
        for (std::size_t f : groups[l]) plane.push_back({boxes[f], f, spans});
    // Open overlaps: every entering non-flat triangle against the active groups.
    for (std::size_t e = entering; e < next_lo; ++e) {
      const std::size_t g = by_lo[e];
      if (boxes[g].hi[2] == c) continue;
      for (std::size_t l : live) {
        const std::vector<std::size_t>& members = groups[l];
        if (members.empty() || !disjoint(members.front(), g) || (!in_fan(g) && !in_fan(members.front()))) continue;
        for (std::size_t f : members)
          if (boxes_overlap(boxes[f], boxes[g], 3) && visit(std::min(f, g), std::max(f, g))) return true;
      }
      add(g);
    }
    // Contacts in the plane z = c.
    bool has_end = false, has_start = false;
    for (const Item& it : plane) has_end = has_end || it.kind == ends, has_start = has_start || it.kind == starts;
    bool has_fan = false;
    for (const Item& it : plane) has_fan = has_fan || in_fan(it.facet);
    if (!has_fan || (!has_flat && !(has_end && has_start))) continue;
    // Sweep and prune along x among the pieces (a uniform grid crowds where the faces lie
    // on a curve, as a book's chords on its circle).
    order.resize(plane.size());
    for (std::size_t i = 0; i < plane.size(); ++i) order[i] = i;
    std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return plane[a].box.lo[0] < plane[b].box.lo[0]; });
    bool stop = false;
    active.clear();
    for (std::size_t a : order) {
      const Item& x = plane[a];
      std::size_t kept = 0;
      for (std::size_t b : active) {
        const Item& y = plane[b];
        if (y.box.hi[0] < x.box.lo[0]) continue;  // ends left of every later piece
        active[kept++] = b;
        if (stop || y.box.hi[1] < x.box.lo[1] || x.box.hi[1] < y.box.lo[1]) continue;
        const bool wanted = x.kind == flat || y.kind == flat || (x.kind == ends && y.kind == starts) || (x.kind == starts && y.kind == ends);
        if (!wanted || x.facet == y.facet || (!in_fan(x.facet) && !in_fan(y.facet)) || !disjoint(x.facet, y.facet)) continue;
        stop = visit(std::min(x.facet, y.facet), std::max(x.facet, y.facet));
      }
      active.resize(kept);
      active.push_back(a);
      if (stop) break;
    }
    if (stop) return true;
  }
  return false;
}

// Per facet, its vertices whose fan of at least kFanSize triangles the cone test decided
// (-1 for none); all -1 when there is no such fan.
std::vector<std::array<std::int64_t, 3>> decided_fans(const MeshView& m, const FacetSet& set, bool& any) {
  any = false;
  std::vector<std::array<std::int64_t, 3>> decided(set.size(), {-1, -1, -1});
  std::vector<std::size_t> start(m.vertex_count + 1, 0);
  for (std::size_t f = 0; f < set.size(); ++f)
    for (int k = 0; k < 3; ++k) ++start[set.facet(f)[k] + 1];
  for (std::size_t v = 0; v < m.vertex_count; ++v) start[v + 1] += start[v];
  std::vector<std::size_t> at(start[m.vertex_count]), fill(start.begin(), start.end() - 1);
  for (std::size_t f = 0; f < set.size(); ++f)
    for (int k = 0; k < 3; ++k) at[fill[set.facet(f)[k]]++] = f;
  std::vector<std::size_t> fan;
  for (std::size_t v = 0; v < m.vertex_count; ++v) {
    if (start[v + 1] - start[v] < kFanSize) continue;
    fan.assign(at.begin() + static_cast<std::ptrdiff_t>(start[v]), at.begin() + static_cast<std::ptrdiff_t>(start[v + 1]));
    const bool ok = fan_is_embedded(m, set, static_cast<Index>(v), fan,
                                    [&](std::size_t i, std::size_t j) { return triangles_meet(m, set.facet(i), set.facet(j)); });
    if (!ok) continue;
    any = true;
    for (std::size_t f : fan)
      for (auto& slot : decided[f])
        if (slot < 0) {
          slot = static_cast<std::int64_t>(v);
          break;
        }
  }
  for (auto& d : decided) std::sort(d.begin(), d.end());
  return decided;
}

}  // namespace

// 2D: the plane sweep, O(n log n) in the worst case. 3D: the box grid (its worst case, many
// facets whose boxes overlap, is stated in proofs/mesh_certificate.md section 6); a touching
// pair is reported before a crossing one. When fans of many triangles at one vertex are
// decided by their cones, the z sweep above replaces the grid; it only certifies: if it
// finds a contact, the grid runs as before, so a defect is reported exactly as it was.
Finding first_contact(const MeshView& m, const FacetSet& set, Defect touching, Defect crossing,
                      const std::string& what) {
  if (m.dim == 2) {
    std::vector<SweepAnswer> none;
    return sweep_2d(m, set, touching, crossing, what, {}, none);
  }
  std::vector<Box> boxes(set.size());
  for (std::size_t f = 0; f < set.size(); ++f) boxes[f] = facet_box(m, set.facet(f), m.dim);
  bool any_fan = false;
  const auto decided = decided_fans(m, set, any_fan);
  if (any_fan) {
    // Pairs with a triangle of a decided fan: the sweep; the others: the grid over the others.
    auto meet = [&](std::size_t i, std::size_t j) { return facets_meet(m, set.facet(i), set.facet(j)); };
    std::vector<std::size_t> rest;
    std::vector<Box> rest_boxes;
    for (std::size_t f = 0; f < set.size(); ++f)
      if (decided[f][2] < 0) rest.push_back(f), rest_boxes.push_back(boxes[f]);
    if (!sweep_pairs(m, set, boxes, decided, meet) &&
        !BoxGrid(rest_boxes, m.dim).any_pair([&](std::size_t i, std::size_t j) { return meet(rest[i], rest[j]); }))
      return {};
  }
  Finding crossing_found;
  BoxGrid(boxes, m.dim).any_pair([&](std::size_t i, std::size_t j) {
    Finding c = contact_of(m, set, i, j, touching, crossing, what);
    if (c.defect == touching) {
      crossing_found = std::move(c);
      return true;
    }
    if (crossing_found.defect == Defect::none) crossing_found = std::move(c);
    return false;
  });
  return crossing_found;
}

Finding check_boundary_embedding(const MeshView& m, const FacetSet& boundary) {
  // 2D: the single-cover sweep (winding.cpp) is this same sweep with queries added; it reports
  // the first contact, with these defects, before any winding number, so running it here too
  // would sweep the boundary twice.
  if (m.dim == 2) return {};
  return first_contact(m, boundary, Defect::t_junction, Defect::boundary_intersection,
                       m.dim == 2 ? "boundary edge" : "boundary triangle");
}

}  // namespace certimesh::certificate::detail
