// Curve discretization: points on the curve up to rounding, chords close to the step, more
// points where the curvature is high, control points kept, closed curves not repeating their
// first point, determinism, and refusals of bad parameters.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "certimesh/generators/domain/curves_2.h"
#include "certimesh/generators/domain/domain_validation.h"

namespace certimesh::generators {
namespace {

constexpr double kEps = std::numeric_limits<double>::epsilon();

double distance(const Point2& p, const Point2& q) { return std::hypot(p.x - q.x, p.y - q.y); }

std::vector<double> chords(const Polyline2& c) {
  std::vector<double> out;
  const std::size_t n = c.points.size();
  for (std::size_t i = 0; i + 1 < n; ++i) out.push_back(distance(c.points[i], c.points[i + 1]));
  if (c.closed) out.push_back(distance(c.points[n - 1], c.points[0]));
  return out;
}

TEST(dom_Curves, CircleWithAStep) {
  const Point2 centre{3, -2};
  const double r = 2.5, step = 0.1;
  const Polyline2 c = discretize_circle(centre, r, CurveSpacing::with_step(step));
  EXPECT_TRUE(c.closed);
  // N = round(2 pi r / step) equal arcs.
  EXPECT_EQ(c.points.size(), static_cast<std::size_t>(std::llround(2 * std::numbers::pi * r / step)));
  EXPECT_NE(c.points.front(), c.points.back());
  for (const Point2& p : c.points) EXPECT_LE(std::abs(distance(p, centre) - r), 8 * kEps * (r + 3)) << p.x << " " << p.y;
  for (const double chord : chords(c)) {
    EXPECT_NEAR(chord, step, 0.01 * step);  // arc/step within 0.1 %, chord/arc within 0.02 %
  }
  EXPECT_EQ(c.points, discretize_circle(centre, r, CurveSpacing::with_step(step)).points);  // deterministic
}

TEST(dom_Curves, CircleIsCounterclockwise) {
  const Polyline2 c = circle_points({0, 0}, 1, 12);
  double twice_area = 0;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const Point2& p = c.points[i];
    const Point2& q = c.points[(i + 1) % c.points.size()];
    twice_area += p.x * q.y - p.y * q.x;
  }
  EXPECT_GT(twice_area, 0);
  EXPECT_NEAR(twice_area / 2, 3.0, 1e-12);  // the regular 12-gon in the unit circle has area 3
}

// The ellipse point in the ellipse's own frame: (x/a)^2 + (y/b)^2 = 1 up to rounding.
double ellipse_residual(const EllipseArc& e, const Point2& p) {
  const double dx = p.x - e.centre.x, dy = p.y - e.centre.y;
  const double u = std::cos(e.rotation) * dx + std::sin(e.rotation) * dy;
  const double v = -std::sin(e.rotation) * dx + std::cos(e.rotation) * dy;
  return (u / e.semi_axis_a) * (u / e.semi_axis_a) + (v / e.semi_axis_b) * (v / e.semi_axis_b) - 1;
}

TEST(dom_Curves, EllipseArcEndsAtItsAnglesAndStaysOnTheEllipse) {
  const EllipseArc e{{1, 2}, 3, 1, 0.5, 0.25, 2.0};
  const Polyline2 c = discretize_ellipse_arc(e, CurveSpacing::with_step(0.05));
  EXPECT_FALSE(c.closed);
  for (const Point2& p : c.points) EXPECT_LE(std::abs(ellipse_residual(e, p)), 32 * kEps);
  const auto at = [&](double t) {
    const double x = e.semi_axis_a * std::cos(t), y = e.semi_axis_b * std::sin(t);
    return Point2{e.centre.x + std::cos(e.rotation) * x - std::sin(e.rotation) * y,
                  e.centre.y + std::sin(e.rotation) * x + std::cos(e.rotation) * y};
  };
  EXPECT_LE(distance(c.points.front(), at(0.25)), 1e-14);
  EXPECT_LE(distance(c.points.back(), at(2.0)), 1e-14);
  for (const double chord : chords(c)) EXPECT_NEAR(chord, 0.05, 0.005);
}

TEST(dom_Curves, CurvatureModePutsMorePointsWhereTheCurveBends) {
  // a = 4, b = 1: radius of curvature b^2/a = 0.25 at (+-4, 0), a^2/b = 16 at (0, +-1).
  const EllipseArc e{{0, 0}, 4, 1, 0, 0, 2 * std::numbers::pi};
  const double tolerance = 0.01;
  const Polyline2 c = discretize_ellipse_arc(e, CurveSpacing::from_curvature(tolerance, 1e-3, 1.0));
  EXPECT_TRUE(c.closed);
  const double factor = 2 * std::sqrt(tolerance * (2 - tolerance));  // chord = factor * rho
  const std::vector<double> h = chords(c);
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    const Point2& p = c.points[i];
    if (std::abs(p.x) > 3.99) {  // the sharp ends: rho between 0.25 and 0.28 there
      EXPECT_GT(h[i], 0.9 * factor * 0.25) << p.x;
      EXPECT_LT(h[i], 1.25 * factor * 0.25) << p.x;
    }
    if (std::abs(p.x) < 0.5) {
      EXPECT_NEAR(h[i], 1.0, 0.1) << p.x;  // flat sides: max_step
    }
  }
  const std::size_t near_ends = static_cast<std::size_t>(
      std::count_if(c.points.begin(), c.points.end(), [](const Point2& p) { return std::abs(p.x) > 3.5; }));
  const std::size_t near_sides = static_cast<std::size_t>(
      std::count_if(c.points.begin(), c.points.end(), [](const Point2& p) { return std::abs(p.x) < 0.5; }));
  EXPECT_GT(near_ends, 4 * near_sides);  // equal x-widths (1), far more points at the ends
}

