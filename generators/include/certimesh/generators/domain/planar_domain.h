// A planar straight-line graph (PSLG) describing a 2D domain, as a Triangle `.poly` file
// holds it: points, segments with labels, hole points and region seeds.
//
// The domain is, following Triangle, the union of the bounded faces of the arrangement of
// the segments minus the faces that contain a hole point. A segment with the domain on both
// sides is an internal cut (a crack, or an interface between two regions); a segment with
// the domain on neither side is refused (an open loop). Region seeds label the faces they lie
// in. Several components, holes and cuts are allowed; isolated points are not (they belong
// to point-set triangulation, not to domain meshing).
#pragma once

#include <cstdint>
#include <vector>

#include "certimesh/io/mesh_data.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators {

using predicates::Point2;
using DomainVertex = std::uint32_t;

struct DomainSegment {
  DomainVertex a = 0;
  DomainVertex b = 0;
  io::Label label = 0;
  friend bool operator==(const DomainSegment&, const DomainSegment&) = default;
};

struct RegionSeed {
  Point2 point;
  io::Label label = 0;
  friend bool operator==(const RegionSeed&, const RegionSeed&) = default;
};

struct PlanarDomain {
  std::vector<Point2> points;
  std::vector<io::Label> point_labels;  // empty, or one per point
  std::vector<DomainSegment> segments;
  std::vector<Point2> holes;
  std::vector<RegionSeed> regions;
  friend bool operator==(const PlanarDomain&, const PlanarDomain&) = default;
};

}  // namespace certimesh::generators
