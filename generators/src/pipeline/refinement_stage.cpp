#include "refinement_stage.h"

#include "certimesh/generators/delaunay/constrained_delaunay_2.h"
#include "certimesh/generators/delaunay/delaunay_refinement_2.h"

namespace certimesh::generators::detail {

namespace {

// The inside triangles and their labels; the points as they are.
void collect(const ConstrainedDelaunay2& cdt, const std::vector<int>& labels, RefinedTriangulation& out) {
  out.points.reserve(cdt.vertex_count());
  for (std::uint32_t v = 0; v < cdt.vertex_count(); ++v) out.points.push_back(cdt.point(v));
  for (std::uint32_t t = 0; t < cdt.triangle_slot_count(); ++t) {
    if (!cdt.is_live(t) || labels[t] < 0) continue;
    out.triangles.push_back(cdt.vertices(t));
    out.labels.push_back(labels[t]);
  }
}

}  // namespace

RefinedTriangulation refine_domain(const PlanarDomain& domain, const DiscretizedBoundary& boundary,
                                   const SizePolicy& size, const ProgressCallback& progress) {
  ConstrainedDelaunay2 cdt(boundary.points, progress);
  for (const DomainSegment& s : boundary.subsegments) cdt.insert_constraint(s.a, s.b);
  std::vector<int> labels = cdt.classify(domain.holes, domain.regions);
  DelaunayRefinementOptions options;
  options.size = size;
  refine_delaunay_2(cdt, labels, options, progress);
  RefinedTriangulation out;
  collect(cdt, labels, out);
  return out;
}

RefinedTriangulation refine_domain_quality(const PlanarDomain& domain, const DiscretizedBoundary& boundary,
                                           std::span<const Point2> interior, const SizePolicy& size,
                                           double min_angle_degrees, std::uint64_t max_steiner,
                                           const ProgressCallback& progress) {
  std::vector<Point2> points = boundary.points;
  points.insert(points.end(), interior.begin(), interior.end());
  ConstrainedDelaunay2 cdt(points, progress);
  std::vector<Subsegment2> subsegments;
  subsegments.reserve(boundary.subsegments.size());
  for (std::size_t i = 0; i < boundary.subsegments.size(); ++i) {
    const DomainSegment& s = boundary.subsegments[i];
    cdt.insert_constraint(s.a, s.b);
    subsegments.push_back({s.a, s.b, boundary.origin[i]});
  }
  std::vector<int> labels = cdt.classify(domain.holes, domain.regions);
  std::vector<InputSegment2> segments;
  segments.reserve(domain.segments.size());
  for (const DomainSegment& s : domain.segments) segments.push_back({s.a, s.b});
  QualityRefinementOptions options;
  options.min_angle_degrees = min_angle_degrees;
  options.size = size;
  options.max_steiner = max_steiner;
  options.input_vertices = static_cast<std::uint32_t>(domain.points.size());
  options.segments = segments;
  RefinedTriangulation out;
  out.quality = refine_quality_2(cdt, labels, subsegments, options, progress);
  collect(cdt, labels, out);
  out.subsegments.reserve(subsegments.size());
  for (const Subsegment2& s : subsegments) out.subsegments.push_back({s.a, s.b, domain.segments[s.segment].label});
  return out;
}

}  // namespace certimesh::generators::detail
