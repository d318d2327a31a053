#include "domain_faces.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <string>

#include <boost/pending/disjoint_sets.hpp>

#include "certimesh/predicates/orient2d.h"
#include "sweep_2d.h"

namespace certimesh::certificate::detail {
namespace {

using predicates::Point2;
using predicates::Sign;

bool lower(const Point2& a, const Point2& b) { return sweep_less(a, b); }  // the sweep's order

// Union-find over 0..n-1 (Boost's disjoint sets, path compression and union by rank).
class IndexUnionFind {
 public:
  explicit IndexUnionFind(std::size_t n) : sets_(n) {
    for (std::size_t i = 0; i < n; ++i) sets_.make_set(i);
  }
  std::size_t find(std::size_t x) { return sets_.find_set(x); }
  void unite(std::size_t a, std::size_t b) { sets_.union_set(a, b); }

 private:
  boost::disjoint_sets_with_storage<> sets_;
};

std::string point_text(double x, double y) {
  char s[64];
  std::snprintf(s, sizeof s, "(%.17g, %.17g)", x, y);
  return s;
}

// Half-edge 2f runs segment f from its first vertex to its second, 2f + 1 back.
class Arrangement {
 public:
  Arrangement(const MeshView& g, const FacetSet& s) : g_(g), s_(s), out_(g.vertex_count) {
    for (std::size_t h = 0; h < 2 * s.size(); ++h) out_[tail(h)].push_back(h);
    for (Index v = 0; v < g.vertex_count; ++v)
      std::sort(out_[v].begin(), out_[v].end(), [&](std::size_t a, std::size_t b) { return counterclockwise_before(v, a, b); });
    position_.resize(2 * s.size());
    for (Index v = 0; v < g.vertex_count; ++v)
      for (std::size_t i = 0; i < out_[v].size(); ++i) position_[out_[v][i]] = i;
  }
  Index tail(std::size_t h) const { return s_.facet(h / 2)[h % 2]; }
  Index head(std::size_t h) const { return s_.facet(h / 2)[1 - h % 2]; }
  // The half-edge after h along the face on h's left: clockwise after h's twin around its head.
  std::size_t next(std::size_t h) const {
    const std::vector<std::size_t>& around = out_[head(h)];
    const std::size_t twin = h ^ 1u;
    return around[(position_[twin] + around.size() - 1) % around.size()];
  }
  const std::vector<std::size_t>& outgoing(Index v) const { return out_[v]; }

