// Condition 4, first half: the unmatched facets split into closed curves (2D) / closed
// surfaces (3D) that touch only at pinches (design decision 8: two parts sharing a corner, a
// hole touching the outer loop, two solids sharing a vertex or an edge).
//
// 2D: at a boundary vertex the boundary edges, in counterclockwise order, must alternate
// between leaving and entering (the winding number then takes two consecutive values around
// the vertex); each entering edge is followed by the edge after it in that order, which
// leaves. 3D: around a boundary edge the boundary triangles, in their order around the edge,
// must alternate in the direction they give the edge; each triangle is paired with its
// neighbour across the sector in front of both. At a vertex nothing more is needed: with every
// edge paired, the link of the vertex is a union of cycles, one disk of surface each.
// Both pairings are across the sector of lower winding number (outside the mesh), so every
// curve / surface bounds one unmeshed face on its outer side (proofs/mesh_certificate.md,
// section 2: why this pairing keeps the single-cover argument and the hole rules true).
#include <algorithm>
#include <numeric>
#include <vector>

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "stages.h"

namespace certimesh::certificate::detail {
namespace {

using predicates::Sign;

struct FacetUnionFind {
  std::vector<std::size_t> parent;
  explicit FacetUnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
  std::size_t find(std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a), b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  }
};

Finding pinch(const FacetSet& b, std::size_t f, Index v, const std::string& why) {
  return finding(Defect::non_manifold_boundary, b.owner[f], -1, v,
                 "the boundary is not a manifold at vertex " + std::to_string(v) + ": " + why);
}

// Two boundary facets that leave a vertex (2D) or an edge (3D) in the same direction overlap:
// the first such pair, reported by the embedding's own exact rules once no vertex or edge is
// non-manifold (non_manifold_boundary comes first in defect.h).
struct FirstOverlappingPair {
  std::size_t a = SIZE_MAX, b = SIZE_MAX;
  void note(std::size_t x, std::size_t y) {
    if (a == SIZE_MAX) a = x, b = y;
  }
};

// The boundary facets at each vertex (2D) as one array sliced by vertex.
struct Stars {
  std::vector<std::size_t> start, facets;
};

Stars stars_2d(const MeshView& m, const FacetSet& b) {
  Stars s;
  s.start.assign(m.vertex_count + 1, 0);
  for (Index v : b.vertices) ++s.start[v + 1];
  for (std::size_t v = 0; v < m.vertex_count; ++v) s.start[v + 1] += s.start[v];
  s.facets.resize(b.vertices.size());
  std::vector<std::size_t> fill(s.start.begin(), s.start.end() - 1);
  for (std::size_t i = 0; i < b.vertices.size(); ++i) s.facets[fill[b.vertices[i]]++] = i / 2;
  return s;
}

// Counterclockwise order of the boundary edges at v by the direction to their other end,
// starting at the direction (1, 0): the upper half (other end lexicographically after v in
// (y, x): the sweep's order) first, then the lower half; exact orient2d within a half.
struct CcwAround {
  const MeshView* m;
  const FacetSet* b;
  Index v;
  Index far(std::size_t f) const { return b->facet(f)[0] == v ? b->facet(f)[1] : b->facet(f)[0]; }
  bool upper(Index u) const {
    return m->coord(u, 1) != m->coord(v, 1) ? m->coord(u, 1) > m->coord(v, 1) : m->coord(u, 0) > m->coord(v, 0);
  }
  Sign turn(std::size_t f, std::size_t g) const { return predicates::orient2d(m->p2(v), m->p2(far(f)), m->p2(far(g))); }
  bool operator()(std::size_t f, std::size_t g) const {
    const bool uf = upper(far(f)), ug = upper(far(g));
    return uf != ug ? uf : turn(f, g) == Sign::positive;
  }
};

bool leaves(const FacetSet& b, std::size_t f, Index v) { return b.facet(f)[0] == v; }

// One vertex with more than two boundary edges: sorted counterclockwise in place, checked to
// alternate, each entering edge united with the edge after it.
Finding pair_at_pinch_2d(const MeshView& m, const FacetSet& b, Index v, std::size_t* first, std::size_t n, FacetUnionFind& uf,
                         FirstOverlappingPair& overlap) {
  const CcwAround ccw{&m, &b, v};
  // Sorted as keys that carry their half and far end: CcwAround reads the facet, then both
  // ends, then the coordinates for every comparison (most of this stage on a pinwheel).
  struct Spoke {
    bool upper;
    predicates::Point2 far;
    std::size_t facet;
  };
  std::vector<Spoke> spokes(n);
  for (std::size_t i = 0; i < n; ++i) spokes[i] = {ccw.upper(ccw.far(first[i])), m.p2(ccw.far(first[i])), first[i]};
  const predicates::Point2 centre = m.p2(v);
  std::sort(spokes.begin(), spokes.end(), [&](const Spoke& f, const Spoke& g) {  // CcwAround's order
    return f.upper != g.upper ? f.upper : predicates::orient2d(centre, f.far, g.far) == Sign::positive;
  });
  for (std::size_t i = 0; i < n; ++i) first[i] = spokes[i].facet;
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (!ccw(first[i], first[i + 1])) {  // the same direction: the two edges overlap (judged first,
      overlap.note(first[i], first[i + 1]);  // as the order of tied edges is arbitrary)
      return {};
    }
  for (std::size_t i = 0; i < n; ++i) {
    const std::size_t f = first[i], g = first[(i + 1) % n];
    if (leaves(b, f, v) == leaves(b, g, v))
      return pinch(b, g, v, "its " + std::to_string(n) + " boundary edges do not alternate between leaving and entering "
                            "it (counterclockwise), so the elements there cover some direction twice");
  }
  for (std::size_t i = 0; i < n; ++i)
    if (!leaves(b, first[i], v)) uf.unite(first[i], first[(i + 1) % n]);
  return {};
}

// 2D: as many boundary edges enter every boundary vertex as leave it; pairs as above.
Finding loops_2d(const MeshView& m, const FacetSet& b, FacetUnionFind& uf, Stars& stars, FirstOverlappingPair& overlap) {
  stars = stars_2d(m, b);
  for (Index v = 0; v < m.vertex_count; ++v) {
    std::size_t* first = stars.facets.data() + stars.start[v];
    const std::size_t n = stars.start[v + 1] - stars.start[v];
    const auto out = static_cast<std::size_t>(std::count_if(first, first + n, [&](std::size_t f) { return leaves(b, f, v); }));
    if (n == 0) continue;
    if (2 * out != n)
      return pinch(b, first[0], v, std::to_string(out) + " boundary edge(s) leave it and " + std::to_string(n - out) + " enter it");
    if (n == 2) {
      uf.unite(first[0], first[1]);
      continue;
    }
    if (Finding f = pair_at_pinch_2d(m, b, v, first, n, uf, overlap); f.defect != Defect::none) return f;
  }
  return {};
}

struct DirectedEdge {
  Index lo, hi;
  bool forward;  // lo -> hi in its facet's orientation
  std::uint32_t facet;
};

// The third vertex of boundary triangle f, off the edge (lo, hi).
Index apex_of(const FacetSet& b, std::size_t f, Index lo, Index hi) {
  for (int i = 0; i < 3; ++i)
    if (b.facet(f)[i] != lo && b.facet(f)[i] != hi) return b.facet(f)[i];
  return b.facet(f)[0];
}

// The order of the triangles around the edge a -> b, by their third vertices: c' comes after c
// (by less than a half turn) when orient3d(a, b, c, c') < 0, i.e. c' is in front of the
// triangle (a, b, c) (its normal side). Starting at the reference c0 (the first triangle's):
// the half turn [0, pi) first, then [pi, 2 pi). A third vertex in the plane of a, b, c0 is at 0
// or at pi: which one is decided by projecting onto a coordinate plane where a, b, c0 stay a
// triangle (exact orient2d).
struct AroundEdge {
  const MeshView* m;
  Index a, b, c0;
  predicates::Point2 drop(Index v, int axis) const {
    return {m->coord(v, axis == 0 ? 1 : 0), m->coord(v, axis == 2 ? 1 : 2)};
  }
  bool same_half_plane(Index c) const {
    for (int axis = 0; axis < 3; ++axis) {
      const Sign s0 = predicates::orient2d(drop(a, axis), drop(b, axis), drop(c0, axis));
      if (s0 != Sign::zero) return predicates::orient2d(drop(a, axis), drop(b, axis), drop(c, axis)) == s0;
    }
    return true;  // unreachable: a boundary triangle of a positive tetrahedron is not flat
  }
  Sign turn(Index c, Index d) const { return predicates::orient3d(m->p3(a), m->p3(b), m->p3(c), m->p3(d)); }
  int half(Index c) const {
    const Sign s = turn(c0, c);
    return s == Sign::negative ? 0 : s == Sign::positive ? 1 : (same_half_plane(c) ? 0 : 1);
  }
  bool before(Index c, Index d) const {
    const int hc = half(c), hd = half(d);
    return hc != hd ? hc < hd : turn(c, d) == Sign::negative;
  }
};

// One edge in more than two boundary triangles: sorted around it, checked to alternate, and
// each triangle that gives the edge the direction a -> b paired with the next one.
Finding pair_around_edge(const MeshView& m, const FacetSet& b, DirectedEdge* first, std::size_t n, FacetUnionFind& uf,
                         FirstOverlappingPair& overlap) {
  const Index lo = first[0].lo, hi = first[0].hi;
  const AroundEdge around{&m, lo, hi, apex_of(b, first[0].facet, lo, hi)};
  auto apex = [&](const DirectedEdge& e) { return apex_of(b, e.facet, lo, hi); };
  std::sort(first, first + n, [&](const DirectedEdge& x, const DirectedEdge& y) { return around.before(apex(x), apex(y)); });
  for (std::size_t i = 0; i + 1 < n; ++i)
    if (!around.before(apex(first[i]), apex(first[i + 1]))) {  // the same half-plane: the triangles overlap
      overlap.note(first[i].facet, first[i + 1].facet);
      return {};
    }
  for (std::size_t i = 0; i < n; ++i) {
    const DirectedEdge& e = first[i];
    const DirectedEdge& f = first[(i + 1) % n];
    if (e.forward == f.forward)
      return pinch(b, f.facet, lo, "around edge (" + std::to_string(lo) + ", " + std::to_string(hi) + ") its " +
                                       std::to_string(n) + " boundary triangles do not alternate in the direction they "
                                       "give the edge, so the elements there cover some direction twice");
  }
  for (std::size_t i = 0; i < n; ++i)
    if (first[i].forward) uf.unite(first[i].facet, first[(i + 1) % n].facet);
  return {};
}

// 3D, edges: every boundary edge in an even number of boundary triangles, as many giving it
// each direction; two of them oriented oppositely, more paired around the edge.
Finding edges_3d(const MeshView& m, const FacetSet& b, FacetUnionFind& uf, FirstOverlappingPair& overlap) {
  std::vector<DirectedEdge> edges;
  edges.reserve(3 * b.size());
  for (std::size_t f = 0; f < b.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const Index u = b.facet(f)[i], w = b.facet(f)[(i + 1) % 3];
      edges.push_back({std::min(u, w), std::max(u, w), u < w, static_cast<std::uint32_t>(f)});
    }
  std::sort(edges.begin(), edges.end(), [](const DirectedEdge& x, const DirectedEdge& y) {
    return x.lo != y.lo ? x.lo < y.lo : (x.hi != y.hi ? x.hi < y.hi : x.facet < y.facet);
  });
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i + 1;
    while (j < edges.size() && edges[j].lo == edges[i].lo && edges[j].hi == edges[i].hi) ++j;
    const std::string edge = "edge (" + std::to_string(edges[i].lo) + ", " + std::to_string(edges[i].hi) + ")";
    const auto forward = static_cast<std::size_t>(std::count_if(edges.begin() + static_cast<std::ptrdiff_t>(i),
                                                                edges.begin() + static_cast<std::ptrdiff_t>(j),
                                                                [](const DirectedEdge& e) { return e.forward; }));
    if (j - i < 2 || 2 * forward != j - i)
      return pinch(b, edges[i].facet, edges[i].lo, edge + " is in " + std::to_string(j - i) + " boundary triangle(s), " +
                                                       std::to_string(forward) + " of them giving it the direction " +
                                                       std::to_string(edges[i].lo) + " -> " + std::to_string(edges[i].hi));
    if (j - i == 2) uf.unite(edges[i].facet, edges[i + 1].facet);
    if (j - i > 2)
      if (Finding f = pair_around_edge(m, b, edges.data() + i, j - i, uf, overlap); f.defect != Defect::none) return f;
    i = j;
  }
  return {};
}