TEST(dom_Curves, SplinePassesThroughItsControlPoints) {
  const std::vector<Point2> control{{0, 0}, {2, 0}, {2, 1}, {1, 2}, {0, 1}};
  for (const bool closed : {false, true}) {
    const Polyline2 c = discretize_spline(control, closed, CurveSpacing::with_step(0.1));
    EXPECT_EQ(c.closed, closed);
    for (const Point2& q : control) {
      EXPECT_NE(std::find(c.points.begin(), c.points.end(), q), c.points.end()) << q.x << " " << q.y;
    }
    EXPECT_EQ(c.points.front(), control.front());
    if (!closed) {
      EXPECT_EQ(c.points.back(), control.back());
    }
    for (const double chord : chords(c)) EXPECT_NEAR(chord, 0.1, 0.03);
    // A closed loop through these points does not cross itself: a valid domain boundary.
    if (closed) {
      PlanarDomain d;
      add_curve(d, c, 1);
      EXPECT_TRUE(validate_domain(d).empty());
    }
  }
}

TEST(dom_Curves, SplineOfCollinearControlPointsIsTheSegment) {
  // Uniform Catmull-Rom through equally spaced collinear points is the straight line.
  const Polyline2 c = discretize_spline({{0, 0}, {1, 0}, {2, 0}, {3, 0}}, false, CurveSpacing::with_step(0.25));
  EXPECT_EQ(c.points.size(), 13u);
  for (const Point2& p : c.points) EXPECT_EQ(p.y, 0.0);
  for (std::size_t i = 1; i < c.points.size(); ++i) EXPECT_GT(c.points[i].x, c.points[i - 1].x);
}

TEST(dom_Curves, AddCurveAppendsAChainOrALoop) {
  PlanarDomain d;
  d.points = {{9, 9}};
  const DomainVertex first = add_closed_curve(d, {{0, 0}, {1, 0}, {0, 1}}, 5);
  EXPECT_EQ(first, 1u);
  ASSERT_EQ(d.segments.size(), 3u);
  EXPECT_EQ(d.segments[2], (DomainSegment{3, 1, 5}));
  add_curve(d, Polyline2{{{5, 5}, {6, 5}, {7, 6}}, false}, 2);
  EXPECT_EQ(d.segments.size(), 5u);
  EXPECT_EQ(d.segments.back(), (DomainSegment{5, 6, 2}));
}

TEST(dom_Curves, BadParametersAreRefused) {
  EXPECT_THROW(discretize_circle({0, 0}, -1, CurveSpacing::with_step(0.1)), std::invalid_argument);
  EXPECT_THROW(discretize_circle({0, 0}, 1, CurveSpacing::with_step(0)), std::invalid_argument);
  EXPECT_THROW(discretize_circle({0, 0}, 1, CurveSpacing::with_step(1e-9)), std::invalid_argument);  // 6e9 pieces
  EXPECT_THROW(discretize_circle({0, 0}, 1, CurveSpacing::from_curvature(1.5, 0.1, 1)), std::invalid_argument);
  EXPECT_THROW(discretize_circle({0, 0}, 1, CurveSpacing::from_curvature(0.1, 1, 0.1)), std::invalid_argument);
  EXPECT_THROW(discretize_spline({{0, 0}, {0, 0}, {1, 1}}, false, CurveSpacing::with_step(0.1)), std::invalid_argument);
  EXPECT_THROW(discretize_ellipse_arc({{0, 0}, 1, 1, 0, 1, 1}, CurveSpacing::with_step(0.1)), std::invalid_argument);
}

}  // namespace
}  // namespace certimesh::generators
