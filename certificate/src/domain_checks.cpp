// Condition 6: the mesh tiles exactly its domain. Points on domain segments / faces follow
// design decision 2: a mesh vertex is on a domain facet when the facet meets the vertex's
// rounding box (the reals that round to it), or the box a tolerance allows, decided exactly
// (on_simplex.h).
#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <optional>
#include <string>

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"
#include "close_pairs.h"
#include "domain_faces.h"
#include "exact_sum.h"
#include "facet_domain_3.h"
#include "on_simplex.h"
#include "rational.h"
#include "segments_near_points_2d.h"
#include "stages.h"
#include "sweep_2d.h"

namespace certimesh::certificate::detail {
namespace {

using IndexEdge = std::pair<Index, Index>;

struct Domain {
  MeshView geo;     // coordinates only
  FacetSet facets;  // segments (2D) or triangles (3D), domain vertex ids
  BoundaryTolerance tolerance;
  // 3D: every edge used as often in each direction by its triangles. Then the solid is where
  // the winding number of the shells is non-zero (design decision 8): an inner shell oriented
  // inward bounds a cavity without a hole point.
  bool oriented = false;
  std::vector<char> pinned;  // per mesh vertex: it is a domain vertex (domain_vertices_in_mesh)
  std::vector<std::int64_t> mesh_vertex_at;  // per domain vertex: the mesh vertex there, or -1
  // 3D, TetGen's polygonal facets (facet_domain_3.h): `facets` holds their triangles, and a
  // face -- what a mesh facet must lie on and what coverage is judged for -- is a whole facet.
  // Otherwise every segment / triangle is its own face.
  bool polygonal = false;
  PolygonalFacets polygons;
  std::vector<std::size_t> plane_of;  // per face: a triangle of it (its plane, its orientation)
  std::vector<double> holes;           // the volume hole points (polygonal domains)
  std::uint32_t face_of(std::size_t t) const { return polygonal ? polygons.facet_of[t] : static_cast<std::uint32_t>(t); }
  std::size_t face_count() const { return polygonal ? polygons.boundary.size() : facets.size(); }
  std::size_t plane(std::size_t face) const { return polygonal ? plane_of[face] : face; }
  // 2D (domain_faces.h): the segments with a domain face on a side; the others (eaten by a
  // hole, or outside) need no coverage.
  std::vector<char> needs_cover;
};

std::vector<Vec> points_of(const MeshView& g, const Index* ids, int count) {
  std::vector<Vec> out;
  for (int i = 0; i < count; ++i) out.push_back(Vec{g.coord(ids[i], 0), g.coord(ids[i], 1), g.dim == 3 ? Q(g.coord(ids[i], 2)) : Q(0)});
  return out;
}
std::vector<Vec> facet_points(const Domain& d, std::size_t f) { return points_of(d.geo, d.facets.facet(f), d.geo.dim); }
std::vector<Vec> face_points(const Domain& d, std::size_t face) { return facet_points(d, d.plane(face)); }
std::array<const double*, 3> corners(const MeshView& g, const Index* ids, int count) {
  std::array<const double*, 3> out{};  // a segment leaves out[2] null
  for (int i = 0; i < count; ++i) out[static_cast<std::size_t>(i)] = g.xyz + static_cast<std::size_t>(ids[i]) * g.dim;
  return out;
}

Finding invalid(const std::string& why, std::int64_t facet = -1) {
  return finding(Defect::invalid_domain, -1, facet, -1, "the domain " + why);
}

// A segment with equal ends, or a triangle with collinear corners (collinear in every
// coordinate plane), exactly.
bool degenerate(const MeshView& g, const Index* x) {
  if (g.dim == 2) return g.coord(x[0], 0) == g.coord(x[1], 0) && g.coord(x[0], 1) == g.coord(x[1], 1);
  for (int k = 0; k < 3; ++k) {
    const int i = k == 0 ? 1 : 0, j = k == 2 ? 1 : 2;  // the plane without axis k
    auto in_plane = [&](Index v) { return predicates::Point2{g.coord(v, i), g.coord(v, j)}; };
    if (predicates::orient2d(in_plane(x[0]), in_plane(x[1]), in_plane(x[2])) != predicates::Sign::zero) return false;
  }
  return true;
}

Finding load_domain(const io::MeshData& data, int dim, Domain& d) {
  if (data.dimension != dim) return invalid("has dimension " + std::to_string(data.dimension) + ", the mesh " + std::to_string(dim));
  d.geo = MeshView{dim, data.coordinates.data(), data.point_count(), nullptr, 0, nullptr};
  for (double x : data.coordinates) if (!std::isfinite(x)) return invalid("has a NaN or infinite coordinate");
  for (double x : data.holes) if (!std::isfinite(x)) return invalid("has a NaN or infinite hole point");
  for (double x : data.facets.holes) if (!std::isfinite(x)) return invalid("has a NaN or infinite facet hole point");
  for (double x : data.region_points) if (!std::isfinite(x)) return invalid("has a NaN or infinite region point");
  d.polygonal = dim == 3 && !data.facets.empty();
  if (d.polygonal && !data.triangles.empty()) return invalid("has both polygonal facets and triangles");
  if (d.polygonal)
    if (Finding e = triangulate_facets(data, d.polygons); e.defect != Defect::none) return e;
  if (d.polygonal) d.holes = data.holes;
  d.facets = FacetSet{dim, dim == 2 ? data.segments : (d.polygonal ? d.polygons.triangles : data.triangles), {}};
  d.facets.owner.resize(d.facets.vertices.size() / static_cast<std::size_t>(dim));
  std::iota(d.facets.owner.begin(), d.facets.owner.end(), 0);
  d.plane_of.assign(d.face_count(), 0);
  for (std::size_t t = d.facets.size(); t-- > 0;) d.plane_of[d.face_of(t)] = t;
  if (d.facets.size() == 0) return invalid(dim == 2 ? "has no segments" : "has no triangles");
  for (std::size_t f = 0; f < d.facets.size(); ++f) {
    const Index* x = d.facets.facet(f);
    for (int i = 0; i < dim; ++i) if (x[i] >= d.geo.vertex_count) return invalid("facet " + std::to_string(f) + " names a missing vertex", static_cast<std::int64_t>(f));
    if (degenerate(d.geo, x)) return invalid("facet " + std::to_string(f) + " is degenerate", static_cast<std::int64_t>(f));
  }
  // 3D: closed shells, every edge in an even number of triangles (two; more where shells touch
  // along an edge: design decision 8); oriented when every edge is used as often each way.
  std::vector<std::pair<IndexEdge, bool>> edges;
  for (std::size_t f = 0; dim == 3 && f < d.facets.size(); ++f)
    for (int i = 0; i < 3; ++i) {
      const Index u = d.facets.facet(f)[i], w = d.facets.facet(f)[(i + 1) % 3];
      edges.push_back({std::minmax(u, w), u < w});
    }
  std::sort(edges.begin(), edges.end());
  d.oriented = dim == 3;
  for (std::size_t i = 0, j = 0; i < edges.size(); i = j) {
    while (j < edges.size() && edges[j].first == edges[i].first) ++j;
    // A closed surface: every edge in an even number of triangles (two, or more at a pinch);
    // TetGen's facets may also meet three or more at an edge (internal facets). None may end free.
    if (d.polygonal ? j - i < 2 : (j - i) % 2 != 0) return invalid("is not a closed surface: edge (" + std::to_string(edges[i].first.first) + ", " + std::to_string(edges[i].first.second) + ") is in " + std::to_string(j - i) + " triangle(s)");
    const auto forward = std::count_if(edges.begin() + static_cast<std::ptrdiff_t>(i), edges.begin() + static_cast<std::ptrdiff_t>(j), [](const auto& e) { return e.second; });
    d.oriented = d.oriented && 2 * static_cast<std::size_t>(forward) == j - i;
  }
  // 2D: the domain's faces (domain_faces_2d, run next by check_domain) sweep the same segments
  // and report the same first contact, with the same words; sweeping them twice was a sixth of
  // the check of a domain with many segments (holey_grid_2d).
  if (dim == 2) return {};
  Finding c = first_contact(d.geo, d.facets, Defect::invalid_domain, Defect::invalid_domain, "domain facet");
  if (c.defect != Defect::none) c.message = "the domain is not simple: " + c.message;
  return c;
}

struct OnFacet {
  Index vertex;
  std::uint32_t facet;
  bool exact;
  friend bool operator<(const OnFacet& a, const OnFacet& b) { return a.vertex != b.vertex ? a.vertex < b.vertex : a.facet < b.facet; }
};

// Which mesh vertices are domain vertices (identical coordinates): of each mesh vertex, the
// range of `order` (the domain vertices sorted by coordinates) at its point, empty if none.
// Such a vertex is an exact input point: it lies on a domain facet only exactly (and then, the
// domain being valid, at one of the facet's own vertices), never through its rounding box --
// otherwise rounding slack would let the mesh boundary hop from one domain component onto
// another (issue 12).
struct DomainVertexMatch {
  std::vector<Index> order;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> range;  // per mesh vertex, into `order`
};
DomainVertexMatch domain_vertices_in_mesh(const MeshView& m, const Domain& d) {
  DomainVertexMatch match;
  std::vector<Index>& order = match.order;
  order.resize(d.geo.vertex_count);
  std::iota(order.begin(), order.end(), Index{0});
  auto at = [](const MeshView& g, Index v) { return g.xyz + static_cast<std::size_t>(v) * g.dim; };
  auto less = [&](const double* a, const double* b) { return std::lexicographical_compare(a, a + m.dim, b, b + m.dim); };
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return less(at(d.geo, a), at(d.geo, b)); });
  match.range.resize(m.vertex_count);
  for (Index v = 0; v < m.vertex_count; ++v) {
    const double* p = at(m, v);
    auto it = std::lower_bound(order.begin(), order.end(), p, [&](Index u, const double* q) { return less(at(d.geo, u), q); });
    const auto first = static_cast<std::uint32_t>(it - order.begin());
    while (it != order.end() && std::equal(p, p + m.dim, at(d.geo, *it))) ++it;
    match.range[v] = {first, static_cast<std::uint32_t>(it - order.begin())};
  }
  return match;
}

