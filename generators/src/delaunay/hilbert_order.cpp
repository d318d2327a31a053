#include "hilbert_order.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>

namespace certimesh::generators::detail {

namespace {

constexpr int hilbert_bits = 16;
constexpr std::uint32_t hilbert_side = 1u << hilbert_bits;

// The bits of x (16 of them) spread to the even bit positions.
constexpr std::uint32_t spread_bits(std::uint32_t x) {
  x = (x | (x << 8)) & 0x00ff00ffu;
  x = (x | (x << 4)) & 0x0f0f0f0fu;
  x = (x | (x << 2)) & 0x33333333u;
  x = (x | (x << 1)) & 0x55555555u;
  return x;
}

// The position of cell (x, y), x, y < 2^16, along a Hilbert curve of the 2^16 x 2^16 grid,
// branch-free: the per-level orientation state is a prefix scan over the 16 levels done in
// four doubling rounds (the "parallel prefix" formulation of the curve's state machine, as
// in rawrunprotected's public-domain hilbert_curves code). The old loop took a
// data-dependent branch per level, mispredicted half the time on random points (14 % of
// the 10^6-point construction). Which Hilbert curve it is (start (0, 0), end (2^16 - 1, 0))
// only steers speed, never the triangulation: it was checked to be a bijection with unit
// steps on the grids 2^n x 2^n, n = 1, 2, 3, 5, 8, 10, when it was written.
constexpr std::uint32_t hilbert_index(std::uint32_t x, std::uint32_t y) {
  std::uint32_t A, B, C, D;
  {
    const std::uint32_t a = x ^ y, b = 0xffffu ^ a, c = 0xffffu ^ (x | y), d = x & (y ^ 0xffffu);
    A = a | (b >> 1);
    B = (a >> 1) ^ a;
    C = ((c >> 1) ^ (b & (d >> 1))) ^ c;
    D = ((a & (c >> 1)) ^ (d >> 1)) ^ d;
  }
  for (int shift : {2, 4}) {
    const std::uint32_t a = A, b = B, c = C, d = D;
    A = (a & (a >> shift)) ^ (b & (b >> shift));
    B = (a & (b >> shift)) ^ (b & ((a ^ b) >> shift));
    C ^= (a & (c >> shift)) ^ (b & (d >> shift));
    D ^= (b & (c >> shift)) ^ ((a ^ b) & (d >> shift));
  }
  C ^= (A & (C >> 8)) ^ (B & (D >> 8));
  D ^= (B & (C >> 8)) ^ ((A ^ B) & (D >> 8));
  const std::uint32_t a = C ^ (C >> 1), b = D ^ (D >> 1);
  const std::uint32_t i0 = x ^ y, i1 = b | (0xffffu ^ (i0 | a));
  return (spread_bits(i1) << 1) | spread_bits(i0);
}

// splitmix64's finaliser (Steele, Lea and Flood): the seeded, documented generator that
// assigns each point index to its round.
constexpr std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15u;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
  return z ^ (z >> 31);
}

// floor((v - lo) * scale) clamped to the grid; v >= lo, so the product is >= 0 or NaN
// (an infinite extent makes scale 0), and NaN goes to the last cell.
std::uint32_t cell(double v, double lo, double scale) {
  const double c = (v - lo) * scale;
  return c < double(hilbert_side) ? static_cast<std::uint32_t>(c) : hilbert_side - 1;
}

}  // namespace

std::vector<std::uint32_t, LargeArrayAllocator<std::uint32_t>> hilbert_order(std::span<const predicates::Point2> points) {
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
  // (key << 32 | point index), key = (round << 28 | the curve index at 2^14 x 2^14 cells),
  // sorted by a stable LSD radix sort on the key (three passes of 11 bits, histograms
  // counted in one pass): equal keys keep index order, and each pass reads its input
  // sequentially. A point's round: level = (trailing zero bits of mix(index)) / 2, so
  // P(level >= k) = 4^-k, capped at `rounds`; higher levels are inserted first.
  std::vector<std::uint64_t, LargeArrayAllocator<std::uint64_t>> item(points.size()), scratch(points.size());
  constexpr int digit_bits = 11, passes = 3;
  constexpr std::size_t buckets = std::size_t{1} << digit_bits;
  std::vector<std::array<std::uint32_t, buckets>> count(passes);
  for (auto& c : count) c.fill(0);
  int rounds = 0;  // floor(log4(n / 64)), at most 12
  while (rounds < 12 && (std::size_t{64} << (2 * (rounds + 1))) <= points.size()) ++rounds;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::uint32_t curve = hilbert_index(cell(points[i].x, x0, scale), cell(points[i].y, y0, scale)) >> 4;
    const int level = std::min(std::countr_zero(mix(i) | (std::uint64_t{1} << 62)) / 2, rounds);
    const std::uint32_t key = (static_cast<std::uint32_t>(rounds - level) << 28) | curve;
    item[i] = (std::uint64_t{key} << 32) | i;
    for (int p = 0; p < passes; ++p) ++count[p][(key >> (digit_bits * p)) & (buckets - 1)];
  }
  for (int p = 0; p < passes; ++p) {
    auto& c = count[p];
    if (std::count(c.begin(), c.end(), 0u) == buckets - 1) continue;  // one digit value: no reorder
    std::uint32_t sum = 0;
    for (auto& v : c) {
      const std::uint32_t n = v;
      v = sum, sum += n;
    }
    const int shift = 32 + digit_bits * p;
    for (std::uint64_t it : item) scratch[c[(it >> shift) & (buckets - 1)]++] = it;
    item.swap(scratch);
  }
  std::vector<std::uint32_t, LargeArrayAllocator<std::uint32_t>> order(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(item[i]);
  return order;
}

}  // namespace certimesh::generators::detail
