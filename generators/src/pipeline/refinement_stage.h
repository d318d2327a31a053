// The Delaunay path of the pipeline (--algorithm delaunay): the constrained Delaunay
// triangulation of the discretized boundary, classified, then refined with interior Steiner
// points until the size policy holds (delaunay_refinement_2.h); the boundary trace is kept.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "boundary_discretization.h"
#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/generators/progress.h"
#include "certimesh/generators/size_policy.h"

namespace certimesh::generators::detail {

struct RefinedTriangulation {
  std::vector<Point2> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // the inside ones, counterclockwise
  std::vector<io::Label> labels;
};

RefinedTriangulation refine_domain(const PlanarDomain& domain, const DiscretizedBoundary& boundary,
                                   const SizePolicy& size, const ProgressCallback& progress);

}  // namespace certimesh::generators::detail