// The domain facets at each domain vertex (counting sort): `facet[offset[u] .. offset[u + 1])`.
struct FacetsAtVertex {
  std::vector<std::size_t> offset;
  std::vector<std::uint32_t> facet;
};
FacetsAtVertex facets_at_vertices(const Domain& d) {
  FacetsAtVertex at;
  const int k = d.geo.dim;  // corners per facet
  at.offset.assign(d.geo.vertex_count + 1, 0);
  for (std::size_t f = 0; f < d.facets.size(); ++f)
    for (int i = 0; i < k; ++i) ++at.offset[d.facets.facet(f)[i] + 1];
  for (std::size_t u = 0; u < d.geo.vertex_count; ++u) at.offset[u + 1] += at.offset[u];
  at.facet.resize(at.offset.back());
  std::vector<std::size_t> fill(at.offset.begin(), at.offset.end() - 1);
  for (std::size_t f = 0; f < d.facets.size(); ++f)
    for (int i = 0; i < k; ++i) at.facet[fill[d.facets.facet(f)[i]]++] = static_cast<std::uint32_t>(f);
  return at;
}

// Sorted, one incidence per (vertex, face), exact if any is: a face's triangles share edges.
std::vector<OnFacet> finish_incidences(std::vector<OnFacet>& out) {
  std::sort(out.begin(), out.end());
  std::size_t kept = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (kept > 0 && out[kept - 1].vertex == out[i].vertex && out[kept - 1].facet == out[i].facet) {
      out[kept - 1].exact = out[kept - 1].exact || out[i].exact;
    } else {
      out[kept++] = out[i];
    }
  }
  out.resize(kept);
  return out;
}

