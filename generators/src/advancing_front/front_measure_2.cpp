#include "front_measure_2.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace certimesh::generators::advancing_front_detail {
namespace {

[[noreturn]] void refuse(const std::string& what) {
  throw std::invalid_argument("advancing front: " + what);
}

std::string at(const Point2& p) {
  std::ostringstream m;
  m.precision(17);
  m << "(" << p.x << ", " << p.y << ")";
  return m.str();
}

void check_edges(std::span<const Point2> points, std::span<const FrontEdge> front) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sorted;
  sorted.reserve(front.size());
  for (std::size_t i = 0; i < front.size(); ++i) {
    const FrontEdge& e = front[i];
    const std::string name = "front edge " + std::to_string(i) + " (" + std::to_string(e.a) + " -> " +
                             std::to_string(e.b) + ")";
    if (e.a >= points.size() || e.b >= points.size())
      refuse(name + " names a vertex beyond the " + std::to_string(points.size()) + " points");
    if (e.a == e.b) refuse(name + " joins a vertex to itself");
    for (const std::uint32_t v : {e.a, e.b})
      if (!std::isfinite(points[v].x) || !std::isfinite(points[v].y))
        refuse(name + ": vertex " + std::to_string(v) + " is not finite " + at(points[v]));
    sorted.emplace_back(e.a, e.b);
  }
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end())
    refuse("the edge " + std::to_string(twice->first) + " -> " + std::to_string(twice->second) +
           " is listed twice");
}

void check_closed(std::size_t point_count, std::span<const FrontEdge> front) {
  std::vector<std::int64_t> balance(point_count, 0);
  for (const FrontEdge& e : front) {
    ++balance[e.a];
    --balance[e.b];
  }
  for (std::size_t v = 0; v < point_count; ++v)
    if (balance[v] != 0)
      refuse("the front is not closed: vertex " + std::to_string(v) + " has " +
             (balance[v] > 0 ? "more outgoing than incoming" : "more incoming than outgoing") + " edges");
}

std::uint32_t find_root(std::vector<std::uint32_t>& parent, std::uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

std::uint64_t count_components(std::size_t point_count, std::span<const FrontEdge> front) {
  std::vector<std::uint32_t> parent(point_count);
  std::iota(parent.begin(), parent.end(), 0u);
  std::vector<char> used(point_count, 0);
  for (const FrontEdge& e : front) {
    used[e.a] = used[e.b] = 1;
    parent[find_root(parent, e.a)] = find_root(parent, e.b);
  }
  std::uint64_t count = 0;
  for (std::uint32_t v = 0; v < point_count; ++v) count += used[v] && find_root(parent, v) == v;
  return count;
}

// d0 by a grid of cell c: two points closer than 1.5 c have cells at most 2 apart on each
// axis (the cell index is computed to far better than half a cell), so scanning the 5 x 5
// block finds every such pair. With c the median edge length the shortest edge is such a
// pair, so the least distance found is d0 itself.
double least_distance(std::span<const Point2> points, std::span<const FrontEdge> front, double c) {
  std::vector<std::uint32_t> ids;
  ids.reserve(front.size());
  for (const FrontEdge& e : front) ids.push_back(e.a);
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
  for (const std::uint32_t v : ids) {
    x0 = std::min(x0, points[v].x);
    y0 = std::min(y0, points[v].y);
  }
  const auto cell_of = [&](const Point2& p) {
    const auto coord = [&](double t) { return static_cast<std::int64_t>(std::min(std::floor(t / c), 2.0e9)); };
    return std::pair{coord(p.x - x0), coord(p.y - y0)};
  };
  std::vector<std::pair<std::pair<std::int64_t, std::int64_t>, std::uint32_t>> keyed;
  keyed.reserve(ids.size());
  for (const std::uint32_t v : ids) keyed.push_back({cell_of(points[v]), v});
  std::sort(keyed.begin(), keyed.end());
  double best2 = 2.25 * c * c;
  for (const auto& [cell, v] : keyed)
    for (std::int64_t dj = -2; dj <= 2; ++dj)
      for (std::int64_t di = -2; di <= 2; ++di) {
        const std::pair<std::int64_t, std::int64_t> other{cell.first + di, cell.second + dj};
        auto it = std::lower_bound(keyed.begin(), keyed.end(), std::pair{other, 0u});
        for (; it != keyed.end() && it->first == other; ++it) {
          if (it->second == v) continue;
          const Point2 &p = points[v], &q = points[it->second];
          if (p == q)
            refuse("front vertices " + std::to_string(std::min(v, it->second)) + " and " +
                   std::to_string(std::max(v, it->second)) + " coincide at " + at(p));
          const double dx = p.x - q.x, dy = p.y - q.y;
          best2 = std::min(best2, dx * dx + dy * dy);
        }
      }
  return std::sqrt(best2);
}

}  // namespace

double median_edge_length(std::span<const Point2> points, std::span<const FrontEdge> front) {
  if (front.empty()) return 0.0;
  std::vector<double> lengths;
  lengths.reserve(front.size());
  for (const FrontEdge& e : front)
    lengths.push_back(std::hypot(points[e.b].x - points[e.a].x, points[e.b].y - points[e.a].y));
  const auto middle = lengths.begin() + static_cast<std::ptrdiff_t>(lengths.size() / 2);
  std::nth_element(lengths.begin(), middle, lengths.end());
  return *middle;
}

FrontMeasure measure_front(std::span<const Point2> points, std::span<const FrontEdge> front) {
  check_edges(points, front);
  check_closed(points.size(), front);
  FrontMeasure m;
  if (front.empty()) return m;
  const Point2 o = points[front[0].a];  // shoelace about a front vertex: less cancellation
  for (const FrontEdge& e : front) {
    const Point2 &a = points[e.a], &b = points[e.b];
    m.area += 0.5 * ((a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x));
    m.perimeter += std::hypot(b.x - a.x, b.y - a.y);
  }
  // F(P) of a bounded polygon encloses a positive area; a computed area <= 0 would take a
  // polygon thinner than the rounding of its own shoelace sum, so this refuses only fronts
  // with the region on the wrong side.
  if (!(m.area > 0.0)) {
    std::ostringstream why;
    why.precision(17);
    why << "the front encloses no area (signed area " << m.area
        << "): an outer loop runs clockwise, or the region is on the right of the edges";
    refuse(why.str());
  }
  m.components = count_components(points.size(), front);
  m.least_distance = least_distance(points, front, median_edge_length(points, front));
  return m;
}

}  // namespace certimesh::generators::advancing_front_detail
