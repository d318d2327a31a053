// Algorithm 35 in 3D (quality_improvement_3.h).
#include "certimesh/generators/improvement/quality_improvement_3.h"

#include <algorithm>
#include <array>
#include <limits>

#include "certimesh/topology/local_modifications_3.h"
#include "quality_order.h"

namespace certimesh::generators {

namespace {

using topology::ElementId;
using topology::TetrahedralMesh3;
using topology::VertexId;

std::array<double, 3> at(const predicates::Point3& p) { return {p.x, p.y, p.z}; }

double quality_of(const Tetrahedralization3& t, std::size_t i) {
  const auto& c = t.tetrahedra[i];
  return topology::tetrahedron_quality(at(t.points[c[0]]), at(t.points[c[1]]), at(t.points[c[2]]), at(t.points[c[3]]));
}

// The part of the solid worth improving: every tetrahedron with a vertex of a tetrahedron below
// the target (so each such vertex has its whole star, each such edge its whole ring, each such
// facet both sides). Its other facets to the rest of the solid are open in the submesh, hence
// constrained: nothing there changes and their vertices stay, so the rest fits it unchanged.
// Building a facet table of the whole mesh would cost more than improving it.
struct Submesh {
  TetrahedralMesh3 mesh;
  std::vector<std::uint8_t> taken;  // per tetrahedron of the solid
};

Submesh submesh_of(const Tetrahedralization3& t, const std::vector<double>& quality, double target) {
  Submesh s;
  std::vector<std::uint8_t> marked(t.points.size(), 0);
  for (std::size_t i = 0; i < t.tetrahedra.size(); ++i)
    if (quality[i] < target)
      for (const std::uint32_t v : t.tetrahedra[i]) marked[v] = 1;
  s.taken.assign(t.tetrahedra.size(), 0);
  std::size_t count = 0;
  for (std::size_t i = 0; i < t.tetrahedra.size(); ++i) {
    const auto& c = t.tetrahedra[i];
    s.taken[i] = marked[c[0]] | marked[c[1]] | marked[c[2]] | marked[c[3]];
    count += s.taken[i];
  }
  s.mesh.reserve(t.points.size(), count);
  for (const auto& p : t.points) s.mesh.add_vertex(at(p));
  for (std::size_t i = 0; i < t.tetrahedra.size(); ++i) {
    if (!s.taken[i]) continue;
    const auto& c = t.tetrahedra[i];
    s.mesh.add_element({VertexId{c[0]}, VertexId{c[1]}, VertexId{c[2]}, VertexId{c[3]}},
                       i < t.labels.size() ? t.labels[i] : 0);
  }
  for (const auto& f : t.constrained_faces)
    s.mesh.set_facet_label({VertexId{f[0]}, VertexId{f[1]}, VertexId{f[2]}}, 1);
  return s;
}

// The solid's tetrahedra outside the submesh, in their order, then the submesh's in slot order.
void merge_back(const Submesh& s, Tetrahedralization3& t) {
  for (std::size_t v = 0; v < t.points.size(); ++v) {
    const auto p = s.mesh.point(VertexId{static_cast<std::uint32_t>(v)});
    t.points[v] = {p[0], p[1], p[2]};
  }
  const bool labelled = !t.labels.empty();
  std::size_t kept = 0;
  for (std::size_t i = 0; i < t.tetrahedra.size(); ++i) {
    if (s.taken[i]) continue;
    t.tetrahedra[kept] = t.tetrahedra[i];
    if (labelled) t.labels[kept] = t.labels[i];
    ++kept;
  }
  t.tetrahedra.resize(kept);
  if (labelled) t.labels.resize(kept);
  for (std::uint32_t e = 0; e < s.mesh.element_slot_count(); ++e) {
    if (!s.mesh.is_live(ElementId{e})) continue;
    const auto c = s.mesh.vertices(ElementId{e});
    t.tetrahedra.push_back({c[0].value, c[1].value, c[2].value, c[3].value});
    if (labelled) t.labels.push_back(s.mesh.label(ElementId{e}));
  }
}

// One attempt on element e: the first operation that improves, committed.
std::optional<topology::LocalChange3> improve_one(TetrahedralMesh3& mesh, ElementId e,
                                                  const topology::LocalModificationOptions3& o,
                                                  ImprovementStats3& stats) {
  static constexpr int edges[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  for (const auto& edge : edges)
    if (auto c = topology::try_edge_removal(mesh, e, edge[0], edge[1], o)) {
      ++stats.edge_removals;
      return c;
    }
  for (int i = 0; i < 4; ++i)
    if (auto c = topology::try_flip_2_3(mesh, e, i)) {
      ++stats.flips_2_3;
      return c;
    }
  const auto corners = mesh.vertices(e);
  for (const VertexId v : corners)
    if (auto c = topology::try_node_shift(mesh, v, o)) {
      ++stats.node_shifts;
      return c;
    }
  return std::nullopt;
}

}  // namespace

ImprovementStats3 improve_tetrahedra_3(Tetrahedralization3& solid, std::uint32_t first_movable_vertex,
                                       const ImprovementOptions3& options) {
  ImprovementStats3 stats;
  stats.ran = true;
  topology::LocalModificationOptions3 o;
  o.first_movable_vertex = first_movable_vertex;
  std::vector<double> quality;
  const auto measure = [&] {
    quality.resize(solid.tetrahedra.size());
    double worst = solid.tetrahedra.empty() ? 0.0 : 1.0;
    for (std::size_t i = 0; i < quality.size(); ++i) worst = std::min(worst, quality[i] = quality_of(solid, i));
    return worst;
  };
  stats.worst_before = measure();
  for (std::uint32_t pass = 0; pass < options.max_passes; ++pass) {
    if (!(stats.worst_before < options.target_quality) && pass == 0) break;
    Submesh part = submesh_of(solid, quality, options.target_quality);
    TetrahedralMesh3& mesh = part.mesh;
    improvement::QualityOrder queue;
    for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e) {
      const double q = topology::element_quality(mesh, ElementId{e});
      if (q < options.target_quality) queue.insert(ElementId{e}, q);
    }
    if (queue.size() == 0) break;
    ++stats.passes;
    // The fixed vertices of this submesh, once: those of its constrained facets (its open
    // facets among them) and the input's.
    std::vector<std::uint8_t> fixed(mesh.vertex_slot_count(), 0);
    for (std::uint32_t v = 0; v < std::min<std::size_t>(first_movable_vertex, fixed.size()); ++v) fixed[v] = 1;
    for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e)
      for (int i = 0; i < 4; ++i)
        if (topology::is_constrained_facet(mesh, ElementId{e}, i))
          for (const VertexId v : mesh.facet(ElementId{e}, i)) fixed[v.value] = 1;
    o.fixed_vertices = fixed;
    const std::uint64_t budget = options.max_operations ? options.max_operations : 3 * queue.size() + 16;
    std::uint64_t committed = 0;
    for (std::uint64_t attempt = 0; attempt < budget && queue.size() > 0; ++attempt) {
      const ElementId e = queue.kth_worst(1);
      queue.erase(e);
      ++stats.attempts;
      const auto change = improve_one(mesh, e, o, stats);
      if (!change) continue;
      ++committed;
      // Removed ids first: a slot may be reused by an added element (or, in a node shift,
      // the same ids come back with new qualities). Erasing an id no longer queued is a no-op.
      for (const ElementId r : change->removed) queue.erase(r);
      for (const ElementId a : change->added) {
        const double q = topology::element_quality(mesh, a);
        if (q < options.target_quality) queue.insert(a, q);
      }
    }
    o.fixed_vertices = {};
    merge_back(part, solid);
    stats.worst_after = measure();
    if (committed == 0) break;
  }
  if (stats.passes == 0) stats.worst_after = stats.worst_before;
  return stats;
}

}  // namespace certimesh::generators