// Every (mesh vertex, domain facet) incidence by the rounding-box rule (exact only, for a mesh
// vertex that is a domain vertex). A mesh vertex at a domain vertex with facets is on exactly
// those facets: the domain passed its first-contact test, so its vertices lie on no other
// facet. Every other mesh vertex is tested against candidate facets: in 2D with rounding boxes,
// those of the sweep of segments_near_points_2d.h; otherwise those whose double bounding box
// meets its accepted box (a point outside a facet's bounding box has its rounding box outside).
std::vector<OnFacet> incidences(const MeshView& m, const Domain& d, const DomainVertexMatch& match) {
  const FacetsAtVertex at = facets_at_vertices(d);
  std::vector<OnFacet> out;
  std::vector<Index> unmatched;  // vertices the broad phase must answer for
  for (Index v = 0; v < m.vertex_count; ++v) {
    const std::size_t before = out.size();
    for (std::uint32_t i = match.range[v].first; i < match.range[v].second; ++i)
      for (std::size_t k = at.offset[match.order[i]]; k < at.offset[match.order[i] + 1]; ++k) out.push_back({v, d.face_of(at.facet[k]), true});
    if (out.size() == before) unmatched.push_back(v);
  }
  auto test = [&](Index v, std::size_t f) {
    const double* p = m.xyz + static_cast<std::size_t>(v) * m.dim;
    const auto s = corners(d.geo, d.facets.facet(f), m.dim);
    const bool exact = lies_exactly_on(s, m.dim, p);  // then its box meets it
    if (exact || (!d.pinned[v] && meets_accepted_box(s, m.dim, p, d.tolerance))) out.push_back({v, d.face_of(f), exact});
  };
  if (unmatched.empty()) return finish_incidences(out);
  if (m.dim == 2 && !d.tolerance.active()) {  // rounding boxes: the sweep, O(n log n + k)
    std::vector<Segment2> segments;
    for (std::size_t f = 0; f < d.facets.size(); ++f) segments.push_back({d.geo.p2(d.facets.facet(f)[0]), d.geo.p2(d.facets.facet(f)[1])});
    std::vector<predicates::Point2> points;
    for (Index v : unmatched) points.push_back(m.p2(v));
    for (const auto& [q, f] : segments_near_points_2d(segments, points)) test(unmatched[q], f);
  } else {  // 3D, or a tolerance's wider boxes: a box grid (quadratic where many boxes overlap)
    std::vector<Box> boxes;
    for (std::size_t f = 0; f < d.facets.size(); ++f) boxes.push_back(facet_box(d.geo, d.facets.facet(f), d.geo.dim));
    const BoxGrid grid(boxes, m.dim);
    for (Index v : unmatched)
      grid.each_overlapping(accepted_bounds(m.xyz + static_cast<std::size_t>(v) * m.dim, m.dim, d.tolerance), [&](std::size_t f) { test(v, f); });
  }
  return finish_incidences(out);
}

// Distance from mesh vertex v to the line / plane of domain facet f, for the report: exact up
// to the final rounding (the deviations are below an ulp, and at coordinates near 2^900 or
// 2^-1000 the squares would overflow or underflow in double).
// 2D: |u|^2 of each face, read once (mantissa, exponent; mantissa 0: not yet read).
using SquaredLengths = std::vector<std::pair<double, long>>;
double deviation(const MeshView& m, Index v, const Domain& d, std::size_t f, SquaredLengths* cache = nullptr) {
  if (m.dim == 2) {  // |u x (v - a)| / |u|, u = b - a, in integers times powers of two
    const Index* s = d.facets.facet(d.plane(f));
    const double *a = d.geo.xyz + 2 * static_cast<std::size_t>(s[0]), *b = d.geo.xyz + 2 * static_cast<std::size_t>(s[1]);
    std::pair<double, long> uu{0.0, 0};
    if (cache != nullptr) uu = (*cache)[f];
    if (uu.first == 0) {
      bool cut = false;
      uu.first = dot_of_differences(a, b, a, b).magnitude_2exp(uu.second, cut);
      if (cache != nullptr) (*cache)[f] = uu;
    }
    return ratio_to_root(cross_from(a, b, m.xyz + 2 * static_cast<std::size_t>(v)), uu.first, uu.second);
  }
  const std::vector<Vec> p = face_points(d, f);
  const Vec e = minus(p[1], p[0]), n = m.dim == 2 ? Vec{-e[1], e[0], 0} : cross(e, minus(p[2], p[0]));
  const Q along = dot(n, minus(point_of(m, v), p[0]));
  return sqrt_of(along * along / dot(n, n));
}

// Distance from mesh vertex v to the closed domain segment f (2D), or to the plane of domain
// triangle f (3D: a lower bound on the distance to the triangle), for a refusal message.
double distance_to(const MeshView& m, Index v, const Domain& d, std::size_t f) {
  if (m.dim == 3) return deviation(m, v, d, f);
  const std::vector<Vec> s = facet_points(d, f);
  const Vec u = minus(s[1], s[0]), w = minus(point_of(m, v), s[0]);
  Q t = dot(u, w) / dot(u, u);
  t = t < 0 ? Q(0) : (t > 1 ? Q(1) : t);
  const Vec gap = minus(w, Vec{t * u[0], t * u[1], 0});
  return sqrt_of(dot(gap, gap));
}

