// Constructive geometry (constructive_geometry_2.h) on Boost.Geometry multi-polygons, and the
// conversion of a region to a validated PlanarDomain with exactly checked hole points.
#include "certimesh/generators/domain/constructive_geometry_2.h"

// Boost 1.74's overlay rescales doubles to an integer grid of ~10^7 cells per bounding box
// (robust topology, but every point it constructs is off by up to a cell). Compiled without
// the rescaling (BOOST_GEOMETRY_NO_ROBUSTNESS) its points were exact where representable but
// near-tangent discs came back with crossing rings. So the rescaling stays, and each output
// point is snapped back to what it stands for: an input vertex, or the exact intersection of
// two input edges rounded to nearest (design decision 2). The snap distance only chooses the
// construction; validity is decided afterwards, exactly, by validate_domain.
#include <boost/geometry.hpp>
#include <boost/geometry/geometries/multi_polygon.hpp>
#include <boost/geometry/geometries/point_xy.hpp>
#include <boost/geometry/geometries/polygon.hpp>
#include <boost/geometry/algorithms/point_on_surface.hpp>

#include <cmath>
#include <cstddef>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "certimesh/generators/domain/curves_2.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/predicates/orient2d.h"
#include "exact_snap.h"

namespace certimesh::generators {

namespace {

namespace bg = boost::geometry;
using BoostPoint = bg::model::d2::point_xy<double>;
using BoostPolygon = bg::model::polygon<BoostPoint, /*clockwise=*/false, /*closed=*/true>;
using BoostRegion = bg::model::multi_polygon<BoostPolygon>;
using Ring = std::vector<Point2>;

void append_ring(const Ring& ring, BoostPolygon::ring_type& out) {
  for (const Point2& p : ring) out.push_back(BoostPoint(p.x, p.y));
  if (!ring.empty()) out.push_back(BoostPoint(ring.front().x, ring.front().y));
}

BoostRegion to_boost(const Region2& region) {
  BoostRegion out;
  for (const PolygonWithHoles2& polygon : region.polygons) {
    BoostPolygon p;
    append_ring(polygon.outer, p.outer());
    for (const Ring& inner : polygon.inners) {
      p.inners().emplace_back();
      append_ring(inner, p.inners().back());
    }
    out.push_back(std::move(p));
  }
  bg::correct(out);  // orientation and closure as the type says
  return out;
}

Ring from_boost_ring(const BoostPolygon::ring_type& ring) {
  Ring out;
  for (const BoostPoint& p : ring) out.push_back({p.x(), p.y()});
  if (out.size() > 1 && out.front() == out.back()) out.pop_back();  // open form
  return out;
}

Region2 from_boost(const BoostRegion& region) {
  Region2 out;
  for (const BoostPolygon& p : region) {
    PolygonWithHoles2 polygon{from_boost_ring(p.outer()), {}};
    for (const auto& inner : p.inners()) polygon.inners.push_back(from_boost_ring(inner));
    out.polygons.push_back(std::move(polygon));
  }
  return out;
}

template <class Operation>
Region2 boolean_operation(const Region2& a, const Region2& b, Operation operation) {
  BoostRegion result;
  operation(to_boost(a), to_boost(b), result);
  Region2 region = from_boost(result);
  const detail::ExactSnap snap({&a, &b});
  Region2 snapped;
  for (PolygonWithHoles2& polygon : region.polygons) {
    snap.apply(polygon.outer);
    if (polygon.outer.empty()) continue;  // a sliver folded away
    std::vector<Ring> inners;
    for (Ring& inner : polygon.inners) {
      snap.apply(inner);
      if (!inner.empty()) inners.push_back(std::move(inner));
    }
    snapped.polygons.push_back({std::move(polygon.outer), std::move(inners)});
  }
  return snapped;
}

// ---- exact point location against rings ---------------------------------------------------

enum class Location { outside, on_boundary, inside };

bool on_segment(const Point2& p, const Point2& a, const Point2& b) {
  if (predicates::orient2d(a, b, p) != predicates::Sign::zero) return false;
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

// Crossings of the ray from p towards +x, each decided by comparisons and orient2d: exact.
Location locate(const Point2& p, const Ring& ring) {
  bool inside = false;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Point2& a = ring[i];
    const Point2& b = ring[(i + 1) % ring.size()];
    if (on_segment(p, a, b)) return Location::on_boundary;
    if ((a.y > p.y) == (b.y > p.y)) continue;
    const predicates::Sign side = predicates::orient2d(a, b, p);
    if ((b.y > a.y) ? side == predicates::Sign::positive : side == predicates::Sign::negative) inside = !inside;
  }
  return inside ? Location::inside : Location::outside;
}

// Is p in the face that inner ring `inner` of polygon `owner` bounds: strictly inside that
// ring, and neither inside nor on any other polygon (islands in the hole)?
bool is_hole_point(const Point2& p, const Region2& region, std::size_t owner, std::size_t inner) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  if (locate(p, region.polygons[owner].inners[inner]) != Location::inside) return false;
  for (std::size_t q = 0; q < region.polygons.size(); ++q) {
    if (q != owner && locate(p, region.polygons[q].outer) != Location::outside) return false;
  }
  return true;
}

// Candidates: Boost's point on the surface of (hole minus region), then the centroids of the
// corners of the ring; the first that passes the exact test wins.
std::vector<Point2> hole_point_candidates(const BoostRegion& boost_region, const Ring& ring) {
  std::vector<Point2> candidates;
  BoostPolygon hole;
  Ring reversed(ring.rbegin(), ring.rend());
  append_ring(reversed, hole.outer());
  bg::correct(hole);
  BoostRegion face;
  bg::difference(hole, boost_region, face);
  for (const BoostPolygon& piece : face) {
    BoostPoint p(0.0, 0.0);
    bg::point_on_surface(piece, p);
    candidates.push_back({p.x(), p.y()});
  }
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n && candidates.size() < 256; ++i) {
    const Point2& a = ring[(i + n - 1) % n];
    const Point2& b = ring[i];
    const Point2& c = ring[(i + 1) % n];
    candidates.push_back({(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3});
  }
  return candidates;
}

Point2 hole_point(const Region2& region, const BoostRegion& boost_region, std::size_t owner, std::size_t inner) {
  const Ring& ring = region.polygons[owner].inners[inner];
  for (const Point2& p : hole_point_candidates(boost_region, ring)) {
    if (is_hole_point(p, region, owner, inner)) return p;
  }
  throw InvalidDomain({DomainProblem{DomainProblemKind::empty_domain, {}, {},
                                     "no point found strictly inside inner ring " + std::to_string(inner) +
                                         " of polygon " + std::to_string(owner) + " for its hole point"}});
}

// Vertex ids by coordinates: bit-identical points (0 and -0 alike) become one vertex.
class VertexMerger {
 public:
  explicit VertexMerger(PlanarDomain& d) : domain_(d) {}
  DomainVertex id(const Point2& p) {
    const auto [it, inserted] = ids_.try_emplace({p.x, p.y}, static_cast<DomainVertex>(domain_.points.size()));
    if (inserted) domain_.points.push_back(p);
    return it->second;
  }