 private:
  // Angular order from direction 0 (the +x axis) counterclockwise, exactly.
  bool counterclockwise_before(Index o, std::size_t a, std::size_t b) const {
    const Point2 p = g_.p2(o), q = g_.p2(head(a)), r = g_.p2(head(b));
    const auto upper = [&](const Point2& x) { return x.y > p.y || (x.y == p.y && x.x > p.x); };
    if (upper(q) != upper(r)) return upper(q);
    return predicates::orient2d(p, q, r) == Sign::positive;
  }
  const MeshView& g_;
  const FacetSet& s_;
  std::vector<std::vector<std::size_t>> out_;
  std::vector<std::size_t> position_;
};

}  // namespace

Finding domain_faces_2d(const MeshView& geo, const FacetSet& segments, const std::vector<double>& holes,
                        DomainFaces& out) {
  const Arrangement arr(geo, segments);
  const std::size_t halves = 2 * segments.size();
  // Boundary cycles.
  std::vector<std::size_t> cycle(halves, SIZE_MAX);
  std::size_t cycles = 0;
  for (std::size_t h = 0; h < halves; ++h) {
    if (cycle[h] != SIZE_MAX) continue;
    for (std::size_t x = h; cycle[x] == SIZE_MAX; x = arr.next(x)) cycle[x] = cycles;
    ++cycles;
  }
  // Connected components and their lowest vertex; isolated vertices are components too.
  IndexUnionFind vertices(geo.vertex_count);
  for (std::size_t f = 0; f < segments.size(); ++f) vertices.unite(segments.facet(f)[0], segments.facet(f)[1]);
  std::vector<Index> lowest(geo.vertex_count, static_cast<Index>(-1));
  for (Index v = 0; v < geo.vertex_count; ++v) {
    Index& l = lowest[vertices.find(v)];
    if (l == static_cast<Index>(-1) || lower(geo.p2(v), geo.p2(l))) l = v;
  }
  std::vector<std::array<double, 2>> queries;
  std::vector<Index> query_vertex;
  for (Index v = 0; v < geo.vertex_count; ++v)
    if (vertices.find(v) == v) queries.push_back({geo.coord(lowest[v], 0), geo.coord(lowest[v], 1)}), query_vertex.push_back(lowest[v]);
  const std::size_t component_queries = queries.size();
  for (std::size_t h = 0; h < holes.size() / 2; ++h) queries.push_back({holes[2 * h], holes[2 * h + 1]});
  std::vector<SweepAnswer> answers;
  // The domain's own contact check too (load_domain leaves it to this sweep in 2D).
  if (Finding f = sweep_2d(geo, segments, Defect::invalid_domain, Defect::invalid_domain, "domain facet", queries, answers);
      f.defect != Defect::none) {
    f.message = "the domain is not simple: " + f.message;
    return f;
  }
  // The face just left of (and infinitesimally above) a query point: the cycle of the hit
  // segment's half-edge that runs downward (its left side faces +x), or the unbounded face.
  const std::size_t unbounded = cycles;
  const auto face_of = [&](const SweepAnswer& a) -> std::size_t {
    if (a.left_facet < 0) return unbounded;
    const auto f = static_cast<std::size_t>(a.left_facet);
    const bool first_is_lower = lower(geo.p2(segments.facet(f)[0]), geo.p2(segments.facet(f)[1]));
    return cycle[2 * f + (first_is_lower ? 1 : 0)];
  };
  IndexUnionFind faces(cycles + 1);
  std::vector<std::size_t> isolated_face(geo.vertex_count, SIZE_MAX);
  for (std::size_t q = 0; q < component_queries; ++q) {
    const Index v = query_vertex[q];
    const std::vector<std::size_t>& around = arr.outgoing(v);
    if (around.empty()) {  // an isolated vertex
      if (answers[q].on_facet)
        return finding(Defect::invalid_domain, -1, answers[q].left_facet, v,
                       "the domain is not simple: vertex " + std::to_string(v) + ", on no segment, lies on domain segment " +
                           std::to_string(answers[q].left_facet));
      isolated_face[v] = face_of(answers[q]);
      continue;
    }
    // Every edge at the lowest vertex points into the upper half-plane, so the wedge around
    // direction pi (the face around the component) is left of the last one counterclockwise.
    faces.unite(cycle[around.back()], face_of(answers[q]));
  }
  // A hole point on a segment is classified into the face just above-left of it; the hole
  // check (6e) refuses it anyway whenever the mesh reaches it.
  std::vector<char> has_hole(cycles + 1, 0);
  for (std::size_t h = 0; h < holes.size() / 2; ++h) {
    const std::size_t face = faces.find(face_of(answers[component_queries + h]));
    if (face == faces.find(unbounded))
      return finding(Defect::invalid_domain, -1, static_cast<std::int64_t>(h), -1,
                     "the domain's hole point " + std::to_string(h) + " " + point_text(holes[2 * h], holes[2 * h + 1]) +
                         " is outside every face its segments bound: it makes no hole");
    has_hole[face] = 1;
  }
  const auto in_domain = [&](std::size_t c) { const std::size_t f = faces.find(c); return f != faces.find(unbounded) && !has_hole[f]; };
  out.segment_bounds_domain.assign(segments.size(), 0);
  for (std::size_t f = 0; f < segments.size(); ++f) out.segment_bounds_domain[f] = in_domain(cycle[2 * f]) || in_domain(cycle[2 * f + 1]);
  out.isolated_in_domain.assign(geo.vertex_count, 0);
  out.isolated_vertices = 0;
  for (Index v = 0; v < geo.vertex_count; ++v) {
    if (isolated_face[v] == SIZE_MAX) continue;
    ++out.isolated_vertices;
    out.isolated_in_domain[v] = in_domain(isolated_face[v]);
  }
  return {};
}

}  // namespace certimesh::certificate::detail
