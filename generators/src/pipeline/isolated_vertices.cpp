#include "isolated_vertices.h"

#include <algorithm>
#include <cmath>
#include <span>

#include "certimesh/predicates/orient2d.h"
#include "delaunay_completion.h"
#include "region_labels.h"
#include "vertex_stars.h"

namespace certimesh::generators::detail {

namespace {

using predicates::Sign;
using Triangle = std::array<std::uint32_t, 3>;

std::uint64_t undirected_edge_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

// Triangles bucketed by bounding box on a uniform grid of about one cell per triangle.
class TriangleGrid {
 public:
  explicit TriangleGrid(const TriangleSoup& m) : m_(m) {
    for (const Point2& p : m.points) {
      lo_ = {std::min(lo_.x, p.x), std::min(lo_.y, p.y)};
      hi_ = {std::max(hi_.x, p.x), std::max(hi_.y, p.y)};
    }
    side_ = std::max<std::size_t>(1, static_cast<std::size_t>(std::sqrt(static_cast<double>(m.triangles.size()))));
    cells_.resize(side_ * side_);
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t) {
      Point2 a = m.points[m.triangles[t][0]], b = a;
      for (const std::uint32_t v : m.triangles[t]) {
        a = {std::min(a.x, m.points[v].x), std::min(a.y, m.points[v].y)};
        b = {std::max(b.x, m.points[v].x), std::max(b.y, m.points[v].y)};
      }
      for (std::size_t i = cell(a.x, lo_.x, hi_.x); i <= cell(b.x, lo_.x, hi_.x); ++i)
        for (std::size_t j = cell(a.y, lo_.y, hi_.y); j <= cell(b.y, lo_.y, hi_.y); ++j) cells_[i * side_ + j].push_back(t);
    }
  }
  // Every triangle whose closed area contains p (exact orient2d).
  std::vector<std::uint32_t> containing(const Point2& p) const {
    std::vector<std::uint32_t> out;
    if (p.x < lo_.x || p.x > hi_.x || p.y < lo_.y || p.y > hi_.y) return out;
    for (const std::uint32_t t : cells_[cell(p.x, lo_.x, hi_.x) * side_ + cell(p.y, lo_.y, hi_.y)]) {
      const Triangle& v = m_.triangles[t];
      bool inside = true;
      for (int i = 0; i < 3 && inside; ++i)
        inside = predicates::orient2d(m_.points[v[static_cast<std::size_t>(i)]], m_.points[v[static_cast<std::size_t>((i + 1) % 3)]], p) !=
                 Sign::negative;
      if (inside) out.push_back(t);
    }
    return out;
  }

 private:
  // Monotone in the coordinate, so a box's cells are the range of its corners' cells.
  std::size_t cell(double x, double lo, double hi) const {
    if (!(hi > lo)) return 0;
    const double f = (x - lo) / (hi - lo) * static_cast<double>(side_);
    return std::min(side_ - 1, static_cast<std::size_t>(std::max(0.0, f)));
  }
  const TriangleSoup& m_;
  Point2 lo_{INFINITY, INFINITY}, hi_{-INFINITY, -INFINITY};
  std::size_t side_ = 1;
  std::vector<std::vector<std::uint32_t>> cells_;
};

// Edge -> triangles, by sorting (deterministic).
struct EdgeTriangles {
  std::vector<std::pair<std::uint64_t, std::uint32_t>> half;
  explicit EdgeTriangles(const TriangleSoup& m) {
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t)
      for (int i = 0; i < 3; ++i) half.push_back({undirected_edge_key(m.triangles[t][static_cast<std::size_t>(i)], m.triangles[t][static_cast<std::size_t>((i + 1) % 3)]), t});
    std::sort(half.begin(), half.end());
  }
  template <class F>
  void for_each(std::uint64_t key, F f) const {
    for (auto it = std::lower_bound(half.begin(), half.end(), std::make_pair(key, 0u)); it != half.end() && it->first == key; ++it) f(it->second);
  }
};

// The unpinned corner of the host triangles nearest to p when it is within half their mean
// edge length, else UINT32_MAX. (Measured on Triangle's square_circle_hole.poly, 691 isolated
// vertices: worst quality 0.055 keeping every generated vertex, 0.67 removing those within a
// third, 0.83 within a half.)
std::uint32_t crowding_vertex(const TriangleSoup& m, std::span<const std::uint32_t> hosts, const Point2& p,
                              const std::vector<std::uint8_t>& pinned) {
  double length = 0;
  std::uint32_t nearest = UINT32_MAX;
  double best = INFINITY;
  for (const std::uint32_t t : hosts)
    for (int i = 0; i < 3; ++i) {
      const Point2 a = m.points[m.triangles[t][static_cast<std::size_t>(i)]], b = m.points[m.triangles[t][static_cast<std::size_t>((i + 1) % 3)]];
      length += std::hypot(b.x - a.x, b.y - a.y);
      const std::uint32_t w = m.triangles[t][static_cast<std::size_t>(i)];
      const double d = std::hypot(a.x - p.x, a.y - p.y);
      if (!pinned[w] && d < best) best = d, nearest = w;
    }
  if (hosts.empty() || !(best < length / static_cast<double>(3 * hosts.size()) / 2)) return UINT32_MAX;
  return nearest;
}

}  // namespace

