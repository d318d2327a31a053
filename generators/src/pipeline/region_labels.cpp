#include "region_labels.h"

#include <algorithm>

namespace certimesh::generators::detail {

namespace {

struct HalfEdge {
  std::uint64_t key;      // the undirected edge
  std::uint32_t triangle;
  std::uint32_t directed_a;  // the edge as the triangle runs it (region on its left)
  std::uint32_t directed_b;
};

std::uint64_t undirected(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

}  // namespace

std::vector<io::Label> region_labels(std::span<const std::array<std::uint32_t, 3>> triangles,
                                     std::span<const FrontEdge> front, std::span<const io::Label> front_region,
                                     io::Label fallback) {
  const bool single = std::all_of(front_region.begin(), front_region.end(),
                                  [&](io::Label l) { return l == front_region.front(); });
  if (front_region.empty() || single) {
    return std::vector<io::Label>(triangles.size(), front_region.empty() ? fallback : front_region.front());
  }
  // Edge adjacency by sorting half-edges (deterministic, no hashing).
  std::vector<HalfEdge> half;
  half.reserve(triangles.size() * 3);
  for (std::uint32_t t = 0; t < triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = triangles[t][static_cast<std::size_t>(i)];
      const std::uint32_t b = triangles[t][static_cast<std::size_t>((i + 1) % 3)];
      half.push_back({undirected(a, b), t, a, b});
    }
  }
  std::sort(half.begin(), half.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.key != y.key ? x.key < y.key : x.triangle < y.triangle;
  });
  std::vector<std::uint64_t> blocked;
  blocked.reserve(front.size());
  for (const FrontEdge& e : front) blocked.push_back(undirected(e.a, e.b));
  std::sort(blocked.begin(), blocked.end());
  const auto is_blocked = [&](std::uint64_t key) { return std::binary_search(blocked.begin(), blocked.end(), key); };

  constexpr io::Label unset = INT32_MIN;
  std::vector<io::Label> label(triangles.size(), unset);
  std::vector<std::uint32_t> stack;
  for (std::size_t f = 0; f < front.size(); ++f) {  // seeds: the triangle left of each front edge
    const auto range = std::equal_range(half.begin(), half.end(), HalfEdge{undirected(front[f].a, front[f].b), 0, 0, 0},
                                        [](const HalfEdge& x, const HalfEdge& y) { return x.key < y.key; });
    for (auto h = range.first; h != range.second; ++h) {
      if (h->directed_a == front[f].a && h->directed_b == front[f].b && label[h->triangle] == unset) {
        label[h->triangle] = front_region[f];
        stack.push_back(h->triangle);
      }
    }
  }
  while (!stack.empty()) {
    const std::uint32_t t = stack.back();
    stack.pop_back();
    for (int i = 0; i < 3; ++i) {
      const std::uint64_t key = undirected(triangles[t][static_cast<std::size_t>(i)],
                                           triangles[t][static_cast<std::size_t>((i + 1) % 3)]);
      if (is_blocked(key)) continue;
      const auto range = std::equal_range(half.begin(), half.end(), HalfEdge{key, 0, 0, 0},
                                          [](const HalfEdge& x, const HalfEdge& y) { return x.key < y.key; });
      for (auto h = range.first; h != range.second; ++h) {
        if (label[h->triangle] == unset) {
          label[h->triangle] = label[t];
          stack.push_back(h->triangle);
        }
      }
    }
  }
  for (io::Label& l : label) {
    if (l == unset) l = fallback;
  }
  return label;
}

}  // namespace certimesh::generators::detail
