// Stage 3 of the pipeline: the constrained Delaunay triangulation of the domain's own points
// and segments (not of the discretized boundary: a few hundred collinear Steiner points per
// side make incremental Delaunay slow, and the answer is the same), classified into outside
// (-1) and regions (Triangle's rule: faces reachable from
// the hull or from a hole point without crossing a segment are outside). It decides what the
// boundary alone cannot: a segment with the domain on neither side (an open loop), an empty
// domain; and it gives the closed front F(P) of the monograph (outer sides with the domain on
// their left, both directions of every cut) with the region label on the left of each edge.
#pragma once

#include <vector>

#include "boundary_discretization.h"
#include "certimesh/generators/advancing_front/advancing_front_2.h"
#include "certimesh/generators/delaunay/constrained_delaunay_2.h"
#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/generators/progress.h"

namespace certimesh::generators::detail {

struct DomainTriangulation {
  std::vector<FrontEdge> front;            // F(P) over the discretized boundary's points
  std::vector<io::Label> front_region;     // the region label left of each front edge
};

/// Throws InvalidDomain (open_boundary naming the original segments, or empty_domain).
DomainTriangulation triangulate_domain(const PlanarDomain& domain, const DiscretizedBoundary& boundary,
                                       const ProgressCallback& progress);

}  // namespace certimesh::generators::detail
