#include "area_bound.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <memory>
#include <unordered_map>

#include "certimesh/generators/delaunay/constrained_delaunay_2.h"
#include "certimesh/predicates/orient2d.h"
#include "point_on_segment.h"

namespace certimesh::generators::detail {

namespace {

using Triangle = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kNoTriangle = UINT32_MAX;

std::uint64_t undirected_side_key(std::uint32_t a, std::uint32_t b) {
  if (a > b) std::swap(a, b);
  return (static_cast<std::uint64_t>(a) << 32) | b;
}

double squared_length(const Point2& p, const Point2& q) { return (p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y); }

// The fraction of p along segment (a, b), clamped to [0, 1].
double fraction_along(const Point2& a, const Point2& b, const Point2& p) {
  const double f = ((p.x - a.x) * (b.x - a.x) + (p.y - a.y) * (b.y - a.y)) / squared_length(a, b);
  return std::clamp(f, 0.0, 1.0);
}

class Bisection {
 public:
  Bisection(TriangleSoup& m, DiscretizedBoundary& boundary, const PlanarDomain& domain, std::span<const double> max_area)
      : m_(m), boundary_(boundary), domain_(domain), max_area_(max_area) {
    for (std::uint32_t t = 0; t < m.triangles.size(); ++t) link(t);
    for (std::uint32_t s = 0; s < boundary.subsegments.size(); ++s)
      subsegment_.emplace(undirected_side_key(boundary.subsegments[s].a, boundary.subsegments[s].b), s);
  }

  std::uint64_t run() {
    std::vector<std::uint32_t> work;
    for (std::uint32_t t = static_cast<std::uint32_t>(m_.triangles.size()); t-- > 0;) work.push_back(t);
    std::uint64_t splits = 0;
    while (!work.empty()) {
      const std::uint32_t t = work.back();
      work.pop_back();
      if (!too_large(t)) continue;
      for (const std::uint32_t c : split(t)) work.push_back(c);
      ++splits;
    }
    return splits;
  }

 private:
  bool too_large(std::uint32_t t) const {
    const io::Label l = m_.labels[t];
    if (l < 0 || static_cast<std::size_t>(l) >= max_area_.size() || !(max_area_[static_cast<std::size_t>(l)] > 0)) return false;
    const Triangle& v = m_.triangles[t];
    return !area_within(m_.points[v[0]], m_.points[v[1]], m_.points[v[2]], max_area_[static_cast<std::size_t>(l)]);
  }
  std::array<std::uint32_t, 2>& sides(std::uint64_t key) { return sides_.try_emplace(key, std::array{kNoTriangle, kNoTriangle}).first->second; }
  void link(std::uint32_t t) {
    for (int i = 0; i < 3; ++i) {
      auto& slot = sides(undirected_side_key(m_.triangles[t][static_cast<std::size_t>(i)], m_.triangles[t][static_cast<std::size_t>((i + 1) % 3)]));
      if (slot[0] == kNoTriangle || slot[0] == t) slot[0] = t; else slot[1] = t;
    }
  }
  void unlink(std::uint32_t t) {
    for (int i = 0; i < 3; ++i) {
      auto& slot = sides(undirected_side_key(m_.triangles[t][static_cast<std::size_t>(i)], m_.triangles[t][static_cast<std::size_t>((i + 1) % 3)]));
      if (slot[0] == t) slot[0] = slot[1];
      slot[1] = kNoTriangle;
    }
  }
  // The new point on edge (u, v): on its input segment for a boundary or cut edge.
  std::uint32_t new_point(std::uint32_t u, std::uint32_t v) {
    Point2 p{(m_.points[u].x + m_.points[v].x) / 2, (m_.points[u].y + m_.points[v].y) / 2};
    const auto found = subsegment_.find(undirected_side_key(u, v));
    if (found != subsegment_.end()) {
      const DomainSegment& input = domain_.segments[boundary_.origin[found->second]];
      const Point2 a = domain_.points[input.a], b = domain_.points[input.b];
      p = point_on_segment(a, b, (fraction_along(a, b, m_.points[u]) + fraction_along(a, b, m_.points[v])) / 2);
    }
    if (p == m_.points[u] || p == m_.points[v]) throw std::runtime_error("a triangle above its maximum area is too small to bisect");
    const auto id = static_cast<std::uint32_t>(m_.points.size());
    m_.points.push_back(p);
    if (found != subsegment_.end()) {  // (a, b) becomes (a, id), (id, b), in its direction
      const std::uint32_t first = found->second;
      subsegment_.erase(found);
      DomainSegment& s = boundary_.subsegments[first];
      const DomainSegment second{id, s.b, s.label};
      s.b = id;
      subsegment_.emplace(undirected_side_key(s.a, s.b), first);
      subsegment_.emplace(undirected_side_key(second.a, second.b), static_cast<std::uint32_t>(boundary_.subsegments.size()));
      boundary_.origin.push_back(boundary_.origin[first]);
      boundary_.subsegments.push_back(second);
    }
    return id;
  }
  // Triangle t = (u, v, w) split at point p of edge (u, v) into (u, p, w) and (p, v, w).
  std::vector<std::uint32_t> halve(std::uint32_t t, std::uint32_t u, std::uint32_t v, std::uint32_t w, std::uint32_t p) {
    unlink(t);
    const io::Label label = m_.labels[t];
    m_.triangles[t] = {u, p, w};
    const auto other = static_cast<std::uint32_t>(m_.triangles.size());
    m_.triangles.push_back({p, v, w});
    m_.labels.push_back(label);
    for (const std::uint32_t c : {t, other}) {
      const Triangle& x = m_.triangles[c];
      if (predicates::orient2d(m_.points[x[0]], m_.points[x[1]], m_.points[x[2]]) != predicates::Sign::positive)
        throw std::runtime_error("bisecting a triangle above its maximum area would invert a neighbour");
      link(c);
    }
    return {t, other};
  }
  std::vector<std::uint32_t> split(std::uint32_t t) {
    const Triangle v = m_.triangles[t];
    int longest = 0;  // edge (v[i], v[i+1])
    for (int i = 1; i < 3; ++i)
      if (squared_length(m_.points[v[static_cast<std::size_t>(i)]], m_.points[v[static_cast<std::size_t>((i + 1) % 3)]]) >
          squared_length(m_.points[v[static_cast<std::size_t>(longest)]], m_.points[v[static_cast<std::size_t>((longest + 1) % 3)]]))
        longest = i;
    const std::uint32_t a = v[static_cast<std::size_t>(longest)], b = v[static_cast<std::size_t>((longest + 1) % 3)],
                        c = v[static_cast<std::size_t>((longest + 2) % 3)];
    const auto& slot = sides_.at(undirected_side_key(a, b));
    const std::uint32_t across = slot[0] == t ? slot[1] : slot[0];
    const std::uint32_t p = new_point(a, b);
    std::vector<std::uint32_t> out = halve(t, a, b, c, p);
    if (across != kNoTriangle) {
      const Triangle n = m_.triangles[across];
      int i = 0;
      while (!(n[static_cast<std::size_t>(i)] == b && n[static_cast<std::size_t>((i + 1) % 3)] == a)) ++i;
      const std::vector<std::uint32_t> more = halve(across, b, a, n[static_cast<std::size_t>((i + 2) % 3)], p);
      out.insert(out.end(), more.begin(), more.end());
    }
    return out;
  }

