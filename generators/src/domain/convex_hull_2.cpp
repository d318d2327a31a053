#include "certimesh/generators/domain/convex_hull_2.h"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <utility>
#include <vector>

#include "certimesh/predicates/orient2d.h"

namespace certimesh::generators {

namespace {

constexpr io::Label kHullMarker = 1;

// Counterclockwise hull, collinear points on it kept: a point is popped only when it makes a
// clockwise turn. Bit-identical points appear once (the domain validation refuses duplicates).
std::vector<DomainVertex> hull_with_collinear(const std::vector<Point2>& points) {
  std::vector<DomainVertex> order(points.size());
  std::iota(order.begin(), order.end(), DomainVertex{0});
  std::sort(order.begin(), order.end(), [&](DomainVertex a, DomainVertex b) {
    return points[a].x != points[b].x ? points[a].x < points[b].x : (points[a].y != points[b].y ? points[a].y < points[b].y : a < b);
  });
  order.erase(std::unique(order.begin(), order.end(), [&](DomainVertex a, DomainVertex b) { return points[a] == points[b]; }),
              order.end());
  if (order.size() < 3) return {};
  std::vector<DomainVertex> hull;
  for (int pass = 0; pass < 2; ++pass, std::reverse(order.begin(), order.end())) {  // lower, then upper chain
    const std::size_t base = hull.size();
    for (const DomainVertex v : order) {
      while (hull.size() >= base + 2 &&
             predicates::orient2d(points[hull[hull.size() - 2]], points[hull.back()], points[v]) == predicates::Sign::negative)
        hull.pop_back();
      hull.push_back(v);
    }
    hull.pop_back();
  }
  // All collinear: both chains run the same points (no area).
  const bool flat = std::all_of(hull.begin(), hull.end(), [&](DomainVertex v) {
    return predicates::orient2d(points[hull[0]], points[hull[1]], points[v]) == predicates::Sign::zero;
  });
  return flat ? std::vector<DomainVertex>{} : hull;
}

}  // namespace

PlanarDomain with_convex_hull(const PlanarDomain& domain, std::size_t* added) {
  PlanarDomain out = domain;
  const std::vector<DomainVertex> hull = hull_with_collinear(domain.points);
  std::vector<std::pair<DomainVertex, DomainVertex>> existing;
  const auto key = [](DomainVertex a, DomainVertex b) { return std::pair<DomainVertex, DomainVertex>(std::min(a, b), std::max(a, b)); };
  for (const DomainSegment& s : domain.segments) existing.push_back(key(s.a, s.b));
  std::sort(existing.begin(), existing.end());
  std::size_t count = 0;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    const DomainVertex a = hull[i], b = hull[(i + 1) % hull.size()];
    if (std::binary_search(existing.begin(), existing.end(), key(a, b))) continue;
    out.segments.push_back({a, b, kHullMarker});
    ++count;
  }
  if (added != nullptr) *added = count;
  return out;
}

}  // namespace certimesh::generators
