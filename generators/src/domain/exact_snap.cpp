#include "exact_snap.h"

#include <gmp.h>
#include <mpfr.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace certimesh::generators::detail {

namespace {

// A GMP rational with value semantics, enough for one line intersection.
class Rational {
 public:
  explicit Rational(double d = 0.0) {
    mpq_init(v_);
    mpq_set_d(v_, d);
  }
  Rational(const Rational& o) {
    mpq_init(v_);
    mpq_set(v_, o.v_);
  }
  Rational& operator=(const Rational& o) {
    mpq_set(v_, o.v_);
    return *this;
  }
  ~Rational() { mpq_clear(v_); }
  friend Rational operator-(const Rational& a, const Rational& b) { return apply(mpq_sub, a, b); }
  friend Rational operator+(const Rational& a, const Rational& b) { return apply(mpq_add, a, b); }
  friend Rational operator*(const Rational& a, const Rational& b) { return apply(mpq_mul, a, b); }
  friend Rational operator/(const Rational& a, const Rational& b) { return apply(mpq_div, a, b); }
  bool is_zero() const { return mpq_sgn(v_) == 0; }
  // Rounded to the nearest double (MPFR, one rounding).
  double nearest() const {
    mpfr_t f;
    mpfr_init2(f, std::numeric_limits<double>::digits);
    mpfr_set_q(f, v_, MPFR_RNDN);
    const double d = mpfr_get_d(f, MPFR_RNDN);
    mpfr_clear(f);
    return d;
  }

 private:
  static Rational apply(void (*op)(mpq_ptr, mpq_srcptr, mpq_srcptr), const Rational& a, const Rational& b) {
    Rational r;
    op(r.v_, a.v_, b.v_);
    return r;
  }
  mpq_t v_;
};

double max_distance(const Point2& p, const Point2& q) { return std::max(std::abs(p.x - q.x), std::abs(p.y - q.y)); }

// The intersection of the lines through (a, b) and (c, d), rounded; false when parallel.
bool line_crossing(const Point2& a, const Point2& b, const Point2& c, const Point2& d, Point2& out) {
  const Rational ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y), dx(d.x), dy(d.y);
  const Rational ux = bx - ax, uy = by - ay, vx = dx - cx, vy = dy - cy;
  const Rational det = ux * vy - uy * vx;
  if (det.is_zero()) return false;
  const Rational t = ((cx - ax) * vy - (cy - ay) * vx) / det;
  out = {(ax + t * ux).nearest(), (ay + t * uy).nearest()};
  return true;
}

bool near_box(const Point2& p, const Point2& a, const Point2& b, double distance) {
  return p.x >= std::min(a.x, b.x) - distance && p.x <= std::max(a.x, b.x) + distance &&
         p.y >= std::min(a.y, b.y) - distance && p.y <= std::max(a.y, b.y) + distance;
}

}  // namespace

ExactSnap::ExactSnap(std::initializer_list<const Region2*> operands) {
  auto add_ring = [&](const std::vector<Point2>& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      vertices_.push_back(ring[i]);
      edges_.push_back({ring[i], ring[(i + 1) % ring.size()]});
    }
  };
  for (const Region2* region : operands) {
    for (const PolygonWithHoles2& polygon : region->polygons) {
      add_ring(polygon.outer);
      for (const auto& inner : polygon.inners) add_ring(inner);
    }
  }
  std::sort(vertices_.begin(), vertices_.end(), [](const Point2& p, const Point2& q) { return p.x < q.x || (p.x == q.x && p.y < q.y); });
  // Boost's grid has ~10^7 cells across the operands' bounding box (its size, not the
  // coordinates' magnitude); a few cells of slack.
  double xmin = 0, xmax = 0, ymin = 0, ymax = 0;
  for (std::size_t i = 0; i < vertices_.size(); ++i) {
    const Point2& p = vertices_[i];
    xmin = i == 0 ? p.x : std::min(xmin, p.x);
    xmax = i == 0 ? p.x : std::max(xmax, p.x);
    ymin = i == 0 ? p.y : std::min(ymin, p.y);
    ymax = i == 0 ? p.y : std::max(ymax, p.y);
  }
  distance_ = 4e-7 * std::max(xmax - xmin, ymax - ymin);
}

bool ExactSnap::nearest_vertex(const Point2& p, Point2& out) const {
  auto it = std::lower_bound(vertices_.begin(), vertices_.end(), p.x - distance_,
                             [](const Point2& v, double x) { return v.x < x; });
  double best = std::numeric_limits<double>::infinity();
  for (; it != vertices_.end() && it->x <= p.x + distance_; ++it) {
    const double d = max_distance(*it, p);
    if (d <= distance_ && d < best) {
      best = d;
      out = *it;
    }
  }
  return best <= distance_;
}

bool ExactSnap::nearest_crossing(const Point2& p, Point2& out) const {
  std::vector<std::size_t> near;
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    if (near_box(p, edges_[e].first, edges_[e].second, distance_)) near.push_back(e);
  }
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < near.size(); ++i) {
    for (std::size_t j = i + 1; j < near.size(); ++j) {
      const auto& [a, b] = edges_[near[i]];
      const auto& [c, d] = edges_[near[j]];
      Point2 q;
      if (!line_crossing(a, b, c, d, q)) continue;
      const double dist = max_distance(p, q);
      if (dist <= distance_ && dist < best) {
        best = dist;
        out = q;
      }
    }
  }
  return best <= distance_;
}

// The nearer of the nearest operand vertex and the nearest edge crossing: Boost returns
// operand vertices unmoved (distance 0), so a vertex wins whenever the point is one.
Point2 ExactSnap::snap(const Point2& p) const {
  Point2 vertex, crossing;
  const bool has_vertex = nearest_vertex(p, vertex);
  if (has_vertex && vertex == p) return p;
  const bool has_crossing = nearest_crossing(p, crossing);
  if (has_vertex && has_crossing) return max_distance(p, vertex) <= max_distance(p, crossing) ? vertex : crossing;
  if (has_vertex) return vertex;
  if (has_crossing) return crossing;
  return p;  // nothing exact nearby: Boost's point, validated later like every other
}

void ExactSnap::apply(std::vector<Point2>& ring) const {
  // Snapping may merge neighbours (x, x -> x) or fold a sliver into a spike (x, y, x -> x).
  std::vector<Point2> out;
  auto push = [&out](const Point2& q) {
    if (!out.empty() && out.back() == q) return;
    if (out.size() >= 2 && out[out.size() - 2] == q) {
      out.pop_back();
      return;
    }
    out.push_back(q);
  };
  for (const Point2& p : ring) push(snap(p));
  // The same folds across the ring's start.
  bool changed = true;
  while (changed && out.size() >= 3) {
    changed = false;
    const std::size_t n = out.size();
    if (out.front() == out.back()) {
      out.pop_back();
      changed = true;
    } else if (out[n - 2] == out.front()) {  // ..., x, y | x, ...
      out.pop_back();
      out.pop_back();
      changed = true;
    } else if (out[n - 1] == out[1]) {  // ..., y | x, y, ...
      out.pop_back();
      out.erase(out.begin());
      changed = true;
    }
  }
  ring = out.size() >= 3 ? std::move(out) : std::vector<Point2>{};
}

}  // namespace certimesh::generators::detail
