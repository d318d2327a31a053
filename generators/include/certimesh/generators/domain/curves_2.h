// Curved boundaries as polylines: circles, ellipse arcs and splines, discretized either with a
// user step or automatically from the curvature, and added to a PlanarDomain.
//
// Spacing. A curve c(t) is sampled finely, and its points are placed so that each piece of
// curve between two consecutive points has the same "budget" integral of ds / h(s), where h is
// the desired chord length at arc length s:
//   - fixed step:   h = step everywhere (equal arc-length spacing; the count of pieces is
//                   round(length / step), so the arc between points is within a factor
//                   length/(round(length/step) * step) of the step);
//   - curvature:    h = clamp(2 rho sin(theta/2), min_step, max_step) with rho the radius of
//                   curvature and theta = 2 acos(1 - tolerance): the chord's sagitta is at most
//                   tolerance * rho, so the step is proportional to the radius of curvature.
// Every output point is the curve's formula evaluated at its parameter (on the curve up to
// rounding); the spacing only chooses the parameters. Deterministic: no randomness, a fixed
// sampling.
//
// Splines are uniform Catmull-Rom splines (they pass through their control points, which
// appear exactly in the output); an open chain's end tangents come from reflecting the
// neighbouring control point across the end one.
#pragma once

#include <cstddef>
#include <vector>

#include "certimesh/generators/domain/planar_domain.h"

namespace certimesh::generators {

struct CurveSpacing {
  enum class Mode { fixed_step, curvature };
  Mode mode = Mode::fixed_step;
  double step = 0.0;       // fixed_step: the target chord length (> 0)
  double tolerance = 0.0;  // curvature: sagitta / radius of curvature, in (0, 1)
  double min_step = 0.0;   // curvature: bounds of the chord length (0 < min_step <= max_step)
  double max_step = 0.0;

  static CurveSpacing with_step(double step) { return {Mode::fixed_step, step, 0.0, 0.0, 0.0}; }
  static CurveSpacing from_curvature(double tolerance, double min_step, double max_step) {
    return {Mode::curvature, 0.0, tolerance, min_step, max_step};
  }
};

/// A discretized curve: consecutive points joined by segments; a closed curve also joins the
/// last point to the first (which is not repeated).
struct Polyline2 {
  std::vector<Point2> points;
  bool closed = false;
};

/// The counterclockwise circle of `radius` about `centre`, starting at angle 0.
/// Throws std::invalid_argument for a non-positive or non-finite radius or bad spacing.
Polyline2 discretize_circle(Point2 centre, double radius, const CurveSpacing& spacing);

/// The circle as a regular polygon of exactly `count` (>= 3) points, starting at angle 0.
Polyline2 circle_points(Point2 centre, double radius, std::size_t count);

/// centre + R(rotation) (a cos t, b sin t) for t from `start` to `end` (radians, the parametric
/// angle, end > start). An arc of 2 pi or more is a closed ellipse.
struct EllipseArc {
  Point2 centre;
  double semi_axis_a = 1.0;
  double semi_axis_b = 1.0;
  double rotation = 0.0;
  double start = 0.0;
  double end = 0.0;
};
Polyline2 discretize_ellipse_arc(const EllipseArc& arc, const CurveSpacing& spacing);

/// The uniform Catmull-Rom spline through `control` (>= 2 points open, >= 3 closed).
Polyline2 discretize_spline(const std::vector<Point2>& control, bool closed, const CurveSpacing& spacing);

/// Appends the polyline's points and segments (all labelled `label`) to `domain`; returns the
/// id of its first vertex (the others follow consecutively).
DomainVertex add_curve(PlanarDomain& domain, const Polyline2& curve, io::Label label);

/// add_curve for a closed loop given as points (last point not repeated).
DomainVertex add_closed_curve(PlanarDomain& domain, const std::vector<Point2>& points, io::Label label);

}  // namespace certimesh::generators
