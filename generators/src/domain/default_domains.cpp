#include "certimesh/generators/domain/default_domains.h"

#include <vector>

#include "certimesh/generators/domain/curves_2.h"

namespace certimesh::generators {

namespace {

void add_round_hole(PlanarDomain& domain, Point2 centre, double radius, std::size_t segments, io::Label label) {
  add_curve(domain, circle_points(centre, radius, segments), label);
  domain.holes.push_back(centre);
}

}  // namespace

PlanarDomain plate_with_holes_and_crack() {
  PlanarDomain d;
  // Outer boundary; the crack mouth (2,0) splits the bottom edge.
  d.points = {{0, 0}, {2, 0}, {4, 0}, {4, 2}, {0, 2}};
  for (DomainVertex i = 0; i < 5; ++i) d.segments.push_back({i, (i + 1) % 5, 1});
  // The crack: three segments from the mouth (vertex 1) to the tip.
  const std::vector<Point2> crack = {{2, 0.25}, {2.125, 0.5}, {2.125, 0.75}};
  DomainVertex previous = 1;
  for (const Point2& p : crack) {
    d.points.push_back(p);
    const auto current = static_cast<DomainVertex>(d.points.size() - 1);
    d.segments.push_back({previous, current, 4});
    previous = current;
  }
  add_round_hole(d, {1, 1}, 0.4, 32, 2);
  add_round_hole(d, {3, 1}, 0.4, 32, 3);
  return d;
}

PlanarDomain unit_square() {
  PlanarDomain d;
  d.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (DomainVertex i = 0; i < 4; ++i) d.segments.push_back({i, (i + 1) % 4, 1});
  return d;
}

PlanarDomain square_with_two_holes(std::size_t segments_per_hole) {
  PlanarDomain d = unit_square();
  add_round_hole(d, {0.3, 0.5}, 0.1, segments_per_hole, 2);
  add_round_hole(d, {0.7, 0.5}, 0.1, segments_per_hole, 3);
  return d;
}

}  // namespace certimesh::generators
