#include "delaunay_completion.h"

#include <algorithm>
#include <unordered_set>

#include "certimesh/generators/delaunay/constrained_delaunay_2.h"

namespace certimesh::generators::detail {

namespace {

std::uint64_t directed_key(std::uint32_t a, std::uint32_t b) {
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

// The front's vertices and the interior ones, renumbered 0..n-1 in increasing id order (deterministic).
std::vector<std::uint32_t> front_vertices(std::span<const FrontEdge> front, std::span<const std::uint32_t> interior) {
  std::vector<std::uint32_t> ids(interior.begin(), interior.end());
  ids.reserve(front.size() * 2 + interior.size());
  for (const FrontEdge& e : front) {
    ids.push_back(e.a);
    ids.push_back(e.b);
  }
  std::sort(ids.begin(), ids.end());
  ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
  return ids;
}

std::uint32_t local_id(const std::vector<std::uint32_t>& ids, std::uint32_t global) {
  return static_cast<std::uint32_t>(std::lower_bound(ids.begin(), ids.end(), global) - ids.begin());
}

// Inside triangles: seeded on the left of every front edge, grown across unconstrained edges
// (the region is bounded by constrained front edges, so the growth stays inside it).
std::vector<std::uint8_t> inside_triangles(const ConstrainedDelaunay2& cdt,
                                           const std::unordered_set<std::uint64_t>& directed) {
  std::vector<std::uint8_t> inside(cdt.triangle_slot_count(), 0);
  std::vector<std::uint32_t> stack;
  for (std::uint32_t t = 0; t < cdt.triangle_slot_count(); ++t) {
    if (!cdt.is_live(t)) continue;
    const auto v = cdt.vertices(t);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t p = v[static_cast<std::size_t>((i + 1) % 3)];
      const std::uint32_t q = v[static_cast<std::size_t>((i + 2) % 3)];
      if (cdt.is_constrained(t, i) && directed.count(directed_key(p, q)) && !inside[t]) {
        inside[t] = 1;
        stack.push_back(t);
      }
    }
  }
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t n = cdt.neighbour(t, i);
      if (n == ConstrainedDelaunay2::none || cdt.is_constrained(t, i) || inside[n]) continue;
      inside[n] = 1;
      stack.push_back(n);
    }
  }
  return inside;
}

}  // namespace

std::vector<std::array<std::uint32_t, 3>> complete_by_delaunay(std::span<const Point2> points,
                                                               std::span<const FrontEdge> front,
                                                               std::span<const std::uint32_t> interior) {
  const std::vector<std::uint32_t> ids = front_vertices(front, interior);
  std::vector<Point2> local_points;
  local_points.reserve(ids.size());
  for (const std::uint32_t id : ids) local_points.push_back(points[id]);
  ConstrainedDelaunay2 cdt(local_points);
  std::unordered_set<std::uint64_t> directed;
  directed.reserve(front.size() * 2);
  for (const FrontEdge& e : front) {
    const std::uint32_t a = local_id(ids, e.a);
    const std::uint32_t b = local_id(ids, e.b);
    directed.insert(directed_key(a, b));
    if (!directed.count(directed_key(b, a))) cdt.insert_constraint(a, b);  // a cut: once
  }
  const std::vector<std::uint8_t> inside = inside_triangles(cdt, directed);
  std::vector<std::array<std::uint32_t, 3>> triangles;
  for (std::uint32_t t = 0; t < cdt.triangle_slot_count(); ++t) {
    if (!cdt.is_live(t) || !inside[t]) continue;
    const auto v = cdt.vertices(t);
    triangles.push_back({ids[v[0]], ids[v[1]], ids[v[2]]});
  }
  return triangles;
}

}  // namespace certimesh::generators::detail
