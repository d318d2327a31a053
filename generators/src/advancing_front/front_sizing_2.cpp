#include "front_sizing_2.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace certimesh::generators::advancing_front_detail {
namespace {

constexpr double pi = 3.14159265358979323846;
constexpr double sqrt3 = 1.73205080756887729353;
constexpr double mu = 0.5;  // (3.3.2), both modes of the book

}  // namespace

std::uint64_t triangle_bound(const FrontMeasure& front, double delta) {
  const double n = 8.0 * front.area / (pi * delta * delta) + 4.0 * front.perimeter / (pi * delta) +
                   2.0 * static_cast<double>(front.components) - 5.0;
  if (!(n < 9.2e18)) return std::uint64_t{1} << 63;  // also NaN (delta = 0)
  return n < 1.0 ? 1 : static_cast<std::uint64_t>(std::ceil(n));
}

FrontSizing2::FrontSizing2(const SizePolicy& policy, double least_distance)
    : policy_(policy), user_size_(!policy.automatic()), d0_(least_distance) {
  if (!std::isfinite(policy.growth) || policy.growth < 1.0) {
    std::ostringstream m;
    m << "advancing front: the growth factor must be finite and >= 1, got " << policy.growth;
    throw std::invalid_argument(m.str());
  }
  growth_limited_ = user_size_ && policy.growth > 1.0;
  if (!user_size_) {
    s0_ = d0_;
    sigma_ = 2.0 * s0_ * (1.0 - mu) / mu;
  }
}

double FrontSizing2::spacing_r(double s) const {
  const double ds = s - s0_;
  return 0.5 * mu * (s + s0_ + std::sqrt(ds * ds + sigma_ * sigma_));
}

ApexSize FrontSizing2::at(double l, const Point2& mid) {
  double s = policy_.growth * l;
  if (user_size_) {
    const double user = policy_.at(mid);
    if (!(user > 0.0) || !std::isfinite(user)) {
      std::ostringstream m;
      m.precision(17);
      m << "advancing front: the size function returned " << user << " at (" << mid.x << ", "
        << mid.y << "); sizes must be positive and finite";
      throw std::invalid_argument(m.str());
    }
    if (s_min_ == 0.0 || user < s_min_) {
      s_min_ = user;
      delta_changed_ = true;
      if (growth_limited_) {
        s0_ = std::min(d0_, s_min_);
        sigma_ = 2.0 * s0_ * (1.0 - mu) / mu;
      }
    }
    s = growth_limited_ ? std::min(user, s) : user;
  }
  s = std::max(s, l);
  const double hc = std::sqrt(std::max(s * s - 0.25 * l * l, 0.0));
  return ApexSize{s, 0.5 * hc, spacing_r(s)};
}

double FrontSizing2::delta() const {
  if (!user_size_) return sqrt3 / 8.0 * d0_;
  const double s_min = s_min_ > 0.0 ? s_min_ : std::numeric_limits<double>::infinity();
  if (growth_limited_) return sqrt3 / 8.0 * std::min(d0_, s_min);
  return std::min(d0_, sqrt3 / 4.0 * s_min);
}

bool FrontSizing2::take_delta_change() {
  const bool changed = delta_changed_;
  delta_changed_ = false;
  return changed;
}

}  // namespace certimesh::generators::advancing_front_detail
