#include "refinement_stage.h"

#include "certimesh/generators/delaunay/constrained_delaunay_2.h"
#include "certimesh/generators/delaunay/delaunay_refinement_2.h"

namespace certimesh::generators::detail {

RefinedTriangulation refine_domain(const PlanarDomain& domain, const DiscretizedBoundary& boundary,
                                   const SizePolicy& size, const ProgressCallback& progress) {
  ConstrainedDelaunay2 cdt(boundary.points, progress);
  for (const DomainSegment& s : boundary.subsegments) cdt.insert_constraint(s.a, s.b);
  std::vector<int> labels = cdt.classify(domain.holes, domain.regions);
  DelaunayRefinementOptions options;
  options.size = size;
  refine_delaunay_2(cdt, labels, options, progress);
  RefinedTriangulation out;
  out.points.reserve(cdt.vertex_count());
  for (std::uint32_t v = 0; v < cdt.vertex_count(); ++v) out.points.push_back(cdt.point(v));
  for (std::uint32_t t = 0; t < cdt.triangle_slot_count(); ++t) {
    if (!cdt.is_live(t) || labels[t] < 0) continue;
    out.triangles.push_back(cdt.vertices(t));
    out.labels.push_back(labels[t]);
  }
  return out;
}

}  // namespace certimesh::generators::detail
