// The improvement stage of the pipeline works only where it is needed: the triangles below
// the target quality and two rings of their neighbours are copied into a mesh model of their
// own, improved there, and put back. The copy's boundary (open facets) is what the local
// modifications never change, so the triangles outside it stay as they are and still fit;
// boundary and cut edges inside it are labelled facets, which they never change either.
// Cost: proportional to the bad region, not to the mesh (building a facet-hashed mesh model
// of 10^6 triangles to fix a few hundred would dominate the run).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/generators/improvement/quality_improvement_2.h"
#include "certimesh/generators/progress.h"
#include "certimesh/io/mesh_data.h"

namespace certimesh::generators::detail {

struct TriangleSoup {
  std::vector<Point2> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<io::Label> labels;
};

struct RegionImprovementStats {
  std::uint64_t region_triangles = 0;  // triangles copied into the improved region
  ImprovementStats2 improvement;
};

/// Improves the triangles of `mesh` below `options.target_quality` (shape quality) and their
/// neighbourhood in place; `constrained` edges (boundary and cut subsegments) are kept.
RegionImprovementStats improve_bad_region(TriangleSoup& mesh, std::span<const DomainSegment> constrained,
                                          const ImprovementOptions2& options, const ProgressCallback& progress);

}  // namespace certimesh::generators::detail
