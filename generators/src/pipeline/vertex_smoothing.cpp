#include "vertex_smoothing.h"
#include "vertex_stars.h"

#include <algorithm>
#include <cmath>

#include "certimesh/generators/improvement/angle_floor_2.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/topology/quality.h"

namespace certimesh::generators::detail {

namespace {

double quality(const Point2& a, const Point2& b, const Point2& c) {
  return topology::triangle_quality(topology::Point2d{a.x, a.y}, topology::Point2d{b.x, b.y},
                                    topology::Point2d{c.x, c.y});
}

// The two other vertices of triangle t, in counterclockwise order after v.
std::array<std::uint32_t, 2> link_edge(const std::array<std::uint32_t, 3>& t, std::uint32_t v) {
  const int i = t[0] == v ? 0 : (t[1] == v ? 1 : 2);
  return {t[static_cast<std::size_t>((i + 1) % 3)], t[static_cast<std::size_t>((i + 2) % 3)]};
}

// Worst (floored, angle_floor_2.h) quality of v's star with v at p; -2 when some triangle is
// not certainly positive.
double star_quality(const TriangleSoup& m, std::span<const std::uint32_t> star, std::uint32_t v, const Point2& p,
                    double floor) {
  double worst = 1.0;
  for (const std::uint32_t t : star) {
    const auto [a, b] = link_edge(m.triangles[t], v);
    if (predicates::orient2d(p, m.points[a], m.points[b]) != predicates::Sign::positive) return -2.0;
    const topology::Point2d pp{p.x, p.y}, pa{m.points[a].x, m.points[a].y}, pb{m.points[b].x, m.points[b].y};
    worst = std::min(worst, floored_score(topology::triangle_quality(pp, pa, pb), pp, pa, pb, floor));
  }
  return worst;
}

// Mean of the apexes of the equilateral triangles on the link edges, on v's side.
Point2 ideal_position(const TriangleSoup& m, std::span<const std::uint32_t> star, std::uint32_t v) {
  constexpr double kHeight = 0.86602540378443864676;  // √3/2
  double x = 0.0, y = 0.0;
  for (const std::uint32_t t : star) {
    const auto [a, b] = link_edge(m.triangles[t], v);
    const Point2 pa = m.points[a], pb = m.points[b];
    const double dx = pb.x - pa.x, dy = pb.y - pa.y;
    x += 0.5 * (pa.x + pb.x) - kHeight * dy;
    y += 0.5 * (pa.y + pb.y) + kHeight * dx;
  }
  const double n = static_cast<double>(star.size());
  return {x / n, y / n};
}

// The mean of the link vertices (Laplacian smoothing's target).
Point2 link_centroid(const TriangleSoup& m, std::span<const std::uint32_t> star, std::uint32_t v) {
  double x = 0.0, y = 0.0;
  for (const std::uint32_t t : star) {
    const auto [a, b] = link_edge(m.triangles[t], v);
    x += m.points[a].x + m.points[b].x;
    y += m.points[a].y + m.points[b].y;
  }
  const double n = 2.0 * static_cast<double>(star.size());
  return {x / n, y / n};
}

// The best of a few points on the way to the ideal point and to the link's centroid (full,
// half and quarter steps) by the star's worst quality, or v's own place when none strictly
// improves on `before`. The centroid serves where the ideal points of the link edges
// disagree (a vertex of degree 5 or 7), the short steps where the full one overshoots.
Point2 best_position(const TriangleSoup& m, std::span<const std::uint32_t> star, std::uint32_t v, double before,
                     double floor) {
  const Point2 here = m.points[v];
  double best = before;
  Point2 chosen = here;
  for (const Point2& goal : {ideal_position(m, star, v), link_centroid(m, star, v)}) {
    for (const double step : {1.0, 0.5, 0.25}) {
      const Point2 p{here.x + step * (goal.x - here.x), here.y + step * (goal.y - here.y)};
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
      const double q = star_quality(m, star, v, p, floor);
      if (q > best) {
        best = q;
        chosen = p;
      }
    }
  }
  return chosen;
}

std::vector<std::uint8_t> poor_vertices(const TriangleSoup& m, const VertexStars& stars, double target) {
  std::vector<std::uint8_t> poor(m.points.size(), 0);
  for (const auto& t : m.triangles) {
    if (quality(m.points[t[0]], m.points[t[1]], m.points[t[2]]) < target)
      for (const std::uint32_t v : t) poor[v] = 1;
  }
  std::vector<std::uint8_t> grown = poor;  // one ring more
  for (std::uint32_t v = 0; v < m.points.size(); ++v) {
    if (!poor[v]) continue;
    for (const std::uint32_t t : stars.of(v))
      for (const std::uint32_t w : m.triangles[t]) grown[w] = 1;
  }
  return grown;
}

}  // namespace

SmoothingStats smooth_poor_regions(TriangleSoup& m, std::span<const DomainSegment> fixed_edges, double target,
                                   int sweeps, double min_angle_floor) {
  SmoothingStats stats;
  const VertexStars stars(m);
  std::vector<std::uint8_t> movable = poor_vertices(m, stars, target);
  for (const DomainSegment& s : fixed_edges) movable[s.a] = movable[s.b] = 0;
  for (int sweep = 0; sweep < sweeps; ++sweep) {
    for (std::uint32_t v = 0; v < m.points.size(); ++v) {
      if (!movable[v] || stars.of(v).empty()) continue;
      ++stats.candidates;
      const auto star = stars.of(v);
      const double before = star_quality(m, star, v, m.points[v], min_angle_floor);
      const Point2 moved = best_position(m, star, v, before, min_angle_floor);
      if (moved != m.points[v]) {
        m.points[v] = moved;
        ++stats.moved;
      }
    }
  }
  return stats;
}

}  // namespace certimesh::generators::detail
