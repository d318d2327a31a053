// Stage 3 of boundary recovery: after stages 1-2 every surface triangle is a union of mesh
// faces, so every tetrahedron lies on one side of the surface and its winding number is one
// integer. Walking across faces from outside the hull (winding 0), the number changes by one
// across a face that lies in a surface triangle (up when entering against the triangle's
// outward normal) and stays across any other face; the tetrahedra with winding 0 are removed.
// Which triangle a face lies in is decided by its vertices' origins (surface_triangle_of),
// not by geometry: a face whose three vertices lie on one triangle lies in it (convexity),
// and a vertex lies on exactly the triangles its origin names (the surface is valid).
#include <algorithm>
#include <climits>
#include <deque>
#include <string>
#include <utility>

#include "recovery_mesh_3.h"

namespace certimesh::generators::detail {

namespace {

bool lies_on(const RecoveryMesh& m, const RecoverySurface3& s, VertexId v, std::uint32_t triangle) {
  const RecoveryVertex& r = m.vertices[v.value];
  const auto& t = s.triangles[triangle];
  auto corner = [&](std::uint32_t x) { return x == t[0] || x == t[1] || x == t[2]; };
  switch (r.origin) {
    case RecoveryVertex::Origin::input: return corner(v.value);
    case RecoveryVertex::Origin::on_edge: return corner(s.edges[r.on][0]) && corner(s.edges[r.on][1]);
    case RecoveryVertex::Origin::on_face: return r.on == triangle;
    case RecoveryVertex::Origin::interior: return false;
  }
  return false;
}

// The change of winding number from t to the tetrahedron across its local facet j.
int winding_step(const RecoveryMesh& m, const RecoverySurface3& s, ElementId t, int j) {
  const auto f = m.mesh.facet(t, j);
  const std::int64_t triangle = surface_triangle_of(m, s, f[0], f[1], f[2]);
  if (triangle < 0) return 0;
  const auto& c = s.triangles[static_cast<std::size_t>(triangle)];
  const VertexId opposite = m.mesh.vertices(t)[static_cast<std::size_t>(j)];
  const int facet_side = m.orient(f[0], f[1], f[2], opposite);
  const int triangle_side = m.orient(VertexId{c[0]}, VertexId{c[1]}, VertexId{c[2]}, opposite);
  if (facet_side == 0 || triangle_side == 0) recovery_invariant_broken("a flat tetrahedron at a surface face");
  // Same orientation: the triangle's outward normal points from t to its neighbour, so t is
  // on its inner side and the neighbour's winding is one less.
  return facet_side == triangle_side ? -1 : 1;
}

}  // namespace

std::int64_t surface_triangle_of(const RecoveryMesh& m, const RecoverySurface3& s, VertexId a, VertexId b, VertexId c) {
  const RecoveryVertex& r = m.vertices[a.value];
  auto check = [&](std::uint32_t t) { return lies_on(m, s, a, t) && lies_on(m, s, b, t) && lies_on(m, s, c, t); };
  switch (r.origin) {
    case RecoveryVertex::Origin::input:
      for (const std::uint32_t t : s.vertex_triangles[a.value])
        if (check(t)) return t;
      return -1;
    case RecoveryVertex::Origin::on_edge:
      for (const std::uint32_t t : s.edge_triangles[r.on])
        if (check(t)) return t;
      return -1;
    case RecoveryVertex::Origin::on_face: return check(r.on) ? static_cast<std::int64_t>(r.on) : -1;
    case RecoveryVertex::Origin::interior: return -1;
  }
  return -1;
}

void keep_solid(RecoveryMesh& m, const RecoverySurface3& s, BoundaryRecoveryCounts& counts) {
  const std::size_t slots = m.mesh.element_slot_count();
  std::vector<int> winding(slots, INT_MIN);
  std::deque<ElementId> queue;
  for (std::uint32_t t = 0; t < slots && queue.empty(); ++t) {
    const ElementId e{t};
    if (!m.mesh.is_live(e)) continue;
    for (int j = 0; j < 4; ++j)
      if (m.mesh.neighbour(e, j).is_none()) {
        winding[t] = -winding_step(m, s, e, j);  // from outside (winding 0) into t
        queue.push_back(e);
        break;
      }
  }
  while (!queue.empty()) {
    const ElementId t = queue.front();
    queue.pop_front();
    for (int j = 0; j < 4; ++j) {
      const ElementId n = m.mesh.neighbour(t, j);
      const int expected = n.is_none() ? 0 : winding[t.value] + winding_step(m, s, t, j);
      if (n.is_none()) {
        if (winding[t.value] + winding_step(m, s, t, j) != 0)
          recovery_invariant_broken("the winding number is not 0 outside the hull");
        continue;
      }
      if (winding[n.value] == INT_MIN) {
        winding[n.value] = expected;
        queue.push_back(n);
      } else if (winding[n.value] != expected) {
        recovery_invariant_broken("the winding number of tetrahedron " + std::to_string(n.value) +
                                  " is not well defined: the surface is not recovered");
      }
    }
  }
  // The solid's tetrahedra into a fresh mesh (same vertex ids): removing elements may leave a
  // vertex's incident-element hint empty, and the star walks of stage 4 start from it.
  topology::TetrahedralMesh3 solid;
  for (std::uint32_t v = 0; v < m.mesh.vertex_slot_count(); ++v) solid.add_vertex(m.mesh.point(VertexId{v}));
  for (std::uint32_t t = 0; t < slots; ++t) {
    const ElementId e{t};
    if (!m.mesh.is_live(e)) continue;
    if (winding[t] == INT_MIN) recovery_invariant_broken("a tetrahedron unreachable from the hull");
    if (winding[t] == 0)
      ++counts.outside_tetrahedra;
    else
      solid.add_element(m.mesh.vertices(e));
  }
  m.mesh = std::move(solid);
}

}  // namespace certimesh::generators::detail
