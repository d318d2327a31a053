// Stage 1 of boundary recovery: every surface edge becomes a chain of mesh edges
// (Algorithm 18's PROCESS_EDGE, digest C section 2.2). From the current vertex u on the edge
// (a, b), the tetrahedron of u's star whose closed cone at u holds the direction to b says,
// by the exact signs of b against its three faces through u, what the edge meets next:
//   all three positive  -> the interior of the face opposite u: split that face there;
//   one zero            -> the interior of an edge of that face: split that edge there;
//   two zeros           -> a vertex w along a mesh edge (u, w): go on from w.
// The crossing point is exact (rational), so it lies on (a, b) and the split is a stellar
// subdivision. Termination (proofs/boundary_recovery_3.md section 2): a split removes the
// crossed face or edge and creates only cells through the new point, which (a, b) does not
// cross, so the steps for one edge are at most the cells of the mesh when its walk starts.
#include <algorithm>
#include <string>
#include <utility>

#include "recovery_mesh_3.h"

namespace certimesh::generators::detail {

namespace {

std::string point3_text(const Point3& p) {
  return "(" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " + std::to_string(p.z) + ")";
}

int local_of(const topology::TetrahedralMesh3::Element& t, VertexId v) {
  return static_cast<int>(std::find(t.begin(), t.end(), v) - t.begin());
}

// The face f of t opposite u, crossed by (u, b), removed by a flip that makes only cells
// through u: the 2-3 flip with the tetrahedron beyond, else the removal of one of f's edges
// by the fan from u (a 3-2 flip when the edge has three tetrahedra), or by any valid
// triangulation of its ring that makes the edge (u, b) when b is in that ring.
// An edge of f may be on a surface edge already recovered: that one is never removed.
bool remove_face(RecoveryMesh& m, const RecoverySurface3& s, ElementId t, int i, VertexId u, VertexId b,
                 const topology::TetrahedralMesh3::Facet& f) {
  if (try_flip_2_3(m, t, i)) return true;
  for (int k = 0; k < 3; ++k) {
    const VertexId x = f[static_cast<std::size_t>(k)], y = f[static_cast<std::size_t>((k + 1) % 3)];
    if (!on_one_surface_edge(m, s, x, y) && try_remove_edge(m, x, y, u, b)) return true;
  }
  return false;
}

// One step of the walk from u towards b along the surface edge e = (a, b); returns the next
// vertex on (a, b), after splitting what the edge crosses.
// With `flips` false no flip is tried: the walk then ends within the split bound.
VertexId step(RecoveryMesh& m, const RecoverySurface3& s, std::uint32_t e, VertexId u, bool flips,
              BoundaryRecoveryCounts& counts) {
  const VertexId a{s.edges[e][0]}, b{s.edges[e][1]};
  const QPoint& qa = m.vertices[a.value].exact;
  const QPoint& qb = m.vertices[b.value].exact;
  for (const ElementId t : m.star(u)) {
    const auto corners = m.mesh.vertices(t);
    const int i = local_of(corners, u);
    int zero[2] = {-1, -1}, zeros = 0;
    bool outside = false;
    for (int j = 0; j < 4 && !outside; ++j) {
      if (j == i) continue;
      const auto f = m.mesh.facet(t, j);  // outward: orient > 0 on the inner side
      const int side = m.orient(f[0], f[1], f[2], b);
      if (side < 0) outside = true;
      if (side == 0 && zeros < 2) zero[zeros++] = j;
    }
    if (outside) continue;
    if (zeros == 0) {  // through the interior of the face opposite u
      const auto f = m.mesh.facet(t, i);
      if (flips && remove_face(m, s, t, i, u, b, f)) {
        ++counts.flips;
        return u;
      }
      const QPoint &x = m.vertices[f[0].value].exact, &y = m.vertices[f[1].value].exact,
                   &z = m.vertices[f[2].value].exact;
      const mpq_class da = orient_q(x, y, z, qa), db = orient_q(x, y, z, qb);
      ++counts.edge_steiner_points;
      const VertexId face[3] = {f[0], f[1], f[2]};
      return m.split(face, make_vertex(along(qa, qb, da / (da - db)), RecoveryVertex::Origin::on_edge, e));
    }
    if (zeros == 1) {  // in face zero[0] (through u), through the interior of its edge opposite u
      VertexId edge[2];
      int k = 0;
      for (int j = 0; j < 4; ++j)
        if (j != i && j != zero[0]) edge[k++] = corners[static_cast<std::size_t>(j)];
      if (flips && try_remove_edge(m, edge[0], edge[1], u, b, &s)) {
        ++counts.flips;
        return u;
      }
      const QPoint& off = m.vertices[corners[static_cast<std::size_t>(zero[0])].value].exact;  // not in the plane
      const QPoint &x = m.vertices[edge[0].value].exact, &y = m.vertices[edge[1].value].exact;
      const mpq_class ex = orient_q(qa, qb, off, x), ey = orient_q(qa, qb, off, y);
      ++counts.edge_steiner_points;
      return m.split(edge, make_vertex(along(x, y, ex / (ex - ey)), RecoveryVertex::Origin::on_edge, e));
    }
    // Two zeros: along the mesh edge (u, w), w the corner on neither zero face nor u.
    for (int j = 0; j < 4; ++j) {
      if (j == i || j == zero[0] || j == zero[1]) continue;
      const VertexId w = corners[static_cast<std::size_t>(j)];
      if (w != b && m.vertices[w.value].origin == RecoveryVertex::Origin::input)
        throw BoundaryRecoveryError("error: surface vertex " + std::to_string(w.value) + " " +
                                    point3_text(m.vertices[w.value].approx) + " lies on surface edge (" +
                                    std::to_string(a.value) + ", " + std::to_string(b.value) +
                                    "): the surface intersects itself");
      if (w != b) recovery_invariant_broken("a Steiner point lies on another surface edge");
      return w;
    }
  }
  recovery_invariant_broken("no tetrahedron of the star of vertex " + std::to_string(u.value) +
                            " holds the direction of surface edge (" + std::to_string(a.value) + ", " +
                            std::to_string(b.value) + ")");
}

}  // namespace

void recover_edges(RecoveryMesh& m, const RecoverySurface3& s, BoundaryRecoveryCounts& counts, const ProgressCallback& progress) {
  for (std::uint32_t e = 0; e < s.edges.size(); ++e) {
    const VertexId a{s.edges[e][0]}, b{s.edges[e][1]};
    // Flips first, within a budget (proofs/boundary_recovery_3.md section 2: a flip that
    // removes the crossed cell keeps u and moves the exit of (a, b) from u's star strictly
    // towards b; the flips that only shrink a ring need not). A flip can change the
    // number of cells (a, b) crosses, so the split bound restarts after each; with the
    // budget spent the walk goes on by splits and advances alone, within that bound.
    std::size_t flip_budget = 1024;
    std::size_t bound = m.cell_bound(), steps = 0;
    VertexId u = a;
    while (u != b) {
      const std::size_t flips_before = counts.flips;
      const VertexId next = step(m, s, e, u, flip_budget > 0, counts);
      if (counts.flips != flips_before) {
        --flip_budget;
        bound = m.cell_bound();
        steps = 0;
        continue;
      }
      if (++steps > bound) recovery_invariant_broken("edge recovery exceeded its step bound");
      u = next;
    }
    if ((e & 1023) == 0) report(progress, "recovery", e, s.edges.size() + s.triangles.size());
  }
}

}  // namespace certimesh::generators::detail
