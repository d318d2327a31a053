// The certificate's driver: runs the stages in the order of defect.h and stops at the first
// defect, so a mesh broken in exactly one way is reported with exactly that reason.
#include "certimesh/certificate/check_mesh.h"

#include <cmath>

#include "certimesh/predicates/non_finite_input.h"
#include "stages.h"

namespace certimesh::certificate {

namespace {

detail::MeshView view_of(const io::MeshData& mesh) {
  const int dim = mesh.dimension == 3 ? 3 : 2;
  const auto& cells = dim == 2 ? mesh.triangles : mesh.tetrahedra;
  const auto& labels = dim == 2 ? mesh.triangle_labels : mesh.tetrahedron_labels;
  const std::size_t count = cells.size() / static_cast<std::size_t>(dim + 1);
  return {dim, mesh.coordinates.data(), mesh.coordinates.size() / static_cast<std::size_t>(dim), cells.data(), count,
          labels.size() == count ? labels.data() : nullptr};
}

// The domain's hole points for the 2D single-cover sweep to answer for at the same time; none
// when one is not finite (the domain check refuses that, by name).
std::vector<std::array<double, 2>> hole_points_2d(const detail::MeshView& m, const io::MeshData* domain) {
  std::vector<std::array<double, 2>> at;
  if (m.dim != 2 || domain == nullptr || domain->dimension != 2) return at;
  for (std::size_t h = 0; h < domain->hole_count(); ++h) {
    const double x = domain->holes[2 * h], y = domain->holes[2 * h + 1];
    if (!std::isfinite(x) || !std::isfinite(y)) return {};
    at.push_back({x, y});
  }
  return at;
}

Finding run_stages(const detail::MeshView& m, const io::MeshData* domain, const CheckOptions& options, Statistics& stats) {
  std::vector<io::Index> lex_order;
  Finding f = detail::check_input(m, lex_order);
  if (f.defect != Defect::none) return f;
  detail::FacetSet boundary;
  f = detail::pair_facets(m, boundary, stats.interior_facets);
  stats.boundary_facets = boundary.size();
  if (f.defect != Defect::none) return f;
  f = detail::check_orientation(m, stats);
  if (f.defect != Defect::none) return f;
  detail::Components comps;
  f = detail::check_boundary_manifold(m, boundary, comps);
  stats.boundary_components = comps.facets.size();
  if (f.defect != Defect::none) return f;
  f = detail::check_boundary_embedding(m, boundary);
  if (f.defect != Defect::none) return f;
  f = detail::check_single_cover(m, boundary, comps, hole_points_2d(m, domain), &lex_order);
  if (f.defect != Defect::none || domain == nullptr) return f;
  return detail::check_domain(m, boundary, comps, lex_order, *domain, options.boundary_tolerance, stats);
}

}  // namespace

Report check_mesh(const io::MeshData& mesh, const io::MeshData* domain, const CheckOptions& options) {
  Report report;
  const detail::MeshView m = view_of(mesh);
  report.statistics.dimension = m.dim;
  report.statistics.vertices = m.vertex_count;
  report.statistics.elements = m.element_count;
  report.mesh_sha256 = detail::mesh_sha256(mesh);
  try {
    report.finding = run_stages(m, domain, options, report.statistics);
  } catch (const predicates::NonFiniteInput& e) {  // only a domain coordinate can get there
    report.finding = detail::finding(Defect::invalid_domain, -1, -1, -1,
                                     std::string("a predicate refused the input: ") + e.what());
  }
  report.valid = report.finding.defect == Defect::none;
  return report;
}

}  // namespace certimesh::certificate