// vertex_off_domain_boundary for v, naming the nearest domain facet and the distance to it.
Finding vertex_off(const MeshView& m, Index v, const Domain& d) {
  std::size_t nearest = 0;
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < d.face_count(); ++f)
    if (const double x = distance_to(m, v, d, f); x < best) best = x, nearest = f;
  std::string at;
  for (int k = 0; k < m.dim; ++k) {
    char x[32];
    std::snprintf(x, sizeof x, "%.17g", m.coord(v, k));
    at += (k ? ", " : "(") + std::string(x);
  }
  char distance[32];
  std::snprintf(distance, sizeof distance, "%.3g", best);
  return finding(Defect::vertex_off_domain_boundary, -1, static_cast<std::int64_t>(nearest), v,
                 "boundary vertex " + std::to_string(v) + " " + at + ") is on no domain " + (m.dim == 2 ? "segment" : (d.polygonal ? "facet" : "triangle")) +
                     ": the nearest, " + std::to_string(nearest) + ", is " + distance + " away" +
                     (m.dim == 3 ? " (from its plane)" : "") +
                     (d.tolerance.active() ? ", beyond the boundary tolerance" : "; the exact rule allows half an ulp per coordinate (see --boundary-tolerance)"));
}

// Incidences of every mesh vertex, and the first domain facet all of `count` vertices are on.
struct OnDomain {
  OnDomain(std::vector<OnFacet> incidences, std::size_t vertex_count) : on(std::move(incidences)), first(vertex_count + 1, 0) {
    for (const OnFacet& o : on) ++first[o.vertex + 1];
    for (std::size_t v = 0; v < vertex_count; ++v) first[v + 1] += first[v];
  }
  std::vector<OnFacet> on;         // sorted by vertex, then facet
  std::vector<std::size_t> first;  // of vertex v: on[first[v] .. first[v + 1])
  std::pair<const OnFacet*, const OnFacet*> range(Index v) const { return {on.data() + first[v], on.data() + first[v + 1]}; }
  bool has(Index v, std::uint32_t facet) const {
    const auto r = range(v);
    return std::binary_search(r.first, r.second, OnFacet{v, facet, false});
  }
  std::uint32_t common(const Index* x, int count) const {
    for (auto it = range(x[0]).first; it != range(x[0]).second; ++it)
      if (std::all_of(x + 1, x + count, [&](Index v) { return has(v, it->facet); }))
        return it->facet;
    return UINT32_MAX;
  }
};

// facet_off_domain_boundary (a facet whose vertices are all on the domain boundary but on no
// common domain facet), then vertex_off_domain_boundary, for the mesh boundary.
Finding boundary_on_domain(const MeshView& m, const FacetSet& b, const Domain& d, const OnDomain& on, Statistics& stats) {
  for (std::size_t f = 0; f < b.size(); ++f) {
    const Index* x = b.facet(f);
    if (std::none_of(x, x + m.dim, [&](Index v) { return on.range(v).first == on.range(v).second; }) && on.common(x, m.dim) == UINT32_MAX)
      return finding(Defect::facet_off_domain_boundary, b.owner[f], -1, x[0],
                     "boundary facet " + std::to_string(f) + " of element " + std::to_string(b.owner[f]) + " lies on no single domain facet");
  }
  SquaredLengths squared_lengths(m.dim == 2 ? d.face_count() : 0, {0.0, 0});
  std::vector<Index> verts(b.vertices);
  std::sort(verts.begin(), verts.end());
  verts.erase(std::unique(verts.begin(), verts.end()), verts.end());
  for (Index v : verts) {
    const auto r = on.range(v);
    if (r.first == r.second) return vertex_off(m, v, d);
    if (std::any_of(r.first, r.second, [](const OnFacet& o) { return o.exact; })) { ++stats.vertices_exactly_on_domain_boundary; continue; }
    ++stats.vertices_in_rounding_box_only;
    stats.max_boundary_deviation = std::max(stats.max_boundary_deviation, deviation(m, v, d, r.first->facet, &squared_lengths));
  }
  return {};
}

// The mesh edges between vertices on the domain boundary, as each such vertex's neighbours
// (interior edges included: they cover internal constraints). A counting sort by first vertex,
// so the cost is linear in the elements whatever their order.
struct NearEdges {
  std::vector<std::size_t> offset;  // neighbours of v: around[offset[v] .. offset[v + 1])
  std::vector<Index> around;
  const Index* begin(Index v) const { return around.data() + offset[v]; }
  const Index* end(Index v) const { return around.data() + offset[v + 1]; }
};
NearEdges mesh_edges(const MeshView& m, const std::vector<char>& near) {
  NearEdges e;
  e.offset.assign(m.vertex_count + 1, 0);
  auto each_pair = [&](auto&& use) {
    for (std::size_t c = 0; c < m.element_count; ++c)
      for (int i = 0; i < m.corners(); ++i)
        for (int j = 0; j < m.corners(); ++j)
          if (i != j && near[m.cell(c)[i]] && near[m.cell(c)[j]]) use(m.cell(c)[i], m.cell(c)[j]);
  };
  each_pair([&](Index u, Index) { ++e.offset[u + 1]; });
  for (std::size_t v = 0; v < m.vertex_count; ++v) e.offset[v + 1] += e.offset[v];
  e.around.resize(e.offset.back());
  std::vector<std::size_t> fill(e.offset.begin(), e.offset.end() - 1);
  each_pair([&](Index u, Index w) { e.around[fill[u]++] = w; });
  std::size_t out = 0;  // each neighbour once, in order, compacted in place
  for (std::size_t v = 0; v < m.vertex_count; ++v) {
    Index* first = e.around.data() + e.offset[v];
    Index* last = e.around.data() + e.offset[v + 1];
    std::sort(first, last);
    e.offset[v] = out;
    for (Index *w = first, *kept = std::unique(first, last); w != kept; ++w) e.around[out++] = *w;
  }
  e.offset[m.vertex_count] = out;
  e.around.resize(out);
  return e;
}

