#include "refinement_stage.h"

namespace certimesh::generators::detail {

RefinedTriangulation refine_domain(DomainTriangulation& dt, const SizePolicy& /*size*/,
                                   const ProgressCallback& /*progress*/) {
  // TODO(issue 5): Delaunay refinement (delaunay_refinement_2.h) once it lands; until then the
  // domain triangulation itself, which is already a valid mesh of the domain.
  RefinedTriangulation out;
  for (std::uint32_t v = 0; v < dt.cdt.vertex_count(); ++v) out.points.push_back(dt.cdt.point(v));
  for (std::uint32_t t = 0; t < dt.cdt.triangle_slot_count(); ++t) {
    if (!dt.cdt.is_live(t) || dt.labels[t] < 0) continue;
    out.triangles.push_back(dt.cdt.vertices(t));
    out.labels.push_back(dt.labels[t]);
  }
  return out;
}

}  // namespace certimesh::generators::detail