// The components: facets, bounding box, enclosed sign.
void collect_components(const MeshView& m, const FacetSet& b, FacetUnionFind& uf, Components& comps) {
  std::vector<std::size_t> id(b.size(), SIZE_MAX);  // components numbered by first facet
  for (std::size_t i = 0; i < b.size(); ++i) {
    const std::size_t root = uf.find(i), c = id[root] == SIZE_MAX ? (id[root] = comps.facets.size()) : id[root];
    const Box fb = facet_box(m, b.facet(i), m.dim);
    if (c == comps.facets.size()) comps.facets.emplace_back(), comps.vertex.push_back(b.facet(i)[0]), comps.box.push_back(fb);
    comps.facets[c].push_back(i);
    for (int k = 0; k < m.dim; ++k)
      comps.box[c].lo[k] = std::min(comps.box[c].lo[k], fb.lo[k]), comps.box[c].hi[k] = std::max(comps.box[c].hi[k], fb.hi[k]);
  }
  comps.of_facet.assign(b.size(), 0);
  for (std::size_t c = 0; c < comps.facets.size(); ++c)
    for (std::size_t facet : comps.facets[c]) comps.of_facet[facet] = c;
  for (const auto& c : comps.facets) comps.measure_sign.push_back(enclosed_measure_sign(m, b, c));
}

