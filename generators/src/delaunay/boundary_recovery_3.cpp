// tetrahedralize_solid_3 (boundary_recovery_3.h): the driver of the four stages.
#include "certimesh/generators/delaunay/boundary_recovery_3.h"

#include <gmp.h>
#include <mpfr.h>

#include <algorithm>
#include <map>
#include <string>

#include "certimesh/generators/delaunay/delaunay_3.h"
#include "certimesh/predicates/volume_sign.h"
#include "certimesh/topology/topology_error.h"
#include "recovery_mesh_3.h"

namespace certimesh::generators {

namespace {

using detail::RecoveryMesh;
using detail::RecoveryVertex;
using detail::RecoverySurface3;
using topology::ElementId;
using topology::VertexId;

RecoverySurface3 surface_of(std::span<const Point3> points, std::span<const std::array<std::uint32_t, 3>> triangles) {
  RecoverySurface3 s{points, triangles, {}, {}, std::vector<std::vector<std::uint32_t>>(points.size())};
  std::map<std::array<std::uint32_t, 2>, std::vector<std::uint32_t>> edges;
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = triangles[t][static_cast<std::size_t>(i)], b = triangles[t][static_cast<std::size_t>((i + 1) % 3)];
      if (a >= points.size() || b >= points.size())
        throw BoundaryRecoveryError("error: triangle " + std::to_string(t) + " names vertex " +
                                    std::to_string(std::max(a, b)) + ", but there are " +
                                    std::to_string(points.size()) + " points");
      if (a == b) throw BoundaryRecoveryError("error: triangle " + std::to_string(t) + " repeats vertex " + std::to_string(a));
      edges[{std::min(a, b), std::max(a, b)}].push_back(t);
      if (i == 0 || s.vertex_triangles[a].empty() || s.vertex_triangles[a].back() != t) s.vertex_triangles[a].push_back(t);
    }
  for (const auto& [e, holders] : edges) {
    if (holders.size() != 2)
      throw BoundaryRecoveryError("error: surface edge (" + std::to_string(e[0]) + ", " + std::to_string(e[1]) +
                                  ") is in " + std::to_string(holders.size()) +
                                  " triangles (first " + std::to_string(holders[0]) +
                                  "): the surface is not closed and manifold");
    s.edges.push_back(e);
    s.edge_triangles.push_back({holders[0], holders[1]});
  }
  return s;
}

// The Delaunay tetrahedralization of the points the triangles use, into m (vertex ids =
// input indices).
void start_with_delaunay(RecoveryMesh& m, const RecoverySurface3& s, BoundaryRecoveryCounts& counts) {
  for (const Point3& p : s.points) m.add_vertex(detail::make_input_vertex(p));
  std::vector<std::uint32_t> used;
  for (std::uint32_t v = 0; v < s.points.size(); ++v)
    if (!s.vertex_triangles[v].empty()) used.push_back(v);
  std::vector<Point3> points;
  for (const std::uint32_t v : used) points.push_back(s.points[v]);
  try {
    const Delaunay3 dt(points);
    for (const auto& t : dt.tetrahedra()) {
      m.mesh.add_element({VertexId{used[t[0]]}, VertexId{used[t[1]]}, VertexId{used[t[2]]}, VertexId{used[t[3]]}});
      ++counts.delaunay_tetrahedra;
    }
  } catch (const DelaunayError& e) {
    throw BoundaryRecoveryError(e.what());
  }
}

// Design decision 2 for --refine-surface: each surface Steiner point rounded to nearest once.
double round_rational_to_nearest(const mpq_class& q) {
  const mpfr_exp_t saved_emin = mpfr_get_emin(), saved_emax = mpfr_get_emax();
  mpfr_set_emin(-1073);
  mpfr_set_emax(1024);
  mpfr_t r;
  mpfr_init2(r, 53);
  mpfr_subnormalize(r, mpfr_set_q(r, q.get_mpq_t(), MPFR_RNDN), MPFR_RNDN);
  const double d = mpfr_get_d(r, MPFR_RNDN);
  mpfr_clear(r);
  mpfr_set_emin(saved_emin);
  mpfr_set_emax(saved_emax);
  return d;
}

void round_surface_steiner_points(RecoveryMesh& m) {
  for (std::uint32_t v = 0; v < m.vertices.size(); ++v) {
    RecoveryVertex& r = m.vertices[v];
    if (r.origin != RecoveryVertex::Origin::on_edge && r.origin != RecoveryVertex::Origin::on_face) continue;
    const Point3 p{round_rational_to_nearest(r.exact[0]), round_rational_to_nearest(r.exact[1]), round_rational_to_nearest(r.exact[2])};
    m.set_double_point(VertexId{v}, p, r.origin);
  }
}

SolidMesh3 output_of(const RecoveryMesh& m, BoundaryRecoveryCounts counts) {
  SolidMesh3 out;
  out.counts = counts;
  for (const RecoveryVertex& v : m.vertices) {
    if (!v.is_double) detail::recovery_invariant_broken("a vertex without double coordinates at the end");
    out.points.push_back(v.approx);
  }
  for (std::uint32_t t = 0; t < m.mesh.element_slot_count(); ++t) {
    const ElementId e{t};
    if (!m.mesh.is_live(e)) continue;
    const auto c = m.mesh.vertices(e);
    const std::array<std::uint32_t, 4> tet{c[0].value, c[1].value, c[2].value, c[3].value};
    if (predicates::volume_sign(out.points[tet[0]], out.points[tet[1]], out.points[tet[2]], out.points[tet[3]]) !=
        predicates::Sign::positive) {
      if (counts.moved_inside == 0 && counts.edge_steiner_points + counts.face_steiner_points > 0)
        throw BoundaryRecoveryError(
            "error: rounding the surface Steiner points to doubles makes tetrahedron " + std::to_string(t) +
            " non-positive; without --refine-surface the points are moved inside instead");
      detail::recovery_invariant_broken("a non-positive tetrahedron in the result");
    }
    out.tetrahedra.push_back(tet);
  }
  return out;
}

}  // namespace

SolidMesh3 tetrahedralize_solid_3(std::span<const Point3> points, std::span<const std::array<std::uint32_t, 3>> triangles,
                                  const BoundaryRecoveryOptions& options, const ProgressCallback& progress) {
  const RecoverySurface3 s = surface_of(points, triangles);
  RecoveryMesh m;
  BoundaryRecoveryCounts counts;
  try {
    start_with_delaunay(m, s, counts);
    detail::recover_edges(m, s, counts, progress);
    detail::recover_faces(m, s, counts, progress);
    detail::keep_solid(m, s, counts);
    if (options.keep_surface_steiner_points)
      round_surface_steiner_points(m);
    else
      detail::remove_surface_steiner_points(m, s, counts);
  } catch (const topology::TopologyError& e) {
    detail::recovery_invariant_broken(std::string("the mesh refused a change: ") + e.what());
  }
  report(progress, "recovery", s.edges.size() + s.triangles.size(), s.edges.size() + s.triangles.size());
  return output_of(m, counts);
}

}  // namespace certimesh::generators