// The mesh vertex with exactly the coordinates p, by binary search in the coordinate order.
std::int64_t find_vertex(const MeshView& m, const std::vector<Index>& lex, const double* p) {
  const auto it = std::lower_bound(lex.begin(), lex.end(), p, [&](Index v, const double* q) {
    return vertex_order_less(m.xyz + static_cast<std::size_t>(v) * m.dim, q, m.dim);
  });
  return it != lex.end() && std::equal(p, p + m.dim, m.xyz + static_cast<std::size_t>(*it) * m.dim) ? static_cast<std::int64_t>(*it) : -1;
}

// From the mesh vertex at domain point a to the one at b along mesh edges whose ends are on
// segment ab (`on_ab`: the incidence rule of the domain facet, and in 3D the edge's own rounding-
// box rule), greedily towards b: success shows ab covered by mesh edges. `path` receives the mesh
// vertices from a to b; `seen` (one stamp per vertex, `stamp` this walk's) keeps each vertex once
// without a search.
template <class OnSegment>
bool walk(const MeshView& m, const NearEdges& edges, std::int64_t start, std::int64_t target, const double* b,
          const OnSegment& on_ab, std::vector<Index>& path, std::vector<std::uint32_t>& seen, std::uint32_t stamp) {
  path.clear();
  if (start < 0 || target < 0) return false;
  path.push_back(static_cast<Index>(start));
  seen[path[0]] = stamp;
  for (Index u = path[0]; u != target;) {
    std::int64_t best = -1;
    double best_distance = std::numeric_limits<double>::infinity();
    for (const Index* w = edges.begin(u); w != edges.end(u); ++w) {
      const double* p = m.xyz + static_cast<std::size_t>(*w) * m.dim;
      double dist = 0;  // max-norm: squares would overflow for huge coordinates
      for (int k = 0; k < m.dim; ++k) dist = std::max(dist, std::abs(p[k] - b[k]));
      if ((best < 0 || dist < best_distance) && seen[*w] != stamp && on_ab(*w)) best = *w, best_distance = dist;
    }
    if (best < 0) return false;
    path.push_back(u = static_cast<Index>(best));
    seen[u] = stamp;
  }
  return true;
}

// 3D, the analogue of the 2D segment chains: a mesh triangle on domain triangle T, with the
// side of T's plane its element lies on (0 when the element's fourth vertex is on the plane).
struct TriangleOnFace {
  std::uint32_t home;
  std::array<Index, 3> vertices;
  int side;
  std::size_t element;
  friend bool operator<(const TriangleOnFace& a, const TriangleOnFace& b) {
    return a.home != b.home ? a.home < b.home : (a.vertices != b.vertices ? a.vertices < b.vertices : a.element < b.element);
  }
};

int side_of(const Domain& d, std::uint32_t face, const predicates::Point3& p) {
  const Index* t = d.facets.facet(d.plane(face));
  return static_cast<int>(predicates::orient3d(d.geo.p3(t[0]), d.geo.p3(t[1]), d.geo.p3(t[2]), p));
}

// The mesh triangles on each domain triangle T are all boundary triangles whose elements lie on
// one side of T (T bounds the domain), or all interior (T is inside it: an interface): a face
// covered partly one way and partly the other, or bounded from both sides, means the mesh
// boundary leaves T through rounding slack (issue 12, as segment_chains.cpp in 2D).
Finding faces_bound_one_side(std::vector<TriangleOnFace>& sides) {
  std::sort(sides.begin(), sides.end());
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t end = i;
    int boundary_side = 0;
    bool boundary = false, interior = false;
    for (; end < sides.size() && sides[end].home == sides[i].home; ) {
      std::size_t same = end + 1;
      while (same < sides.size() && sides[same].home == sides[end].home && sides[same].vertices == sides[end].vertices) ++same;
      const bool is_boundary = same - end == 1;
      (is_boundary ? boundary : interior) = true;
      const int side = sides[end].side;
      if (is_boundary && side != 0 && boundary_side != 0 && side != boundary_side)
        return finding(Defect::domain_boundary_not_covered, static_cast<std::int64_t>(sides[end].element), sides[end].home, -1,
                       "domain triangle " + std::to_string(sides[end].home) + " is bounded by mesh elements on both of its sides");
      if (is_boundary && side != 0) boundary_side = side;
      end = same;
    }
    if (boundary && interior)
      return finding(Defect::domain_boundary_not_covered, static_cast<std::int64_t>(sides[i].element), sides[i].home, -1,
                     "domain triangle " + std::to_string(sides[i].home) + " is covered partly by mesh boundary triangles and partly by interior ones");
    i = end;
  }
  return {};
}

