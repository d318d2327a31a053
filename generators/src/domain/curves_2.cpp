// Curve discretization (curves_2.h): fine sampling of a parametric curve, a budget integral of
// ds / h(s), and points at equal budget steps, each evaluated from the curve's formula.
#include "certimesh/generators/domain/curves_2.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace certimesh::generators {

namespace {

// A point of a curve with its first and second derivatives in the parameter.
struct CurvePoint {
  Point2 p;
  double dx, dy, ddx, ddy;
};
using CurveFunction = std::function<CurvePoint(double)>;

// More pieces than this is a step far too small for the curve, not a domain anyone meshes.
constexpr double kMaxPieces = 1e7;

void check_spacing(const CurveSpacing& s) {
  if (s.mode == CurveSpacing::Mode::fixed_step) {
    if (!(std::isfinite(s.step) && s.step > 0)) {
      throw std::invalid_argument("curve step must be a positive finite number, got " + std::to_string(s.step));
    }
    return;
  }
  if (!(s.tolerance > 0 && s.tolerance < 1)) {
    throw std::invalid_argument("curvature tolerance must be in (0, 1), got " + std::to_string(s.tolerance));
  }
  if (!(std::isfinite(s.max_step) && s.min_step > 0 && s.min_step <= s.max_step)) {
    throw std::invalid_argument("curvature spacing needs 0 < min_step <= max_step, finite; got " +
                                std::to_string(s.min_step) + " and " + std::to_string(s.max_step));
  }
}

// The desired chord length at a curve point (curves_2.h: sagitta <= tolerance * rho).
double desired_step(const CurvePoint& c, const CurveSpacing& s) {
  if (s.mode == CurveSpacing::Mode::fixed_step) return s.step;
  const double speed = std::hypot(c.dx, c.dy);
  const double cross = std::abs(c.dx * c.ddy - c.dy * c.ddx);
  if (cross == 0.0) return s.max_step;
  const double rho = speed * speed * speed / cross;
  const double chord = 2.0 * rho * std::sqrt(s.tolerance * (2.0 - s.tolerance));
  return std::clamp(chord, s.min_step, s.max_step);
}

// Parameters t0 = u_0 < u_1 < ... < u_N = t1 with equal budget between neighbours, N >= min_pieces.
std::vector<double> spaced_parameters(const CurveFunction& curve, double t0, double t1, const CurveSpacing& spacing,
                                      std::size_t min_pieces, std::size_t samples) {
  std::vector<double> t(samples + 1), budget(samples + 1, 0.0);
  double previous = 0.0;
  for (std::size_t k = 0; k <= samples; ++k) {
    t[k] = t0 + (t1 - t0) * static_cast<double>(k) / static_cast<double>(samples);
    const CurvePoint c = curve(t[k]);
    const double density = std::hypot(c.dx, c.dy) / desired_step(c, spacing);
    if (k > 0) budget[k] = budget[k - 1] + 0.5 * (previous + density) * (t[k] - t[k - 1]);
    previous = density;
  }
  const double total = budget[samples];
  if (!(total <= kMaxPieces)) {
    throw std::invalid_argument("curve discretization would need " + std::to_string(total) +
                                " pieces: the step is too small for the curve");
  }
  const std::size_t pieces = std::max<std::size_t>(min_pieces, static_cast<std::size_t>(std::llround(total)));
  std::vector<double> out{t0};
  std::size_t k = 0;
  for (std::size_t j = 1; j < pieces; ++j) {
    const double target = total * static_cast<double>(j) / static_cast<double>(pieces);
    while (k + 1 < samples && budget[k + 1] <= target) ++k;
    const double width = budget[k + 1] - budget[k];
    const double f = width > 0 ? (target - budget[k]) / width : 0.5;
    out.push_back(t[k] + f * (t[k + 1] - t[k]));
  }
  out.push_back(t1);
  return out;
}

CurveFunction ellipse_function(const EllipseArc& e) {
  const double cr = std::cos(e.rotation), sr = std::sin(e.rotation);
  return [e, cr, sr](double t) {
    const double ct = std::cos(t), st = std::sin(t);
    const double lx = e.semi_axis_a * ct, ly = e.semi_axis_b * st;          // position
    const double l1x = -e.semi_axis_a * st, l1y = e.semi_axis_b * ct;       // first derivative
    return CurvePoint{{e.centre.x + cr * lx - sr * ly, e.centre.y + sr * lx + cr * ly},
                      cr * l1x - sr * l1y, sr * l1x + cr * l1y,
                      -(cr * lx - sr * ly), -(sr * lx + cr * ly)};  // second derivative = -position
  };
}

bool finite(const Point2& p) { return std::isfinite(p.x) && std::isfinite(p.y); }

// The uniform Catmull-Rom span from p1 (t = 0) to p2 (t = 1), tangents from p0 and p3.
CurveFunction catmull_rom_span(Point2 p0, Point2 p1, Point2 p2, Point2 p3) {
  return [=](double t) {
    auto axis = [t](double a, double b, double c, double d) {
      const double c1 = -a + c, c2 = 2 * a - 5 * b + 4 * c - d, c3 = -a + 3 * b - 3 * c + d;
      return std::array<double, 3>{0.5 * (2 * b + t * (c1 + t * (c2 + t * c3))),
                                   0.5 * (c1 + t * (2 * c2 + 3 * t * c3)), 0.5 * (2 * c2 + 6 * t * c3)};
    };
    const auto x = axis(p0.x, p1.x, p2.x, p3.x);
    const auto y = axis(p0.y, p1.y, p2.y, p3.y);
    return CurvePoint{{x[0], y[0]}, x[1], y[1], x[2], y[2]};
  };
}

}  // namespace