 private:
  PlanarDomain& domain_;
  std::map<std::pair<double, double>, DomainVertex> ids_;
};

void add_ring(const Ring& ring, io::Label label, VertexMerger& merger, PlanarDomain& domain) {
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const DomainVertex a = merger.id(ring[i]);
    const DomainVertex b = merger.id(ring[(i + 1) % ring.size()]);
    if (a != b) domain.segments.push_back({a, b, label});
  }
}

}  // namespace

Region2 rectangle_region(double x0, double y0, double x1, double y1) {
  if (!(std::isfinite(x0) && std::isfinite(y0) && std::isfinite(x1) && std::isfinite(y1) && x0 < x1 && y0 < y1)) {
    throw std::invalid_argument("a rectangle needs finite x0 < x1 and y0 < y1");
  }
  return Region2{{PolygonWithHoles2{{{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}}, {}}}};
}

Region2 disc_region(Point2 centre, double radius, double step) {
  return Region2{{PolygonWithHoles2{discretize_circle(centre, radius, CurveSpacing::with_step(step)).points, {}}}};
}

Region2 polygon_region(const std::vector<Point2>& vertices) {
  if (vertices.size() < 3) throw std::invalid_argument("a polygon needs 3 vertices or more");
  for (const Point2& p : vertices) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) throw std::invalid_argument("a polygon vertex is not finite");
  }
  BoostPolygon polygon;
  append_ring(vertices, polygon.outer());
  bg::correct(polygon);
  std::string reason;
  if (!bg::is_valid(polygon, reason)) throw std::invalid_argument("the polygon is not simple: " + reason);
  return from_boost(BoostRegion{polygon});
}

Region2 region_union(const Region2& a, const Region2& b) {
  return boolean_operation(a, b, [](const auto& x, const auto& y, auto& out) { bg::union_(x, y, out); });
}

Region2 region_difference(const Region2& a, const Region2& b) {
  return boolean_operation(a, b, [](const auto& x, const auto& y, auto& out) { bg::difference(x, y, out); });
}

Region2 region_intersection(const Region2& a, const Region2& b) {
  return boolean_operation(a, b, [](const auto& x, const auto& y, auto& out) { bg::intersection(x, y, out); });
}

double region_area(const Region2& region) { return bg::area(to_boost(region)); }

PlanarDomain to_planar_domain(const Region2& region, io::Label label) {
  PlanarDomain domain;
  if (region.polygons.empty()) {
    throw InvalidDomain({DomainProblem{DomainProblemKind::empty_domain, {}, {}, "the region is empty"}});
  }
  VertexMerger merger(domain);
  const BoostRegion boost_region = to_boost(region);
  for (std::size_t p = 0; p < region.polygons.size(); ++p) {
    add_ring(region.polygons[p].outer, label, merger, domain);
    for (std::size_t i = 0; i < region.polygons[p].inners.size(); ++i) {
      add_ring(region.polygons[p].inners[i], label, merger, domain);
      domain.holes.push_back(hole_point(region, boost_region, p, i));
    }
  }
  std::vector<DomainProblem> problems = validate_domain(domain);
  if (!problems.empty()) throw InvalidDomain(std::move(problems));
  return domain;
}

}  // namespace certimesh::generators
