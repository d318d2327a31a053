#include "certimesh/topology/quality.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/volume_sign.h"

namespace certimesh::topology {

namespace {

namespace pr = certimesh::predicates;

template <std::size_t N>
double distance_nd(const std::array<double, N>& p, const std::array<double, N>& q) {
  double sum = 0.0;
  for (std::size_t i = 0; i < N; ++i) sum += (q[i] - p[i]) * (q[i] - p[i]);
  return std::sqrt(sum);
}

template <std::size_t N>
double perimeter(const std::array<double, N>& a, const std::array<double, N>& b,
                 const std::array<double, N>& c) {
  return distance_nd(a, b) + distance_nd(b, c) + distance_nd(c, a);
}

double total_edge_length(const Point3d& a, const Point3d& b, const Point3d& c, const Point3d& d) {
  return distance_nd(a, b) + distance_nd(a, c) + distance_nd(a, d) + distance_nd(b, c) + distance_nd(b, d) +
         distance_nd(c, d);
}

Point3d difference(const Point3d& p, const Point3d& q) { return {p[0] - q[0], p[1] - q[1], p[2] - q[2]}; }

Point3d cross(const Point3d& u, const Point3d& v) {
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// Three points in space are collinear exactly when all three coordinate-plane projections are.
bool collinear(const Point3d& a, const Point3d& b, const Point3d& c) {
  const auto zero = [&](int i, int j) {
    const auto ui = static_cast<std::size_t>(i);
    const auto uj = static_cast<std::size_t>(j);
    return pr::orient2d({a[ui], a[uj]}, {b[ui], b[uj]}, {c[ui], c[uj]}) == pr::Sign::zero;
  };
  return zero(0, 1) && zero(1, 2) && zero(0, 2);
}

void check_size(double h) {
  if (!(h > 0.0) || !std::isfinite(h))
    throw std::invalid_argument("size-aware quality: the size h must be positive and finite");
}

// 12√3 and 6⁴√2: the factors that make the equilateral simplex score 1.
constexpr double triangle_normaliser = 12.0 * std::numbers::sqrt3;
constexpr double tetrahedron_normaliser = 1296.0 * std::numbers::sqrt2;

}  // namespace

double triangle_area(const Point2d& a, const Point2d& b, const Point2d& c) {
  if (pr::orient2d({a[0], a[1]}, {b[0], b[1]}, {c[0], c[1]}) == pr::Sign::zero) return 0.0;
  return 0.5 * std::abs((b[0] - a[0]) * (c[1] - a[1]) - (c[0] - a[0]) * (b[1] - a[1]));
}

double triangle_area(const Point3d& a, const Point3d& b, const Point3d& c) {
  if (collinear(a, b, c)) return 0.0;
  const Point3d n = cross(difference(b, a), difference(c, a));
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

double tetrahedron_volume(const Point3d& a, const Point3d& b, const Point3d& c, const Point3d& d) {
  const auto P = [](const Point3d& p) { return pr::Point3{p[0], p[1], p[2]}; };
  if (pr::volume_sign(P(a), P(b), P(c), P(d)) == pr::Sign::zero) return 0.0;
  const Point3d n = cross(difference(c, a), difference(d, a));
  const Point3d e = difference(b, a);
  return std::abs(e[0] * n[0] + e[1] * n[1] + e[2] * n[2]) / 6.0;
}

double triangle_quality(const Point2d& a, const Point2d& b, const Point2d& c) {
  const double area = triangle_area(a, b, c);
  if (area == 0.0) return 0.0;
  const double p = perimeter(a, b, c);
  return std::min(1.0, triangle_normaliser * area / (p * p));
}

double triangle_quality(const Point3d& a, const Point3d& b, const Point3d& c) {
  const double area = triangle_area(a, b, c);
  if (area == 0.0) return 0.0;
  const double p = perimeter(a, b, c);
  return std::min(1.0, triangle_normaliser * area / (p * p));
}

double tetrahedron_quality(const Point3d& a, const Point3d& b, const Point3d& c, const Point3d& d) {
  const double volume = tetrahedron_volume(a, b, c, d);
  if (volume == 0.0) return 0.0;
  const double p = total_edge_length(a, b, c, d);
  return std::min(1.0, tetrahedron_normaliser * volume / (p * p * p));
}

double tetrahedron_min_dihedral_angle(const Point3d& a, const Point3d& b, const Point3d& c, const Point3d& d) {
  if (tetrahedron_volume(a, b, c, d) == 0.0) return 0.0;
  const Point3d* p[4] = {&a, &b, &c, &d};
  auto sub = [](const Point3d& u, const Point3d& v) { return Point3d{u[0] - v[0], u[1] - v[1], u[2] - v[2]}; };
  auto cross = [](const Point3d& u, const Point3d& v) {
    return Point3d{u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  };
  auto dot = [](const Point3d& u, const Point3d& v) { return u[0] * v[0] + u[1] * v[1] + u[2] * v[2]; };
  double smallest = 180.0;
  // The angle at edge (i, j) is between the faces (i, j, k) and (i, j, l): the angle between
  // the components of k - i and l - i orthogonal to the edge, atan2(|u x v|, u . v).
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      int k = 0;
      while (k == i || k == j) ++k;
      const int l = 6 - i - j - k;
      const Point3d e = sub(*p[j], *p[i]);
      const Point3d u = cross(e, sub(*p[k], *p[i])), v = cross(e, sub(*p[l], *p[i]));
      const Point3d w = cross(u, v);
      const double angle = std::atan2(std::sqrt(dot(w, w)), dot(u, v)) * (180.0 / std::numbers::pi);
      smallest = std::min(smallest, angle);
    }
  return smallest;
}

double size_quality_factor(double gamma) {
  if (!(gamma >= 0.0)) throw std::invalid_argument("size_quality_factor: gamma must be >= 0");
  if (gamma == 0.0 || std::isinf(gamma)) return 0.0;
  const double m = std::min(gamma, 1.0 / gamma);
  const double f = m * (2.0 - m);
  return f * f * f;
}

double size_aware_triangle_quality(const Point2d& a, const Point2d& b, const Point2d& c, double h) {
  check_size(h);
  const double gamma = perimeter(a, b, c) / (3.0 * h);
  return size_quality_factor(gamma) * triangle_quality(a, b, c);
}

double size_aware_tetrahedron_quality(const Point3d& a, const Point3d& b, const Point3d& c,
                                      const Point3d& d, double h) {
  check_size(h);
  const double gamma = total_edge_length(a, b, c, d) / (6.0 * h);
  return size_quality_factor(gamma) * tetrahedron_quality(a, b, c, d);
}

}  // namespace certimesh::topology