// 2D: each component's lowest, then leftmost vertex v (sweep_2d's order), and the correction
// from W just left of v to W just counterclockwise of the component's last edge at v: the
// sweep weights (+1 downward, -1 upward, 0 horizontal) of the edges at v between them, all in
// the upper half (proofs/mesh_certificate.md, condition 5).
void lowest_vertices_2d(const MeshView& m, const FacetSet& b, const Stars& stars, Components& comps) {
  auto lower = [&](Index v, Index w) {
    return m.coord(v, 1) != m.coord(w, 1) ? m.coord(v, 1) < m.coord(w, 1) : m.coord(v, 0) < m.coord(w, 0);
  };
  for (std::size_t c = 0; c < comps.facets.size(); ++c)
    for (std::size_t facet : comps.facets[c])
      if (lower(b.facet(facet)[0], comps.vertex[c])) comps.vertex[c] = b.facet(facet)[0];
  comps.winding_offset.assign(comps.facets.size(), 0);
  std::vector<char> done(comps.facets.size(), 0);
  for (std::size_t c = 0; c < comps.facets.size(); ++c) {
    const Index v = comps.vertex[c];
    const std::size_t first = stars.start[v], n = stars.start[v + 1] - first;
    if (n == 2 || done[c]) continue;
    const CcwAround ccw{&m, &b, v};
    int sum = 0;  // over the upper half, from its last edge back towards the direction (1, 0)
    for (std::size_t k = n; k-- > 0;) {
      const std::size_t f = stars.facets[first + k];
      if (!ccw.upper(ccw.far(f))) continue;
      const std::size_t owner = comps.of_facet[f];
      if (comps.vertex[owner] == v && !done[owner]) comps.winding_offset[owner] = sum, done[owner] = 1;
      const double from = m.coord(b.facet(f)[0], 1), to = m.coord(b.facet(f)[1], 1);
      sum += from > to ? 1 : (from < to ? -1 : 0);
    }
  }
}