// The domain's winding number on the far side of domain triangle `home` from mesh element
// `element` on it, or nullopt when it cannot be decided here. W_D is taken exactly at the
// element's rounded centroid, once orient3d confirms that point strictly inside the element and
// on no domain triangle (so in the region on the element's side), and W_D changes by one across
// the triangle, down in the direction of its normal.
std::optional<int> winding_beyond(const MeshView& m, const Domain& d, std::uint32_t home, std::size_t element) {
  const Index* c = m.cell(element);
  double centre[3];
  for (int k = 0; k < 3; ++k) centre[k] = (m.coord(c[0], k) + m.coord(c[1], k) + m.coord(c[2], k) + m.coord(c[3], k)) / 4;
  const predicates::Point3 p{centre[0], centre[1], centre[2]};
  for (int i = 0; i < 4; ++i) {  // strictly inside: on the inner side of every face (kFace order of facet_pairing)
    static constexpr int face[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};
    if (predicates::orient3d(m.p3(c[face[i][0]]), m.p3(c[face[i][1]]), m.p3(c[face[i][2]]), p) != predicates::Sign::positive)
      return std::nullopt;
  }
  for (std::size_t f = 0; f < d.facets.size(); ++f)
    if (lies_exactly_on(corners(d.geo, d.facets.facet(f), 3), 3, centre)) return std::nullopt;
  const int side = side_of(d, home, p);  // > 0: the element is on the side opposite the normal
  if (side == 0) return std::nullopt;
  std::vector<std::size_t> all(d.facets.size());
  std::iota(all.begin(), all.end(), std::size_t{0});
  const int here = winding_number(d.geo, d.facets, all, centre);
  return side > 0 ? here - 1 : here + 1;
}

// With an oriented domain, a domain triangle inside the mesh (an interface) must have solid on
// both sides: the same cube with its inward cavity filled is not a mesh of the domain.
Finding interfaces_inside_solid(const MeshView& m, const Domain& d, const std::vector<TriangleOnFace>& sides) {
  for (std::size_t i = 0; i < sides.size();) {
    std::size_t end = i;
    while (end < sides.size() && sides[end].home == sides[i].home) ++end;
    const bool interior = end - i >= 2 && sides[i].vertices == sides[i + 1].vertices;  // all alike (faces_bound_one_side)
    for (std::size_t k = i; interior && k < end; ++k) {
      const std::optional<int> beyond = winding_beyond(m, d, sides[k].home, sides[k].element);
      if (!beyond) continue;
      if (*beyond == 0)
        return finding(Defect::hole_covered, static_cast<std::int64_t>(sides[k].element), sides[k].home, -1,
                       "the mesh covers both sides of domain triangle " + std::to_string(sides[k].home) +
                           ", but by the orientation of the domain's shells one side is outside the solid (winding number 0)");
      break;
    }
    i = end;
  }
  return {};
}

// Every domain facet covered: its edges by chains of mesh edges (walk), and in 3D its area by
// the mesh facets on it, whose mod-2 boundary must be exactly those chains: a 2-chain with
// that boundary covers the face an odd number of times, and non-overlapping facets cover once.
// In 2D the chains then go to check_segment_chains (how each segment is covered).
// The domain edges whose mesh-edge chains face f needs, and which of them bound it: a segment;
// a triangle's three edges; a polygonal facet's every polygon edge, of which those in an odd
// number of its polygons bound its region (the others are inside it, covered from both sides).
void face_edges(const Domain& d, std::size_t f, std::vector<IndexEdge>& walked, std::vector<char>& bounding) {
  walked.clear();
  bounding.clear();
  if (d.polygonal) {
    walked = d.polygons.edges[f];
    for (const IndexEdge& e : walked) bounding.push_back(std::binary_search(d.polygons.boundary[f].begin(), d.polygons.boundary[f].end(), e));
    return;
  }
  const Index* x = d.facets.facet(f);
  const int n = d.geo.dim == 2 ? 1 : 3;
  for (int i = 0; i < n; ++i) walked.push_back({x[i], x[(i + 1) % d.geo.dim]}), bounding.push_back(1);
}

