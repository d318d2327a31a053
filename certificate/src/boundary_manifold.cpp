// Condition 4, first half: the unmatched facets form a closed manifold (2D: disjoint loops;
// 3D: closed surfaces, each edge in two boundary triangles with opposite orientations, each
// vertex's link a single cycle), split into connected components.
#include <algorithm>
#include <numeric>

#include "stages.h"

namespace certimesh::certificate::detail {
namespace {

struct UnionFind {
  std::vector<std::size_t> parent;
  explicit UnionFind(std::size_t n) : parent(n) { std::iota(parent.begin(), parent.end(), std::size_t{0}); }
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

// 2D: exactly one boundary edge leaves and one enters every boundary vertex.
Finding loops_2d(const MeshView& m, const FacetSet& b, UnionFind& uf) {
  std::vector<std::size_t> leaving(m.vertex_count, SIZE_MAX);
  std::vector<std::uint8_t> in(m.vertex_count, 0), out(m.vertex_count, 0);
  for (std::size_t f = 0; f < b.size(); ++f) {
    const Index u = b.facet(f)[0], w = b.facet(f)[1];
    if (++out[u] > 1) return pinch(b, f, u, "two boundary edges leave it");
    if (++in[w] > 1) return pinch(b, f, w, "two boundary edges enter it");
    leaving[u] = f;
  }
  for (std::size_t f = 0; f < b.size(); ++f) {
    const Index w = b.facet(f)[1];
    if (leaving[w] == SIZE_MAX) return pinch(b, f, w, "a boundary edge ends there");
    uf.unite(f, leaving[w]);
  }
  return {};
}

struct DirectedEdge {
  Index lo, hi;
  bool forward;  // lo -> hi in its facet's orientation
  std::uint32_t facet;
};

// 3D, edges: every boundary edge in exactly two boundary triangles, oriented oppositely.
Finding edges_3d(const FacetSet& b, UnionFind& uf) {
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
    if (j - i != 2) return pinch(b, edges[i].facet, edges[i].lo, edge + " is in " + std::to_string(j - i) + " boundary triangle(s)");
    if (edges[i].forward == edges[i + 1].forward)
      return pinch(b, edges[i].facet, edges[i].lo, edge + " is oriented the same way by both its boundary triangles");
    uf.unite(edges[i].facet, edges[i + 1].facet);
    i = j;
  }
  return {};
}

// 3D, vertices: the triangles around a boundary vertex form one cycle (no pinch). Each
// triangle at v gives a link edge (the vertex after v -> the one after that); every link vertex
// starts exactly one link edge (edges_3d), so the edges sorted by start are followed by binary
// search: O(d log d) for a vertex in d boundary triangles.
Finding links_3d(const MeshView& m, const FacetSet& b) {
  std::vector<std::size_t> start(m.vertex_count + 1, 0);
  for (Index v : b.vertices) ++start[v + 1];
  for (std::size_t v = 0; v < m.vertex_count; ++v) start[v + 1] += start[v];
  std::vector<std::size_t> star(b.vertices.size()), fill(start.begin(), start.end() - 1);
  for (std::size_t i = 0; i < b.vertices.size(); ++i) star[fill[b.vertices[i]]++] = i;
  std::vector<std::pair<Index, Index>> link;
  for (Index v = 0; v < m.vertex_count; ++v) {
    const std::size_t first = start[v], degree = start[v + 1] - start[v];
    if (degree == 0) continue;
    auto after = [&](std::size_t k, std::size_t which) {  // vertex after v (which = 1) or after that (2)
      const std::size_t at = star[first + k];
      return b.vertices[at - at % 3 + (at % 3 + which) % 3];
    };
    link.clear();
    for (std::size_t k = 0; k < degree; ++k) link.push_back({after(k, 1), after(k, 2)});
    std::sort(link.begin(), link.end());
    Index current = link[0].second;
    std::size_t steps = 1;
    for (; current != link[0].first && steps <= degree; ++steps) {
      const auto it = std::lower_bound(link.begin(), link.end(), std::pair<Index, Index>{current, 0});
      if (it == link.end() || it->first != current) break;
      current = it->second;
    }
    if (steps != degree) return pinch(b, star[first] / 3, v, "its boundary triangles form more than one fan");
  }
  return {};
}

}  // namespace

Finding check_boundary_manifold(const MeshView& m, const FacetSet& b, Components& comps) {
  UnionFind uf(b.size());
  Finding f = m.dim == 2 ? loops_2d(m, b, uf) : edges_3d(b, uf);
  if (f.defect == Defect::none && m.dim == 3) f = links_3d(m, b);
  if (f.defect != Defect::none) return f;
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
    for (std::size_t facet : comps.facets[c]) {
      comps.of_facet[facet] = c;
      const Index v = b.facet(facet)[0];  // 2D: the lowest, then leftmost vertex (sweep_2d's order)
      const Index& best = comps.vertex[c];
      if (m.dim == 2 && (m.coord(v, 1) < m.coord(best, 1) || (m.coord(v, 1) == m.coord(best, 1) && m.coord(v, 0) < m.coord(best, 0))))
        comps.vertex[c] = v;
    }
  for (const auto& c : comps.facets) comps.measure_sign.push_back(enclosed_measure_sign(m, b, c));
  return {};
}

}  // namespace certimesh::certificate::detail