Polyline2 discretize_ellipse_arc(const EllipseArc& arc, const CurveSpacing& spacing) {
  check_spacing(spacing);
  if (!(std::isfinite(arc.semi_axis_a) && std::isfinite(arc.semi_axis_b) && arc.semi_axis_a > 0 &&
        arc.semi_axis_b > 0 && finite(arc.centre) && std::isfinite(arc.rotation))) {
    throw std::invalid_argument("ellipse needs a finite centre and rotation and positive finite semi-axes");
  }
  if (!(std::isfinite(arc.start) && std::isfinite(arc.end) && arc.end > arc.start)) {
    throw std::invalid_argument("ellipse arc needs finite angles with end > start");
  }
  const bool closed = arc.end - arc.start >= 2 * std::numbers::pi;
  const double end = closed ? arc.start + 2 * std::numbers::pi : arc.end;
  const CurveFunction curve = ellipse_function(arc);
  std::vector<double> t = spaced_parameters(curve, arc.start, end, spacing, closed ? 3 : 1, 4096);
  if (closed) t.pop_back();  // the end is the start again
  Polyline2 out{{}, closed};
  for (const double u : t) out.points.push_back(curve(u).p);
  return out;
}

Polyline2 discretize_circle(Point2 centre, double radius, const CurveSpacing& spacing) {
  if (!(std::isfinite(radius) && radius > 0)) {
    throw std::invalid_argument("circle radius must be a positive finite number, got " + std::to_string(radius));
  }
  return discretize_ellipse_arc({centre, radius, radius, 0.0, 0.0, 2 * std::numbers::pi}, spacing);
}

Polyline2 circle_points(Point2 centre, double radius, std::size_t count) {
  if (count < 3) throw std::invalid_argument("a circle needs at least 3 points");
  Polyline2 out{{}, true};
  for (std::size_t k = 0; k < count; ++k) {
    const double angle = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(count);
    out.points.push_back({centre.x + radius * std::cos(angle), centre.y + radius * std::sin(angle)});
  }
  return out;
}

Polyline2 discretize_spline(const std::vector<Point2>& control, bool closed, const CurveSpacing& spacing) {
  check_spacing(spacing);
  const std::size_t n = control.size();
  if (n < (closed ? 3u : 2u)) {
    throw std::invalid_argument(std::string("a ") + (closed ? "closed spline needs 3" : "spline needs 2") +
                                " control points or more, got " + std::to_string(n));
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!finite(control[i])) throw std::invalid_argument("spline control point " + std::to_string(i) + " is not finite");
    if ((closed || i + 1 < n) && control[i] == control[(i + 1) % n]) {
      throw std::invalid_argument("spline control points " + std::to_string(i) + " and " +
                                  std::to_string((i + 1) % n) + " coincide");
    }
  }
  // Control point i, extended past an open chain's ends by reflection.
  auto at = [&](std::ptrdiff_t i) -> Point2 {
    const auto m = static_cast<std::ptrdiff_t>(n);
    if (closed) return control[static_cast<std::size_t>(((i % m) + m) % m)];
    if (i < 0) return {2 * control[0].x - control[1].x, 2 * control[0].y - control[1].y};
    if (i >= m) return {2 * control[n - 1].x - control[n - 2].x, 2 * control[n - 1].y - control[n - 2].y};
    return control[static_cast<std::size_t>(i)];
  };
  Polyline2 out{{}, closed};
  const std::size_t spans = closed ? n : n - 1;
  for (std::size_t s = 0; s < spans; ++s) {
    const auto i = static_cast<std::ptrdiff_t>(s);
    const CurveFunction span = catmull_rom_span(at(i - 1), at(i), at(i + 1), at(i + 2));
    const std::vector<double> t = spaced_parameters(span, 0.0, 1.0, spacing, 1, 512);
    out.points.push_back(control[s]);  // exactly the control point
    for (std::size_t k = 1; k + 1 < t.size(); ++k) out.points.push_back(span(t[k]).p);
  }
  if (!closed) out.points.push_back(control[n - 1]);
  return out;
}

DomainVertex add_curve(PlanarDomain& domain, const Polyline2& curve, io::Label label) {
  const std::size_t n = curve.points.size();
  if (n < (curve.closed ? 3u : 2u)) throw std::invalid_argument("a curve needs 2 points (3 when closed)");
  if (domain.points.size() + n > std::numeric_limits<DomainVertex>::max()) {
    throw std::length_error("too many domain vertices");
  }
  const auto first = static_cast<DomainVertex>(domain.points.size());
  const bool labelled = !domain.point_labels.empty();
  for (const Point2& p : curve.points) {
    domain.points.push_back(p);
    if (labelled) domain.point_labels.push_back(label);
  }
  const auto count = static_cast<DomainVertex>(n);
  for (DomainVertex i = 0; i + 1 < count; ++i) domain.segments.push_back({first + i, first + i + 1, label});
  if (curve.closed) domain.segments.push_back({first + count - 1, first, label});
  return first;
}

DomainVertex add_closed_curve(PlanarDomain& domain, const std::vector<Point2>& points, io::Label label) {
  return add_curve(domain, Polyline2{points, true}, label);
}

}  // namespace certimesh::generators