Finding coverage(const MeshView& m, const FacetSet& b, const Domain& d, const OnDomain& on, Statistics& stats,
                 std::vector<char>& face_on_facet) {
  std::vector<char> near(m.vertex_count, 0);  // on the domain boundary: only these matter below
  for (const OnFacet& o : on.on) near[o.vertex] = 1;
  const NearEdges edges = mesh_edges(m, near);
  std::vector<std::pair<std::uint32_t, std::array<Index, 3>>> on_face;  // (domain facet, mesh facet), once each
  std::vector<TriangleOnFace> sides;  // and the side of the domain facet its element(s) lie on
  for (std::size_t e = 0; m.dim == 3 && e < m.element_count; ++e)
    for (int i = 0; i < 4; ++i) {
      std::array<Index, 3> x{m.cell(e)[(i + 1) % 4], m.cell(e)[(i + 2) % 4], m.cell(e)[(i + 3) % 4]};
      if (!near[x[0]] || !near[x[1]] || !near[x[2]]) continue;
      std::sort(x.begin(), x.end());
      if (const std::uint32_t home = on.common(x.data(), 3); home != UINT32_MAX) {
        face_on_facet[4 * e + static_cast<std::size_t>(i)] = 1;
        on_face.push_back({home, x});
        sides.push_back({home, x, side_of(d, home, m.p3(m.cell(e)[i])), e});
      }
    }
  std::sort(on_face.begin(), on_face.end());
  on_face.erase(std::unique(on_face.begin(), on_face.end()), on_face.end());
  if (Finding f = faces_bound_one_side(sides); f.defect != Defect::none) return f;
  if (d.oriented)
    if (Finding f = interfaces_inside_solid(m, d, sides); f.defect != Defect::none) return f;
  auto next = on_face.begin();
  std::vector<std::uint32_t> seen(m.vertex_count, 0);
  std::uint32_t stamp = 0;
  std::vector<SegmentChain> chains;
  std::vector<IndexEdge> walked;
  std::vector<char> bounding;
  for (std::size_t f = 0; f < d.face_count(); ++f) {
    // A TetGen facet no mesh face lies on is allowed when the domain's hole points make both
    // of its sides void (TetGen removes it: the window of its example.poly).
    if (d.polygonal && (next == on_face.end() || next->first != f) && facet_void_on_both_sides(d.geo, d.facets, d.polygons, static_cast<std::uint32_t>(f), d.holes))
      continue;
    const bool optional = !d.needs_cover.empty() && !d.needs_cover[f];  // 2D, eaten: covered or not at all
    face_edges(d, f, walked, bounding);
    std::vector<IndexEdge> chain, edges_on_face, odd;
    std::vector<Index> path;
    bool complete = true;
    for (std::size_t i = 0; i < walked.size() && complete; ++i) {
      const auto [from, to] = walked[i];
      const double* a = d.geo.xyz + static_cast<std::size_t>(from) * m.dim;
      const double* z = d.geo.xyz + static_cast<std::size_t>(to) * m.dim;
      auto on_az = [&](Index w) {  // 2D: the segment's incidence; 3D: also on the facet's edge az
        if (!on.has(w, static_cast<std::uint32_t>(f))) return false;
        if (m.dim == 2) return true;
        const double* p = m.xyz + static_cast<std::size_t>(w) * m.dim;
        return lies_exactly_on({a, z, nullptr}, m.dim, p) || (!d.pinned[w] && meets_accepted_box({a, z, nullptr}, m.dim, p, d.tolerance));
      };
      complete = walk(m, edges, d.mesh_vertex_at[from], d.mesh_vertex_at[to], z, on_az, path, seen, ++stamp);
      if (!complete && optional) break;
      if (!complete)
        return finding(Defect::domain_boundary_not_covered, -1, static_cast<std::int64_t>(f), -1,
                       "domain facet " + std::to_string(f) + ": its edge from domain vertex " + std::to_string(from) + " to " +
                           std::to_string(to) + " is not covered by mesh edges on it");
      for (std::size_t k = 0; bounding[i] && k + 1 < path.size(); ++k) chain.push_back(std::minmax(path[k], path[k + 1]));
    }
    if (m.dim == 2) {
      // An eaten segment that the mesh covers anyway keeps its chain, so that a mesh reaching
      // into a hole face is refused where it is plainest (6e: the hole point is covered).
      if (!complete) continue;
      chains.push_back({static_cast<std::int64_t>(f), std::move(path)});
      continue;
    }
    for (; next != on_face.end() && next->first == f; ++next)
      for (int i = 0; i < 3; ++i) edges_on_face.push_back(std::minmax(next->second[i], next->second[(i + 1) % 3]));
    std::sort(edges_on_face.begin(), edges_on_face.end());
    for (std::size_t i = 0, j = 0; i < edges_on_face.size(); i = j) {
      while (j < edges_on_face.size() && edges_on_face[j] == edges_on_face[i]) ++j;
      if ((j - i) % 2 == 1) odd.push_back(edges_on_face[i]);
    }
    std::sort(chain.begin(), chain.end());
    chain.erase(std::unique(chain.begin(), chain.end()), chain.end());
    if (odd != chain)
      return finding(Defect::domain_boundary_not_covered, -1, static_cast<std::int64_t>(f), -1,
                     std::string(d.polygonal ? "domain facet " : "domain triangle ") + std::to_string(f) +
                         " is not covered exactly by the mesh triangles on it");
  }
  return m.dim == 2 ? check_segment_chains(m, b, chains, stats) : Finding{};
}

// A hole point covered or a cavity without one, reported (after the per-dimension passes).
Finding hole_covered(std::size_t h) {
  return finding(Defect::hole_covered, -1, static_cast<std::int64_t>(h), -1, "hole point " + std::to_string(h) + " is covered by the mesh");
}
Finding cavities_need_holes(const FacetSet& b, const Components& comps, const std::vector<char>& has_hole) {
  for (std::size_t c = 0; c < comps.facets.size(); ++c)
    if (comps.measure_sign[c] < 0 && !has_hole[c])
      return finding(Defect::region_not_meshed, b.owner[comps.facets[c][0]], -1, comps.vertex[c],
                     "the region inside the boundary component through vertex " + std::to_string(comps.vertex[c]) +
                         " is not meshed and holds no hole point");
  return {};
}

// 2D, one sweep for all hole points: a hole point on a boundary edge or at a mesh vertex, or
// with W != 0 just left of it, is covered; otherwise the first edge its leftward ray hits
// bounds its face: a cavity component (the face is its inside) or an island, whose
// surrounding cavity single_cover_2d found (`around`).
Finding holes_and_regions_2d(const MeshView& m, const FacetSet& b, const Components& comps, const std::vector<Index>& lex,
                             const io::MeshData& data) {
  std::vector<std::array<double, 2>> at(data.hole_count());
  for (std::size_t h = 0; h < at.size(); ++h) at[h] = {data.holes[2 * h], data.holes[2 * h + 1]};
  std::vector<SweepAnswer> answers = comps.hole_answers;  // check_single_cover's sweep, when it had them
  if (answers.size() != at.size())
    if (Finding f = sweep_2d(m, b, Defect::t_junction, Defect::boundary_intersection, "boundary edge", at, answers, &lex); f.defect != Defect::none)
      return f;
  std::vector<char> has_hole(comps.facets.size(), 0);
  for (std::size_t h = 0; h < at.size(); ++h) {
    if (answers[h].on_facet || answers[h].winding != 0 || find_vertex(m, lex, at[h].data()) >= 0) return hole_covered(h);
    if (answers[h].left_facet < 0) continue;  // the unbounded face
    const std::size_t hit = comps.of_facet[static_cast<std::size_t>(answers[h].left_facet)];
    const std::int64_t bounding = comps.measure_sign[hit] < 0 ? static_cast<std::int64_t>(hit) : comps.around[hit];
    if (bounding >= 0) has_hole[static_cast<std::size_t>(bounding)] = 1;
  }
  return cavities_need_holes(b, comps, has_hole);
}

