// The Delaunay path of the pipeline (--algorithm delaunay): interior Steiner points inserted
// into the classified domain triangulation until the size policy holds; the boundary trace is
// kept (no point on a segment).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "certimesh/generators/progress.h"
#include "certimesh/generators/size_policy.h"
#include "domain_triangulation.h"

namespace certimesh::generators::detail {

struct RefinedTriangulation {
  std::vector<Point2> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;  // the inside ones, counterclockwise
  std::vector<io::Label> labels;
};

RefinedTriangulation refine_domain(DomainTriangulation& dt, const SizePolicy& size, const ProgressCallback& progress);

}  // namespace certimesh::generators::detail
