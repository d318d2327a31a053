#include "boundary_discretization.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "point_on_segment.h"

namespace certimesh::generators::detail {

namespace {

constexpr int kMinSizeSamples = 16;       // size samples along a segment, at least
constexpr double kSamplesPerSize = 4.0;   // and at least this many per local size
constexpr std::size_t kMaxSizeSamples = std::size_t{1} << 26;

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

// ∫ 1/s along the segment, sampled at fractions `at` (from 0 to 1): the step is at most
// 1/16 of the segment and a quarter of the size at the last sample, so a size that varies
// along the segment (the boundary-adapted size near a short neighbour) is followed.
struct SizeIntegral {
  std::vector<double> at, cumulative;
};

SizeIntegral integrate_inverse_size(const Point2& a, const Point2& b, double length, const SizePolicy& size) {
  SizeIntegral out;
  out.at.push_back(0.0);
  out.cumulative.push_back(0.0);
  double t = 0.0, previous = 1.0 / checked_size(size, a);
  while (t < 1.0) {
    // A constant size (no size function) needs no more than the 16 samples.
    const double step = size.size_function ? std::min(1.0 / kMinSizeSamples, 1.0 / (kSamplesPerSize * previous * length))
                                           : 1.0 / kMinSizeSamples;
    const double next = step >= 1.0 - t ? 1.0 : t + step;
    const double current = 1.0 / checked_size(size, next == 1.0 ? b : lerp(a, b, next));
    out.at.push_back(next);
    out.cumulative.push_back(out.cumulative.back() + 0.5 * (previous + current) * length * (next - t));
    if (out.at.size() > kMaxSizeSamples) throw std::invalid_argument("the size is too small: a segment would need over 10^7 pieces");
    t = next;
    previous = current;
  }
  return out;
}

// The fractions (in (0, 1), increasing) where a segment of length `length` is split so that
// each piece is about as long as the size there: the number of pieces is the integral of
// 1/size along the segment, rounded, and the split points divide that integral evenly.
std::vector<double> split_fractions(const Point2& a, const Point2& b, double length, const SizePolicy& size) {
  const SizeIntegral integral = integrate_inverse_size(a, b, length, size);
  const double total = integral.cumulative.back();
  const double pieces = std::max(1.0, std::round(total));
  if (pieces > 1e9) throw std::invalid_argument("the size is too small: a segment would need over 10^9 pieces");
  std::vector<double> fractions;
  fractions.reserve(static_cast<std::size_t>(pieces) - 1);
  std::size_t k = 0;
  const std::size_t last = integral.at.size() - 1;
  for (double i = 1.0; i < pieces; i += 1.0) {
    const double target = total * i / pieces;
    while (k + 1 < last && integral.cumulative[k + 1] < target) ++k;
    const double span = integral.cumulative[k + 1] - integral.cumulative[k];
    const double within = span > 0.0 ? (target - integral.cumulative[k]) / span : 0.0;
    const double f = integral.at[k] + within * (integral.at[k + 1] - integral.at[k]);
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