// 3D: each component's vertex is one that no other component passes through, so that the
// winding numbers of the others are defined there and equal their value along the component.
Finding free_vertices_3d(const MeshView& m, const FacetSet& b, Components& comps) {
  std::vector<std::size_t> owner(m.vertex_count, SIZE_MAX);
  std::vector<char> shared(m.vertex_count, 0);
  for (std::size_t i = 0; i < b.vertices.size(); ++i) {
    const Index v = b.vertices[i];
    const std::size_t c = comps.of_facet[i / 3];
    if (owner[v] != SIZE_MAX && owner[v] != c) shared[v] = 1;
    owner[v] = c;
  }
  for (std::size_t c = 0; c < comps.facets.size(); ++c) {
    bool found = false;
    for (std::size_t k = 0; k < comps.facets[c].size() * 3 && !found; ++k) {
      const Index v = b.facet(comps.facets[c][k / 3])[k % 3];
      if (!shared[v]) comps.vertex[c] = v, found = true;
    }
    if (!found)
      return pinch(b, comps.facets[c][0], comps.vertex[c],
                   "every vertex of its boundary component is also on another component; the certificate needs one vertex of "
                   "each component off the others to compare their winding numbers (a limitation, "
                   "proofs/mesh_certificate.md section 7)");
  }
  return {};
}

}  // namespace

Finding check_boundary_manifold(const MeshView& m, const FacetSet& b, Components& comps) {
  FacetUnionFind uf(b.size());
  FirstOverlappingPair overlap;
  Stars stars;
  Finding f = m.dim == 2 ? loops_2d(m, b, uf, stars, overlap) : edges_3d(m, b, uf, overlap);
  if (f.defect != Defect::none) return f;
  if (overlap.a != SIZE_MAX) {
    f = contact_of(m, b, overlap.a, overlap.b, Defect::t_junction, Defect::boundary_intersection,
                   m.dim == 2 ? "boundary edge" : "boundary triangle");
    if (f.defect == Defect::none)  // unreachable: two facets along one ray / half-plane meet
      f = finding(Defect::boundary_intersection, b.owner[overlap.a], b.owner[overlap.b], -1, "two boundary facets overlap");
    return f;
  }
  collect_components(m, b, uf, comps);
  if (m.dim == 2) {
    lowest_vertices_2d(m, b, stars, comps);
    return {};
  }
  return free_vertices_3d(m, b, comps);
}

}  // namespace certimesh::certificate::detail