// 3D: each hole point strictly outside the mesh (W = 0, off the boundary), and each cavity
// component of the mesh boundary the innermost component around some hole point. Only the
// facets of components whose box holds p can hold p or wind around it.
// With an oriented domain, a cavity of the mesh whose inside the shells' winding number says
// is outside the solid needs no hole point.
bool cavity_outside_solid(const MeshView& m, const FacetSet& b, const Components& comps, std::size_t c, const Domain& d,
                          const OnDomain& on) {
  if (!d.oriented) return false;
  for (std::size_t f : comps.facets[c]) {
    const Index* x = b.facet(f);
    const std::uint32_t home = on.common(x, 3);
    if (home == UINT32_MAX) continue;
    if (const std::optional<int> beyond = winding_beyond(m, d, home, static_cast<std::size_t>(b.owner[f]))) return *beyond == 0;
  }
  return false;
}

Finding holes_and_regions_3d(const MeshView& m, const FacetSet& b, const Components& comps, const Domain& d,
                             const OnDomain& on, const io::MeshData& data) {
  std::vector<char> has_hole(comps.facets.size(), 0);
  for (std::size_t h = 0; h < data.hole_count(); ++h) {
    const double* p = data.holes.data() + h * static_cast<std::size_t>(m.dim);
    auto inside = [&](const Box& box) { return boxes_overlap(box, Box{{p[0], p[1], p[m.dim - 1]}, {p[0], p[1], p[m.dim - 1]}}, m.dim); };
    bool covered = false;
    int w = 0;
    std::size_t innermost = SIZE_MAX;
    for (std::size_t c = 0; c < comps.facets.size() && !covered; ++c) {
      if (!inside(comps.box[c])) continue;
      for (std::size_t f : comps.facets[c])
        if (!covered && inside(facet_box(m, b.facet(f), m.dim))) covered = lies_exactly_on(corners(m, b.facet(f), m.dim), m.dim, p);
      const int wc = covered ? 0 : winding_number(m, b, comps.facets[c], p);
      w += wc;
      if (wc != 0 && (innermost == SIZE_MAX || comps.enclosed_by[c].size() > comps.enclosed_by[innermost].size())) innermost = c;
    }
    if (covered || w != 0) return hole_covered(h);
    if (innermost != SIZE_MAX) has_hole[innermost] = 1;
    else if (d.polygonal && point_escapes(d.geo, d.facets, p))  // TetGen's rule, as decision 8's in 2D
      return invalid("has hole point " + std::to_string(h) + " outside the solid (a ray from it leaves the domain crossing no facet)");
  }
  for (std::size_t c = 0; c < comps.facets.size(); ++c)
    if (comps.measure_sign[c] < 0 && !has_hole[c]) has_hole[c] = cavity_outside_solid(m, b, comps, c, d, on);
  return cavities_need_holes(b, comps, has_hole);
}

// 2D: the faces of the domain (domain_faces.h); every isolated domain vertex inside the domain
// is a mesh vertex (design decision 8).
Finding faces_and_isolated_vertices(const MeshView& m, const std::vector<Index>& lex, const io::MeshData& data, Domain& d) {
  DomainFaces faces;
  if (Finding f = domain_faces_2d(d.geo, d.facets, data.holes, faces); f.defect != Defect::none) return f;
  d.needs_cover = std::move(faces.segment_bounds_domain);
  for (Index v = 0; v < d.geo.vertex_count; ++v) {
    if (!faces.isolated_in_domain[v] || find_vertex(m, lex, d.geo.xyz + 2 * static_cast<std::size_t>(v)) >= 0) continue;
    char at[80];
    std::snprintf(at, sizeof at, "(%.17g, %.17g)", d.geo.coord(v, 0), d.geo.coord(v, 1));
    return finding(Defect::domain_boundary_not_covered, -1, -1, -1,
                   "domain vertex " + std::to_string(v) + " " + at + ", on no segment and inside the domain, is not a mesh vertex");
  }
  return {};
}

}  // namespace

Finding check_domain(const MeshView& m, const FacetSet& boundary, const Components& comps,
                     const std::vector<Index>& lex_order, const io::MeshData& domain, const BoundaryTolerance& tolerance,
                     Statistics& stats) {
  Domain d;
  d.tolerance = tolerance;
  stats.boundary_tolerance = tolerance;
  Finding f = load_domain(domain, m.dim, d);
  // 2D: also the domain's contact check (load_domain leaves it to this sweep), before anything
  // that assumes a simple domain.
  if (f.defect == Defect::none && m.dim == 2) f = faces_and_isolated_vertices(m, lex_order, domain, d);
  if (f.defect != Defect::none) return f;
  const DomainVertexMatch match = domain_vertices_in_mesh(m, d);
  d.pinned.resize(m.vertex_count);
  d.mesh_vertex_at.assign(d.geo.vertex_count, -1);
  for (Index v = 0; v < m.vertex_count; ++v) {
    d.pinned[v] = match.range[v].first != match.range[v].second;
    for (std::uint32_t i = match.range[v].first; i < match.range[v].second; ++i) d.mesh_vertex_at[match.order[i]] = v;
  }
  const OnDomain on(incidences(m, d, match), m.vertex_count);
  f = boundary_on_domain(m, boundary, d, on, stats);
  std::vector<char> face_on_facet(m.dim == 3 ? 4 * m.element_count : 0, 0);
  if (f.defect == Defect::none) f = coverage(m, boundary, d, on, stats, face_on_facet);
  if (f.defect == Defect::none)
    f = m.dim == 2 ? holes_and_regions_2d(m, boundary, comps, lex_order, domain) : holes_and_regions_3d(m, boundary, comps, d, on, domain);
  if (f.defect == Defect::none && m.dim == 3) f = region_labels(m, domain, face_on_facet);
  return f;
}

}  // namespace certimesh::certificate::detail
