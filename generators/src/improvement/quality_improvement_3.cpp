// Algorithm 35 in 3D (quality_improvement_3.h).
#include "certimesh/generators/improvement/quality_improvement_3.h"

#include <algorithm>
#include <limits>

#include "certimesh/topology/local_modifications_3.h"
#include "quality_order.h"

namespace certimesh::generators {

namespace {

using topology::ElementId;
using topology::TetrahedralMesh3;
using topology::VertexId;

TetrahedralMesh3 to_topology(const Tetrahedralization3& t) {
  TetrahedralMesh3 mesh;
  mesh.reserve(t.points.size(), t.tetrahedra.size());
  for (const auto& p : t.points) mesh.add_vertex({p.x, p.y, p.z});
  for (std::size_t i = 0; i < t.tetrahedra.size(); ++i) {
    const auto& c = t.tetrahedra[i];
    mesh.add_element({VertexId{c[0]}, VertexId{c[1]}, VertexId{c[2]}, VertexId{c[3]}},
                     i < t.labels.size() ? t.labels[i] : 0);
  }
  for (const auto& f : t.constrained_faces) mesh.set_facet_label({VertexId{f[0]}, VertexId{f[1]}, VertexId{f[2]}}, 1);
  return mesh;
}

void export_to(const TetrahedralMesh3& mesh, Tetrahedralization3& t) {
  for (std::size_t v = 0; v < t.points.size(); ++v) {
    const auto p = mesh.point(VertexId{static_cast<std::uint32_t>(v)});
    t.points[v] = {p[0], p[1], p[2]};
  }
  const bool labelled = !t.labels.empty();
  t.tetrahedra.clear();
  t.labels.clear();
  for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e) {
    if (!mesh.is_live(ElementId{e})) continue;
    const auto c = mesh.vertices(ElementId{e});
    t.tetrahedra.push_back({c[0].value, c[1].value, c[2].value, c[3].value});
    if (labelled) t.labels.push_back(mesh.label(ElementId{e}));
  }
}

double mesh_worst(const TetrahedralMesh3& mesh) {
  double worst = std::numeric_limits<double>::infinity();
  for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e)
    if (mesh.is_live(ElementId{e})) worst = std::min(worst, topology::element_quality(mesh, ElementId{e}));
  return mesh.element_count() ? worst : 0.0;
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
  TetrahedralMesh3 mesh = to_topology(solid);
  stats.worst_before = mesh_worst(mesh);
  topology::LocalModificationOptions3 o;
  o.first_movable_vertex = first_movable_vertex;
  const std::uint64_t budget = options.max_operations ? options.max_operations : 4 * mesh.element_count() + 16;
  for (std::uint32_t pass = 0; pass < options.max_passes; ++pass) {
    improvement::QualityOrder queue;
    for (std::uint32_t e = 0; e < mesh.element_slot_count(); ++e) {
      if (!mesh.is_live(ElementId{e})) continue;
      const double q = topology::element_quality(mesh, ElementId{e});
      if (q < options.target_quality) queue.insert(ElementId{e}, q);
    }
    ++stats.passes;
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
    if (committed == 0) break;
  }
  stats.worst_after = mesh_worst(mesh);
  export_to(mesh, solid);
  return stats;
}

}  // namespace certimesh::generators
