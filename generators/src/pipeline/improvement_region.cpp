#include "improvement_region.h"

#include <algorithm>

#include "certimesh/topology/quality.h"
#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::generators::detail {

namespace {

constexpr int kRings = 2;              // neighbours of bad triangles the improvement may change
constexpr std::uint32_t kNoLocalVertex = UINT32_MAX;
// Algorithm 35's budget N1 per region triangle. Ideal-point smoothing has already done the
// easy work; what is left stagnates quickly, and the default (5 per element) only spends
// time on graded meshes whose triangles cannot all reach the target.
constexpr std::uint64_t kOperationsPerTriangle = 2;
constexpr std::uint32_t kBasketSize = 256;  // Algorithm 35's N2
// The work queue stops after region / kStallFraction + kStallFloor iterations in a row that
// did not raise the worst quality. Gmsh's needs_rand_1e-9 (62k triangles): the whole budget
// took 5.7 s for a worst of 0.717; stopping at the stall, 0.4 s for 0.645 (Gmsh: 0.286).
constexpr std::uint64_t kStallFraction = 10;
constexpr std::uint64_t kStallFloor = 1000;

double soup_shape_quality(const TriangleSoup& m, const std::array<std::uint32_t, 3>& t) {
  const auto p = [&](int i) {
    const Point2& q = m.points[t[static_cast<std::size_t>(i)]];
    return topology::Point2d{q.x, q.y};
  };
  return topology::triangle_quality(p(0), p(1), p(2));
}

// Triangles below the target, grown by `kRings` rings of vertex neighbours.
std::vector<std::uint8_t> select_region(const TriangleSoup& m, double target) {
  std::vector<std::uint8_t> in_region(m.triangles.size(), 0);
  for (std::size_t t = 0; t < m.triangles.size(); ++t) in_region[t] = soup_shape_quality(m, m.triangles[t]) < target;
  std::vector<std::uint8_t> marked_vertex(m.points.size(), 0);
  for (int ring = 0; ring < kRings; ++ring) {
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      if (in_region[t]) {
        for (const std::uint32_t v : m.triangles[t]) marked_vertex[v] = 1;
      }
    }
    for (std::size_t t = 0; t < m.triangles.size(); ++t) {
      const auto& v = m.triangles[t];
      if (marked_vertex[v[0]] || marked_vertex[v[1]] || marked_vertex[v[2]]) in_region[t] = 1;
    }
  }
  return in_region;
}

}  // namespace

RegionImprovementStats improve_bad_region(TriangleSoup& m, std::span<const DomainSegment> constrained,
                                          const ImprovementOptions2& options, const ProgressCallback& progress) {
  RegionImprovementStats stats;
  const std::vector<std::uint8_t> in_region = select_region(m, options.target_quality);
  // Copy the region into a mesh model; local vertex ids are assigned in first-use order.
  std::vector<std::uint32_t> local_of(m.points.size(), kNoLocalVertex);
  std::vector<std::uint32_t> global_of;
  topology::TriangleMesh2 region;
  TriangleSoup kept;  // the triangles outside the region, unchanged
  for (std::size_t t = 0; t < m.triangles.size(); ++t) {
    if (!in_region[t]) {
      kept.triangles.push_back(m.triangles[t]);
      kept.labels.push_back(m.labels[t]);
      continue;
    }
    topology::TriangleMesh2::Element e;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t g = m.triangles[t][static_cast<std::size_t>(i)];
      if (local_of[g] == kNoLocalVertex) {
        local_of[g] = static_cast<std::uint32_t>(global_of.size());
        global_of.push_back(g);
        region.add_vertex({m.points[g].x, m.points[g].y});
      }
      e[static_cast<std::size_t>(i)] = topology::VertexId{local_of[g]};
    }
    region.add_element(e, m.labels[t]);
    ++stats.region_triangles;
  }
  if (stats.region_triangles == 0) return stats;
  for (const DomainSegment& s : constrained) {
    if (local_of[s.a] != kNoLocalVertex && local_of[s.b] != kNoLocalVertex) {
      region.set_facet_label({topology::VertexId{local_of[s.a]}, topology::VertexId{local_of[s.b]}}, 1);
    }
  }
  ImprovementOptions2 bounded = options;
  if (bounded.max_operations == 0) bounded.max_operations = kOperationsPerTriangle * stats.region_triangles;
  // The k-th worst element costs O(k) to reach (quality_order.h): a basket of 7 % of a large
  // region would make every iteration O(N). A fixed basket keeps iterations O(log N + 256).
  if (bounded.basket_size == 0) bounded.basket_size = kBasketSize;
  if (bounded.stall_iterations == 0) bounded.stall_iterations = stats.region_triangles / kStallFraction + kStallFloor;
  if (bounded.max_baskets == 0) {
    bounded.max_baskets = static_cast<std::uint32_t>(std::min<std::uint64_t>(stats.region_triangles / kBasketSize + 2, 1u << 20));
  }
  stats.improvement = improve_quality_2(region, bounded, progress);
  // Put it back: moved vertices get their new place, new vertices new global ids.
  global_of.resize(region.vertex_slot_count(), kNoLocalVertex);
  for (std::uint32_t v = 0; v < region.vertex_slot_count(); ++v) {
    const topology::VertexId id{v};
    if (!region.is_live(id)) continue;
    const auto p = region.point(id);
    if (global_of[v] == kNoLocalVertex) {
      global_of[v] = static_cast<std::uint32_t>(m.points.size());
      m.points.push_back({p[0], p[1]});
    } else {
      m.points[global_of[v]] = {p[0], p[1]};
    }
  }
  for (std::uint32_t e = 0; e < region.element_slot_count(); ++e) {
    const topology::ElementId id{e};
    if (!region.is_live(id)) continue;
    const auto v = region.vertices(id);
    kept.triangles.push_back({global_of[v[0].value], global_of[v[1].value], global_of[v[2].value]});
    kept.labels.push_back(region.label(id));
  }
  m.triangles = std::move(kept.triangles);
  m.labels = std::move(kept.labels);
  return stats;
}

}  // namespace certimesh::generators::detail
