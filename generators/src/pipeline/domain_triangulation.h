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

// What the classification decides about the input, and the part of it that is meshed.
struct DomainClassification {
  // The meshed part, renumbered in input order: the segments with the domain on at least one
  // side, their vertices, and the isolated vertices inside the domain (holes and regions as
  // given). Segments with the domain on neither side (in a hole, outside) are eaten, as
  // Triangle's holes eat them; isolated vertices outside are dropped.
  PlanarDomain kept;
  std::vector<DomainVertex> vertex_origin;              // the input id of each kept vertex
  std::vector<std::uint8_t> inside_sides;               // per kept segment: bit 0 a->b side, bit 1 b->a
  std::vector<std::array<io::Label, 2>> region;         // per kept segment, the label on each side
  std::vector<DomainVertex> isolated;                   // kept ids of the isolated vertices
  std::uint64_t eaten_segments = 0;
  std::uint64_t dropped_vertices = 0;
};

/// Classifies `domain` (a valid PSLG). Throws InvalidDomain: hole_outside_domain naming the
/// hole, open_boundary when no segment bounds a face, empty_domain.
DomainClassification classify_domain(const PlanarDomain& domain, const ProgressCallback& progress);

struct DomainTriangulation {
  std::vector<FrontEdge> front;            // F(P) over the discretized boundary's points
  std::vector<io::Label> front_region;     // the region label left of each front edge
};

/// F(P) over `boundary`, the discretization of `c.kept`.
DomainTriangulation front_of(const DomainClassification& c, const DiscretizedBoundary& boundary);

}  // namespace certimesh::generators::detail
