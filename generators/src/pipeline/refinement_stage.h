// The Delaunay paths of the pipeline: the constrained Delaunay triangulation of the
// discretized boundary (and, for the quality stage, of given interior points), classified,
// then refined: to the size policy only (delaunay_refinement_2.h, --algorithm delaunay), or
// to a smallest angle with segment splitting (quality_refinement_2.h, --min-angle).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "boundary_discretization.h"
#include "certimesh/generators/delaunay/quality_refinement_2.h"
#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/generators/progress.h"
#include "certimesh/generators/size_policy.h"

namespace certimesh::generators::detail {

struct RefinedTriangulation {
  std::vector<Point2> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // the inside ones, counterclockwise
  std::vector<io::Label> labels;
  std::vector<DomainSegment> subsegments;  // the boundary as refined (quality stage only)
  QualityRefinementStats quality;          // quality stage only
};

/// Size-only refinement; the boundary trace is kept.
RefinedTriangulation refine_domain(const PlanarDomain& domain, const DiscretizedBoundary& boundary,
                                   const SizePolicy& size, const ProgressCallback& progress);

/// The quality stage: the constrained Delaunay triangulation of the boundary points and
/// `interior` (points strictly inside the domain, e.g. the advancing front's), refined until
/// every inside triangle has the smallest angle asked or is exempt (quality_refinement_2.h);
/// subsegments are split there.
RefinedTriangulation refine_domain_quality(const PlanarDomain& domain, const DiscretizedBoundary& boundary,
                                           std::span<const Point2> interior, const SizePolicy& size,
                                           double min_angle_degrees, std::uint64_t max_steiner,
                                           const ProgressCallback& progress);

}  // namespace certimesh::generators::detail
