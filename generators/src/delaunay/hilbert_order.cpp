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
std::uint32_t cell(double v, double lo, double scale, std::uint32_t side) {
  const double c = (v - lo) * scale;
  return c < double(side) ? static_cast<std::uint32_t>(c) : side - 1;
}


// The 3D curve: Skilling's transform ("Programming the Hilbert curve", AIP Conf. Proc. 707,
// 2004) of cell (x, y, z), each < 2^10, to the transposed index, then its bits interleaved:
// a position along a Hilbert curve of the 2^10 x 2^10 x 2^10 grid (30 bits). As in 2D, which
// curve it is steers speed only, never the tetrahedralization.
constexpr int hilbert_bits_3 = 10;
constexpr std::uint32_t hilbert_side_3 = 1u << hilbert_bits_3;

// The bits of x (10 of them) spread to every third bit position.
constexpr std::uint32_t spread_bits_3(std::uint32_t x) {
  x = (x | (x << 16)) & 0x030000ffu;
  x = (x | (x << 8)) & 0x0300f00fu;
  x = (x | (x << 4)) & 0x030c30c3u;
  x = (x | (x << 2)) & 0x09249249u;
  return x;
}

constexpr std::uint32_t hilbert_index_3(std::uint32_t x0, std::uint32_t x1, std::uint32_t x2) {
  std::uint32_t X[3] = {x0, x1, x2};
  constexpr std::uint32_t top = 1u << (hilbert_bits_3 - 1);
  for (std::uint32_t q = top; q > 1; q >>= 1) {  // undo the excess work
    const std::uint32_t p = q - 1;
    for (int i = 0; i < 3; ++i) {
      if (X[i] & q) {
        X[0] ^= p;
      } else {
        const std::uint32_t t = (X[0] ^ X[i]) & p;
        X[0] ^= t, X[i] ^= t;
      }
    }
  }
  X[1] ^= X[0], X[2] ^= X[1];  // Gray encode
  std::uint32_t t = 0;
  for (std::uint32_t q = top; q > 1; q >>= 1)
    if (X[2] & q) t ^= q - 1;
  for (auto& v : X) v ^= t;
  return (spread_bits_3(X[0]) << 2) | (spread_bits_3(X[1]) << 1) | spread_bits_3(X[2]);
}

// The biased randomized rounds, each sorted along the curve: curve(i) is the curve position
// of point i in 28 bits. (key << 32 | point index), key = (round << 28 | curve(i)), sorted by
// a stable LSD radix sort on the key (three passes of 11 bits, histograms counted in one
// pass): equal keys keep index order, and each pass reads its input sequentially. A point's
// round: level = (trailing zero bits of mix(index)) / 2, so P(level >= k) = 4^-k, capped at
// `rounds`; higher levels are inserted first.
template <class Curve>
std::vector<std::uint32_t, LargeArrayAllocator<std::uint32_t>> brio_order(std::size_t n, Curve curve) {
  std::vector<std::uint64_t, LargeArrayAllocator<std::uint64_t>> item(n), scratch(n);
  constexpr int digit_bits = 11, passes = 3;
  constexpr std::size_t buckets = std::size_t{1} << digit_bits;
  std::vector<std::array<std::uint32_t, buckets>> count(passes);
  for (auto& c : count) c.fill(0);
  int rounds = 0;  // floor(log4(n / 64)), at most 12
  while (rounds < 12 && (std::size_t{64} << (2 * (rounds + 1))) <= n) ++rounds;
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t position = curve(i);
    const int level = std::min(std::countr_zero(mix(i) | (std::uint64_t{1} << 62)) / 2, rounds);
    const std::uint32_t key = (static_cast<std::uint32_t>(rounds - level) << 28) | position;
    item[i] = (std::uint64_t{key} << 32) | i;
    for (int p = 0; p < passes; ++p) ++count[p][(key >> (digit_bits * p)) & (buckets - 1)];
  }
  for (int p = 0; p < passes; ++p) {
    auto& c = count[p];
    if (std::count(c.begin(), c.end(), 0u) == buckets - 1) continue;  // one digit value: no reorder
    std::uint32_t sum = 0;
    for (auto& v : c) {
      const std::uint32_t k = v;
      v = sum, sum += k;
    }
    const int shift = 32 + digit_bits * p;
    for (std::uint64_t it : item) scratch[c[(it >> shift) & (buckets - 1)]++] = it;
    item.swap(scratch);
  }
  std::vector<std::uint32_t, LargeArrayAllocator<std::uint32_t>> order(n);
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(item[i]);
  return order;
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
  // The curve index at 2^14 x 2^14 cells.
  return brio_order(points.size(), [&](std::size_t i) {
    return hilbert_index(cell(points[i].x, x0, scale, hilbert_side), cell(points[i].y, y0, scale, hilbert_side)) >> 4;
  });
}

std::vector<std::uint32_t, LargeArrayAllocator<std::uint32_t>> hilbert_order_3(std::span<const predicates::Point3> points) {
  if (points.empty()) return {};
  predicates::Point3 lo = points[0], hi = points[0];
  for (const auto& p : points) {
    lo.x = std::min(lo.x, p.x), hi.x = std::max(hi.x, p.x);
    lo.y = std::min(lo.y, p.y), hi.y = std::max(hi.y, p.y);
    lo.z = std::min(lo.z, p.z), hi.z = std::max(hi.z, p.z);
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  const double scale = extent > 0.0 && std::isfinite(extent) ? double(hilbert_side_3) / extent : 0.0;
  // The curve index at 2^28 cells (of 2^30).
  return brio_order(points.size(), [&](std::size_t i) {
    const auto& p = points[i];
    return hilbert_index_3(cell(p.x, lo.x, scale, hilbert_side_3), cell(p.y, lo.y, scale, hilbert_side_3),
                           cell(p.z, lo.z, scale, hilbert_side_3)) >> 2;
  });
}

}  // namespace certimesh::generators::detail