  TriangleSoup& m_;
  DiscretizedBoundary& boundary_;
  const PlanarDomain& domain_;
  std::span<const double> max_area_;
  // Looked up only, never iterated: the order of the hash maps decides nothing.
  std::unordered_map<std::uint64_t, std::array<std::uint32_t, 2>> sides_;
  std::unordered_map<std::uint64_t, std::uint32_t> subsegment_;
};

}  // namespace

namespace {

// Point -> region by a walk from the last answer (the generators query nearby points in turn).
struct RegionLocator {
  ConstrainedDelaunay2 cdt;
  std::vector<int> labels;
  ConstrainedDelaunay2::TriangleId hint = ConstrainedDelaunay2::none;
  explicit RegionLocator(const PlanarDomain& d) : cdt(d.points) {
    for (const DomainSegment& s : d.segments) cdt.insert_constraint(s.a, s.b);
    labels = cdt.classify(d.holes, d.regions);
  }
  int region_at(const Point2& p) {
    hint = cdt.locate(p, hint);
    if (hint == ConstrainedDelaunay2::none || cdt.is_ghost(hint)) {
      hint = ConstrainedDelaunay2::none;
      return -1;
    }
    return labels[hint];
  }
};

}  // namespace

SizePolicy size_for_max_areas(const SizePolicy& size, const PlanarDomain& domain, std::span<const double> max_area) {
  if (std::none_of(max_area.begin(), max_area.end(), [](double a) { return a > 0; })) return size;
  double longest = 0.0;
  for (const DomainSegment& s : domain.segments) longest = std::max(longest, std::sqrt(squared_length(domain.points[s.a], domain.points[s.b])));
  std::vector<double> side(max_area.size(), 0.0);  // 0: no bound
  constexpr double kEquilateralSide = 1.5196713713031850;  // sqrt(4 / sqrt(3)): side of area 1
  for (std::size_t r = 0; r < max_area.size(); ++r) side[r] = max_area[r] > 0 ? 0.8 * kEquilateralSide * std::sqrt(max_area[r]) : 0.0;
  // Automatic mode outside the bounded regions: twice their largest side (a step the front and
  // the refinement grade across smoothly), at most the longest segment.
  const double unbounded = std::min(longest, 2 * *std::max_element(side.begin(), side.end()));
  auto locator = std::make_shared<RegionLocator>(domain);
  SizePolicy out = size;
  out.size_function = [base = size, unbounded, side = std::move(side), locator](const Point2& p) {
    const double elsewhere = base.automatic() ? unbounded : base.at(p);
    const int r = locator->region_at(p);
    const double bound = r >= 0 && static_cast<std::size_t>(r) < side.size() ? side[static_cast<std::size_t>(r)] : 0.0;
    return bound > 0 ? std::min(elsewhere, bound) : elsewhere;
  };
  return out;
}

bool area_within(const Point2& a, const Point2& b, const Point2& c, double bound) {
  const double left = (a.x - c.x) * (b.y - c.y), right = (a.y - c.y) * (b.x - c.x);
  const double twice = std::abs(left - right);
  // Shewchuk's bound for the determinant (ccwerrboundA, 3.33e-16), taken as 1e-15.
  const double error = 1e-15 * (std::abs(left) + std::abs(right));
  return twice + error <= 2 * bound * (1 - 1e-12);
}

std::uint64_t enforce_max_areas(TriangleSoup& mesh, DiscretizedBoundary& boundary, const PlanarDomain& domain,
                                std::span<const double> max_area) {
  if (std::none_of(max_area.begin(), max_area.end(), [](double a) { return a > 0; })) return 0;
  return Bisection(mesh, boundary, domain, max_area).run();
}

}  // namespace certimesh::generators::detail
