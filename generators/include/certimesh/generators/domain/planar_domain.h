// A planar straight-line graph (PSLG) describing a 2D domain, as a Triangle `.poly` file
// holds it: points, segments with labels, hole points and region seeds.
//
// The domain is, following Triangle (design decision 8), the union of the bounded faces of
// the arrangement of the segments minus the faces that contain a hole point. A segment with
// the domain on both sides is an internal edge of the mesh (a crack or a dangling cut, a
// segment tree inside a face, an interface between two regions); a segment with the domain on
// neither side (inside a hole, outside everything) is eaten as Triangle's holes eat it: it is
// not in the mesh. An isolated point (on no segment) inside the domain is a mesh vertex; one
// outside it is dropped, as Triangle's -j drops it. Region seeds give the faces they lie in a
// real attribute and, optionally, a maximum triangle area. A hole point outside every bounded
// face is refused.
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
  io::Label label = 0;      // the triangles' label: the attribute when it is an integer
  double attribute = 0.0;   // Triangle's regional attribute (a real number)
  double max_area = -1.0;   // every triangle of the region has at most this area; <= 0: none
  friend bool operator==(const RegionSeed&, const RegionSeed&) = default;
};

/// The attribute a seed gives its region: a seed built in code with only a label has its
/// label as attribute.
inline double attribute_of(const RegionSeed& r) {
  return r.attribute == 0.0 && r.label != 0 ? static_cast<double>(r.label) : r.attribute;
}

struct PlanarDomain {
  std::vector<Point2> points;
  std::vector<io::Label> point_labels;  // empty, or one per point
  std::vector<DomainSegment> segments;
  std::vector<Point2> holes;
  std::vector<RegionSeed> regions;
  friend bool operator==(const PlanarDomain&, const PlanarDomain&) = default;
};

}  // namespace certimesh::generators
