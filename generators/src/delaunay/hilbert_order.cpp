#include "hilbert_order.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace certimesh::generators::detail {

namespace {

constexpr int hilbert_bits = 16;
constexpr std::uint32_t hilbert_side = 1u << hilbert_bits;

// The position of cell (x, y) along the Hilbert curve of a 2^16 x 2^16 grid.
std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y) {
  std::uint32_t d = 0;
  for (std::uint32_t s = hilbert_side / 2; s > 0; s /= 2) {
    const std::uint32_t rx = (x & s) ? 1u : 0u, ry = (y & s) ? 1u : 0u;
    d += s * s * ((3u * rx) ^ ry);
    if (ry == 0) {
      if (rx == 1) {
        x = hilbert_side - 1 - x;
        y = hilbert_side - 1 - y;
      }
      std::swap(x, y);
    }
  }
  return d;
}

std::uint32_t cell(double v, double lo, double scale) {
  const double c = std::floor((v - lo) * scale);
  return static_cast<std::uint32_t>(std::clamp(c, 0.0, double(hilbert_side - 1)));
}

}  // namespace

std::vector<std::uint32_t> hilbert_order(std::span<const predicates::Point2> points) {
  if (points.empty()) return {};
  double x0 = points[0].x, x1 = x0, y0 = points[0].y, y1 = y0;
  for (const auto& p : points) {
    x0 = std::min(x0, p.x), x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
  }
  // One scale for both axes keeps the curve's cells square (an approximation is fine:
  // the order only steers speed, never a decision).
  const double extent = std::max(x1 - x0, y1 - y0);
  const double scale = extent > 0.0 && std::isfinite(extent) ? double(hilbert_side) / extent : 0.0;
  std::vector<std::uint32_t> key(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    key[i] = hilbert_index(cell(points[i].x, x0, scale), cell(points[i].y, y0, scale));
  // Stable LSD radix sort on the 32-bit curve index (four byte passes): equal keys keep
  // index order, and it is several times faster than a comparison sort of 10^6 keys.
  std::vector<std::uint32_t> order(points.size()), scratch(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
  for (int shift = 0; shift < 32; shift += 8) {
    std::array<std::size_t, 257> start{};
    for (std::uint32_t i : order) ++start[((key[i] >> shift) & 0xffu) + 1];
    for (std::size_t b = 1; b < start.size(); ++b) start[b] += start[b - 1];
    for (std::uint32_t i : order) scratch[start[(key[i] >> shift) & 0xffu]++] = i;
    order.swap(scratch);
  }
  return order;
}

}  // namespace certimesh::generators::detail
