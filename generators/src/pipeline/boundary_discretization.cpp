#include "boundary_discretization.h"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

#include "point_on_segment.h"

namespace certimesh::generators::detail {

namespace {

constexpr int kSizeSamples = 16;  // size samples along a segment, for graded size functions

double checked_size(const SizePolicy& size, const Point2& p) {
  const double s = size.at(p);
  if (!(s > 0.0) || !std::isfinite(s)) {
    throw std::invalid_argument("the size function gives " + std::to_string(s) + " at (" +
                                std::to_string(p.x) + ", " + std::to_string(p.y) +
                                "); sizes must be positive and finite");
  }
  return s;
}

Point2 lerp(const Point2& a, const Point2& b, double t) {
  return {a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
}

// The fractions (in (0, 1), increasing) where a segment of length `length` is split so that
// each piece is about as long as the size there: the number of pieces is the integral of
// 1/size along the segment, rounded, and the split points divide that integral evenly.
std::vector<double> split_fractions(const Point2& a, const Point2& b, double length, const SizePolicy& size) {
  std::array<double, kSizeSamples + 1> cumulative{};  // ∫ 1/s from 0 to sample k
  double previous = 1.0 / checked_size(size, a);
  for (int k = 1; k <= kSizeSamples; ++k) {
    const double t = static_cast<double>(k) / kSizeSamples;
    const double current = 1.0 / checked_size(size, lerp(a, b, t));
    cumulative[static_cast<std::size_t>(k)] =
        cumulative[static_cast<std::size_t>(k - 1)] + 0.5 * (previous + current) * length / kSizeSamples;
    previous = current;
  }
  const double total = cumulative[kSizeSamples];
  const double pieces = std::max(1.0, std::round(total));
  if (pieces > 1e9) throw std::invalid_argument("the size is too small: a segment would need over 10^9 pieces");
  std::vector<double> fractions;
  fractions.reserve(static_cast<std::size_t>(pieces) - 1);
  std::size_t k = 0;
  for (double i = 1.0; i < pieces; i += 1.0) {
    const double target = total * i / pieces;
    while (k + 1 < kSizeSamples && cumulative[k + 1] < target) ++k;
    const double span = cumulative[k + 1] - cumulative[k];
    const double within = span > 0.0 ? (target - cumulative[k]) / span : 0.0;
    const double f = (static_cast<double>(k) + within) / kSizeSamples;
    if (f > 0.0 && f < 1.0 && (fractions.empty() || f > fractions.back())) fractions.push_back(f);
  }
  return fractions;
}

}  // namespace

DiscretizedBoundary discretize_boundary(const PlanarDomain& domain, const SizePolicy& size,
                                        std::span<const std::uint8_t> keep_whole, std::uint64_t max_points) {
  DiscretizedBoundary out;
  out.points = domain.points;
  for (std::uint32_t s = 0; s < domain.segments.size(); ++s) {
    const DomainSegment& segment = domain.segments[s];
    const Point2 a = domain.points[segment.a];
    const Point2 b = domain.points[segment.b];
    const bool whole = size.automatic() || (s < keep_whole.size() && keep_whole[s] != 0);
    const std::vector<double> fractions =
        whole ? std::vector<double>{} : split_fractions(a, b, std::hypot(b.x - a.x, b.y - a.y), size);
    if (out.points.size() + fractions.size() > max_points) {
      throw std::invalid_argument("the size is too small for this domain: over " + std::to_string(max_points) +
                                  " boundary points");
    }
    std::uint32_t from = segment.a;
    for (const double f : fractions) {
      const Point2 p = point_on_segment(a, b, f);
      if (p == out.points[from] || p == b) continue;  // rounding met a neighbour: skip it
      const auto id = static_cast<std::uint32_t>(out.points.size());
      out.points.push_back(p);
      out.subsegments.push_back({from, id, segment.label});
      out.origin.push_back(s);
      from = id;
    }
    out.subsegments.push_back({from, segment.b, segment.label});
    out.origin.push_back(s);
  }
  return out;
}

}  // namespace certimesh::generators::detail
