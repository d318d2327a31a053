// Algorithm 32: node shift (local_modifications_2.h).
//
// The worst quality of the star, Q_σ(x), is maximised along one forward-difference gradient
// direction (the monograph does one direction and one 1-D search per call, not an iteration:
// the neighbours keep moving anyway). Along a ray each triangle's shape quality |S|/P² is
// quasi-concave in the step (|S| is affine and positive inside the kernel, P² convex), so the
// minimum over the star is quasi-concave too and a golden-section search finds its maximum;
// with the size-aware quality it is a good heuristic. Every trial point is checked exactly:
// all star triangles strictly counterclockwise (the kernel of the star, digest D §2.1).
// A boundary Steiner vertex, given the input segments, slides along its segment instead
// (boundary_slide_2.cpp); every other trace vertex stays.
#include <algorithm>
#include <cmath>
#include <limits>
#include <tuple>
#include <utility>

#include "golden_section_search.h"
#include "input_segment_run_2.h"
#include "local_geometry_2.h"

namespace certimesh::topology {

namespace {

constexpr double sqrt_epsilon = 1.4901161193847656e-08;  // √ε_mach = 2^-26
constexpr double invalid_shift_quality = -1.0;

class StarAtPosition {
 public:
  StarAtPosition(const TriangleMesh2& mesh, VertexId v, const local::OrderedStar2& star,
                 const LocalModificationOptions2& options)
      : options_(options) {
    for (const ElementId e : star.elements) {
      triangles_.push_back(local::virtual_triangle(mesh, mesh.vertices(e), mesh.label(e)));
      moving_.push_back(static_cast<std::size_t>(local::local_index(mesh, e, v)));
    }
  }

  /// Q_σ with v at x, without the validity check (for the finite differences).
  double raw_quality(const Point2d& x) {
    double q = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < triangles_.size(); ++k) {
      triangles_[k].points[moving_[k]] = x;
      q = std::min(q, local::quality_of(triangles_[k], options_));
    }
    return q;
  }

  /// Q_σ with v at x, or `invalid_shift_quality` when some star triangle is not strictly counterclockwise.
  double quality(const Point2d& x) {
    if (!std::isfinite(x[0]) || !std::isfinite(x[1])) return invalid_shift_quality;
    const double q = raw_quality(x);
    for (const auto& t : triangles_)
      if (!local::is_positive(t)) return invalid_shift_quality;
    return q;
  }

  /// The largest step along g before some triangle's (affine) area reaches zero, estimated in
  /// double: only a bound for the search, whose every point is checked exactly.
  double step_bound(const Point2d& x, const Point2d& g) {
    double bound = std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < triangles_.size(); ++k) {
      const double at_0 = twice_area(k, x);
      const double at_1 = twice_area(k, {x[0] + g[0], x[1] + g[1]});
      const double slope = at_1 - at_0;
      if (slope < 0.0) bound = std::min(bound, at_0 / -slope);
    }
    return bound;
  }

 private:
  double twice_area(std::size_t k, const Point2d& x) {
    auto& p = triangles_[k].points;
    p[moving_[k]] = x;
    return (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[2][0] - p[0][0]) * (p[1][1] - p[0][1]);
  }

  const LocalModificationOptions2& options_;
  std::vector<local::VirtualTriangle> triangles_;
  std::vector<std::size_t> moving_;
};

double distance_2d(const Point2d& p, const Point2d& q) { return std::hypot(q[0] - p[0], q[1] - p[1]); }

// The finite-difference increment (5.2.2): √ε_mach relative to the star's shortest edge (the
// monograph's absolute √ε is not scale-invariant), at most 1 % of that edge, and large enough
// to change the coordinate.
double difference_step(const TriangleMesh2& mesh, VertexId v, const local::OrderedStar2& star) {
  const Point2d p = mesh.point(v);
  double shortest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < star.link.size(); ++k) {
    const Point2d a = mesh.point(star.link[k]);
    shortest = std::min({shortest, distance_2d(p, a),
                         distance_2d(a, mesh.point(star.link[(k + 1) % star.link.size()]))});
  }
  const double magnitude = std::max(std::abs(p[0]), std::abs(p[1]));
  return std::min(std::max(sqrt_epsilon * shortest, 0x1p-40 * magnitude), shortest / 100.0);
}

// The best valid step along `direction` by golden-section search in [0, tau_max): the step
// and Q_σ there (step 0 and q0 when nothing beats q0).
std::pair<double, double> search_along(StarAtPosition& at, const Point2d& p, const Point2d& direction, double q0) {
  const double tau_max = at.step_bound(p, direction);
  if (!(tau_max > 0.0) || !std::isfinite(tau_max)) return {0.0, q0};
  const auto position = [&](double tau) { return Point2d{p[0] + tau * direction[0], p[1] + tau * direction[1]}; };
  return local::golden_section_best([&](double tau) { return at.quality(position(tau)); }, 0.0, tau_max, q0, 0.0);
}

bool usable(const Point2d& g) {
  return (g[0] != 0.0 || g[1] != 0.0) && std::isfinite(g[0]) && std::isfinite(g[1]);
}

}  // namespace

std::optional<LocalChange2> try_node_shift(TriangleMesh2& mesh, VertexId v,
                                           const LocalModificationOptions2& options) {
  if (is_trace_vertex(mesh, v)) {
    if (options.input_segments) return local::slide_along_segment(mesh, v, options);
    return std::nullopt;
  }
  const auto star = local::ordered_star(mesh, v);
  StarAtPosition at(mesh, v, *star, options);
  const Point2d p = mesh.point(v);
  const double q0 = at.quality(p);
  if (q0 == invalid_shift_quality) return std::nullopt;
  const double delta = difference_step(mesh, v, *star);
  const auto q = [&](double dx, double dy) { return at.raw_quality({p[0] + dx, p[1] + dy}); };
  // The monograph's forward differences (5.2.2) first. Where the two worst triangles trade
  // places (a kink of the min, e.g. a star symmetric about v), the forward difference can point
  // where the min falls; the central difference then gives the ascent direction.
  const Point2d forward{(q(delta, 0) - q0) / delta, (q(0, delta) - q0) / delta};
  Point2d direction = forward;
  auto [tau, q1] = usable(forward) ? search_along(at, p, forward, q0) : std::pair{0.0, q0};
  if (!(q1 > q0 + options.minimum_shift_gain)) {
    const Point2d central{(q(delta, 0) - q(-delta, 0)) / (2 * delta), (q(0, delta) - q(0, -delta)) / (2 * delta)};
    if (!usable(central)) return std::nullopt;
    direction = central;
    std::tie(tau, q1) = search_along(at, p, central, q0);
  }
  if (!(q1 > q0 + options.minimum_shift_gain)) return std::nullopt;
  const Point2d target{p[0] + tau * direction[0], p[1] + tau * direction[1]};
  if (target == p) return std::nullopt;
  mesh.move_vertex(v, target);
  return LocalChange2{star->elements, star->elements};
}

}  // namespace certimesh::topology