void insert_isolated_vertices(TriangleSoup& mesh, std::span<const DomainSegment> constrained,
                              std::span<const std::uint32_t> isolated) {
  if (isolated.empty()) return;
  std::vector<std::uint64_t> fixed;
  for (const DomainSegment& s : constrained) fixed.push_back(undirected_edge_key(s.a, s.b));
  std::sort(fixed.begin(), fixed.end());
  const auto is_fixed = [&](std::uint64_t key) { return std::binary_search(fixed.begin(), fixed.end(), key); };
  const TriangleGrid grid(mesh);
  const EdgeTriangles edges(mesh);
  const VertexStars stars(mesh);
  std::vector<std::uint8_t> cavity(mesh.triangles.size(), 0);
  std::vector<std::uint8_t> pinned(mesh.points.size(), 0);  // boundary, isolated or given up
  for (const DomainSegment& s : constrained) pinned[s.a] = pinned[s.b] = 1;
  for (const std::uint32_t v : isolated) pinned[v] = 1;
  std::vector<std::uint32_t> interior;
  std::vector<std::uint32_t> replaced(mesh.points.size());
  for (std::uint32_t v = 0; v < replaced.size(); ++v) replaced[v] = v;
  for (const std::uint32_t v : isolated) {
    const Point2 p = mesh.points[v];
    std::vector<std::uint32_t> hosts = grid.containing(p);
    bool at_vertex = false;
    for (const std::uint32_t t : hosts)
      for (const std::uint32_t w : mesh.triangles[t])
        if (mesh.points[w] == p) replaced[w] = v, pinned[w] = 1, at_vertex = true;  // w is v now: never removed
    if (at_vertex) continue;  // the generated vertex there becomes the isolated one
    interior.push_back(v);
    // A generated vertex much closer to p than the triangles are long would leave a sliver
    // between them: it goes, and p takes its place (its star joins the cavity).
    if (const std::uint32_t w = crowding_vertex(mesh, hosts, p, pinned); w != UINT32_MAX) {
      pinned[w] = 1;
      for (const std::uint32_t t : stars.of(w))
        if (std::find(hosts.begin(), hosts.end(), t) == hosts.end()) hosts.push_back(t);
    }
    for (const std::uint32_t t : hosts) {
      cavity[t] = 1;
      for (int i = 0; i < 3; ++i) {
        const std::uint64_t key = undirected_edge_key(mesh.triangles[t][static_cast<std::size_t>(i)], mesh.triangles[t][static_cast<std::size_t>((i + 1) % 3)]);
        if (!is_fixed(key)) edges.for_each(key, [&](std::uint32_t n) { cavity[n] = 1; });
      }
    }
  }
  for (Triangle& t : mesh.triangles)
    for (std::uint32_t& w : t) w = replaced[w];
  if (interior.empty()) return;
  // The cavity's front: its triangles' edges whose other side is not in the cavity, and both
  // directions of constrained edges inside it; each with the label of its cavity triangle.
  std::vector<FrontEdge> front;
  std::vector<io::Label> front_region;
  TriangleSoup kept;
  for (std::uint32_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!cavity[t]) {
      kept.triangles.push_back(mesh.triangles[t]);
      kept.labels.push_back(mesh.labels[t]);
      continue;
    }
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = mesh.triangles[t][static_cast<std::size_t>(i)], b = mesh.triangles[t][static_cast<std::size_t>((i + 1) % 3)];
      bool inner = false;
      edges.for_each(undirected_edge_key(a, b), [&](std::uint32_t n) { inner = inner || (n != t && cavity[n]); });
      if (!inner || is_fixed(undirected_edge_key(a, b))) {
        front.push_back({a, b});
        front_region.push_back(mesh.labels[t]);
      }
    }
  }
  const std::vector<Triangle> filled = complete_by_delaunay(mesh.points, front, interior);
  const std::vector<io::Label> labels = region_labels(filled, front, front_region, front_region.front());
  kept.triangles.insert(kept.triangles.end(), filled.begin(), filled.end());
  kept.labels.insert(kept.labels.end(), labels.begin(), labels.end());
  mesh.triangles = std::move(kept.triangles);
  mesh.labels = std::move(kept.labels);
}

std::vector<DomainSegment> pin_edges(const TriangleSoup& mesh, std::span<const std::uint32_t> isolated) {
  std::vector<std::uint32_t> partner(mesh.points.size(), UINT32_MAX);
  for (const Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      if (partner[t[static_cast<std::size_t>(i)]] == UINT32_MAX) partner[t[static_cast<std::size_t>(i)]] = t[static_cast<std::size_t>((i + 1) % 3)];
  std::vector<DomainSegment> out;
  for (const std::uint32_t v : isolated)
    if (partner[v] != UINT32_MAX) out.push_back({v, partner[v], 0});
  return out;
}

}  // namespace certimesh::generators::detail
