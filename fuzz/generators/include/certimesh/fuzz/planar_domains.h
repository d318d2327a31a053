// Generated planar domains (PSLGs) for the property tests of the 2D generators: valid ones of
// several families, and invalid ones made from a valid one by exactly one mutation, each with
// the problem kind a validator must report and the ids it must name.
//
// The builders are plain functions of (family, seed, size, scale) so that any test -- or a
// benchmark -- can rebuild a case; the RapidCheck generators at the end draw those parameters
// (shrinking towards small sizes and scale 1). Bulk randomness (radii, perturbations) comes from
// std::mt19937_64 seeded with the drawn seed: deterministic and documented.
//
// Exactness. Where a case claims a degeneracy ("vertex exactly on a segment", "collinear
// overlap", "cocircular") the coordinates make it exact: integers, dyadic fractions, exact
// halvings p/2, p/4 of a point p (collinear with p and the origin in exact arithmetic), and
// scaling by powers of two (exact away from overflow and underflow). Where coordinates are
// rounded (the star polygons' cos/sin), validity rests on a margin far above the rounding
// (the angular gaps of the star), and the tests re-check small cases with an independent
// O(n^2) rational oracle.
#pragma once

#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <ostream>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "certimesh/generators/domain/domain_problem.h"
#include "certimesh/generators/domain/planar_domain.h"

namespace certimesh::fuzz {

using generators::DomainProblemKind;
using generators::DomainSegment;
using generators::DomainVertex;
using generators::PlanarDomain;
using generators::Point2;

struct PlanarDomainCase {
  PlanarDomain domain;
  std::string description;               // family, mutation, size, scale, seed
  bool valid = true;
  DomainProblemKind expected{};          // invalid only: the kind a validator must report
  std::vector<std::uint32_t> segments;   // invalid only: segment ids the report must name
  std::vector<std::uint32_t> vertices;   // invalid only: vertex ids the report must name
};

enum class DomainFamily {
  star_polygon,     // random radii around the origin; simple because star-shaped
  comb,             // N rectangular teeth (integer coordinates): the perimeter grows with N
  nested_squares,   // concentric squares, alternately hole and island, with hole points
  near_collinear,   // a chain of vertices within 2^-40 of a line, some exactly on it
  cocircular,       // lattice points of one circle, with a hole of lattice points of another
  tiny_angles,      // a fan of internal cuts from the origin meeting at angles ~2^-k
  star_with_crack,  // a star polygon with a radial internal cut (p/2 -- p)
};
inline constexpr int kDomainFamilies = 7;

enum class DomainMutation {
  crossing_segment,     // a new segment properly crossing one boundary edge
  collinear_overlap,    // two new collinear segments on a ray, overlapping exactly
  duplicate_vertex,     // one end of an edge re-pointed to a new vertex at the same point
  zero_length_segment,  // a segment from a vertex to itself
  vertex_on_segment,    // a new segment through an existing vertex (exactly)
  duplicate_segment,    // an edge listed twice
  isolated_vertex,      // a vertex on no segment, outside everything (valid since issue 12: dropped)
  open_loop,            // one boundary edge removed (open_boundary: not validate_domain's)
  nan_coordinate,       // a vertex coordinate set to NaN
};
inline constexpr int kDomainMutations = 9;

namespace planar_detail {

inline DomainVertex add_point(PlanarDomain& d, Point2 p) {
  d.points.push_back(p);
  return static_cast<DomainVertex>(d.points.size() - 1);
}

inline std::uint32_t add_segment(PlanarDomain& d, DomainVertex a, DomainVertex b, int label = 1) {
  d.segments.push_back({a, b, label});
  return static_cast<std::uint32_t>(d.segments.size() - 1);
}

inline void add_loop(PlanarDomain& d, const std::vector<Point2>& ring, int label) {
  const auto first = static_cast<DomainVertex>(d.points.size());
  for (const Point2& p : ring) add_point(d, p);
  const auto n = static_cast<DomainVertex>(ring.size());
  for (DomainVertex i = 0; i < n; ++i) add_segment(d, first + i, first + (i + 1) % n, label);
}

// Star polygon around the origin: angles 2 pi k / n, radii in [0.5, 1]. Consecutive rounded
// points keep their angular order (gaps >= 2 pi / 10^4 >> rounding), so edges lie in disjoint
// angular sectors: simple, with the origin strictly inside its kernel.
inline std::vector<Point2> star_ring(std::size_t n, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> radius(0.5, 1.0);
  std::vector<Point2> ring;
  for (std::size_t k = 0; k < n; ++k) {
    const double a = 2 * std::numbers::pi * static_cast<double>(k) / static_cast<double>(n);
    const double r = radius(rng);
    ring.push_back({r * std::cos(a), r * std::sin(a)});
  }
  return ring;
}

// Teeth i = 0..N-1 over x in [2i, 2i+1], height h, on the base [0, 2N-1] x [0, 1].
inline std::vector<Point2> comb_ring(std::size_t teeth, double h) {
  std::vector<Point2> ring{{0, 0}, {static_cast<double>(2 * teeth - 1), 0}};
  for (std::size_t j = teeth; j-- > 0;) {
    const double x = static_cast<double>(2 * j);
    ring.push_back({x + 1, h});
    ring.push_back({x, h});
    if (j > 0) {
      ring.push_back({x, 1});
      ring.push_back({x - 1, 1});
    }
  }
  return ring;
}

// Square of half-size s about the origin, each side split into `parts` dyadic pieces.
inline std::vector<Point2> square_ring(double s, std::size_t parts) {
  std::vector<Point2> ring;
  const Point2 corners[4] = {{-s, -s}, {s, -s}, {s, s}, {-s, s}};
  for (int c = 0; c < 4; ++c) {
    const Point2 a = corners[c], b = corners[(c + 1) % 4];
    for (std::size_t k = 0; k < parts; ++k) {
      const double t = static_cast<double>(k) / static_cast<double>(parts);  // parts is 2^m
      ring.push_back({a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t});
    }
  }
  return ring;
}

// The lattice points of x^2 + y^2 = R^2, R = 5 * 13 * 17 * 29 (324 of them), by angle.
inline std::vector<Point2> lattice_circle(std::int64_t r) {
  std::vector<Point2> points;
  for (std::int64_t x = -r; x <= r; ++x) {
    const std::int64_t rest = r * r - x * x;
    auto y = static_cast<std::int64_t>(std::llround(std::sqrt(static_cast<double>(rest))));
    while (y * y > rest) --y;
    while ((y + 1) * (y + 1) <= rest) ++y;
    if (y * y != rest) continue;
    points.push_back({static_cast<double>(x), static_cast<double>(y)});
    if (y != 0) points.push_back({static_cast<double>(x), static_cast<double>(-y)});
  }
  std::sort(points.begin(), points.end(), [](const Point2& p, const Point2& q) {
    return std::atan2(p.y, p.x) < std::atan2(q.y, q.x);
  });
  return points;
}

// `wanted` (>= 3) of the points, spread evenly over the whole list (all when there are fewer).
inline std::vector<Point2> spread_subset(const std::vector<Point2>& points, std::size_t wanted) {
  const std::size_t count = std::min(points.size(), std::max<std::size_t>(wanted, 3));
  std::vector<Point2> out;
  for (std::size_t i = 0; i < count; ++i) out.push_back(points[i * points.size() / count]);
  return out;
}

inline void scale(PlanarDomain& d, double factor, int exponent) {
  auto s = [&](Point2& p) { p = {std::ldexp(p.x * factor, exponent), std::ldexp(p.y * factor, exponent)}; };
  for (Point2& p : d.points) s(p);
  for (Point2& p : d.holes) s(p);
  for (auto& r : d.regions) s(r.point);
}

inline std::size_t power_of_two_at_most(std::size_t n) {
  std::size_t p = 1;
  while (2 * p <= n) p *= 2;
  return p;
}

}  // namespace planar_detail

inline const char* family_name(DomainFamily f) {
  constexpr const char* names[] = {"star_polygon", "comb", "nested_squares", "near_collinear",
                                   "cocircular", "tiny_angles", "star_with_crack"};
  return names[static_cast<int>(f)];
}

inline const char* mutation_name(DomainMutation m) {
  constexpr const char* names[] = {"crossing_segment", "collinear_overlap", "duplicate_vertex",
                                   "zero_length_segment", "vertex_on_segment", "duplicate_segment",
                                   "isolated_vertex", "open_loop", "nan_coordinate"};
  return names[static_cast<int>(m)];
}

/// A valid domain of `family` with about `vertices` (>= 3) boundary vertices, coordinates
/// scaled by 2^scale_exponent (and, for the rounded star families, a factor in [1, 2)).
inline PlanarDomainCase make_valid_domain(DomainFamily family, std::uint64_t seed, std::size_t vertices,
                                          int scale_exponent) {
  using namespace planar_detail;
  std::mt19937_64 rng(seed);
  vertices = std::max<std::size_t>(vertices, 3);
  PlanarDomainCase c;
  PlanarDomain& d = c.domain;
  double factor = 1.0;
  switch (family) {
    case DomainFamily::star_polygon:
    case DomainFamily::star_with_crack: {
      add_loop(d, star_ring(vertices, rng), 1);
      factor = std::uniform_real_distribution<double>(1.0, 2.0)(rng);
      break;
    }
    case DomainFamily::comb: {
      const std::size_t teeth = std::max<std::size_t>(1, vertices / 4);
      add_loop(d, comb_ring(teeth, static_cast<double>(2 + rng() % 30)), 1);
      break;
    }
    case DomainFamily::nested_squares: {
      const std::size_t depth = 2 + rng() % 5;  // rings; odd-numbered faces are holes
      const std::size_t parts = power_of_two_at_most(std::max<std::size_t>(1, vertices / (4 * depth)));
      // The face just inside ring j is domain for even j, a hole for odd j.
      for (std::size_t j = 0; j < depth; ++j) {
        const double s = static_cast<double>(depth - j);
        add_loop(d, square_ring(s, parts), static_cast<int>(j + 1));
        if (j % 2 == 1) d.holes.push_back({j + 1 < depth ? s - 0.5 : 0.0, 0.0});
      }
      break;
    }
    case DomainFamily::near_collinear: {
      const std::size_t n = power_of_two_at_most(std::max<std::size_t>(2, vertices - 2));
      std::vector<Point2> ring{{0, 0}};
      for (std::size_t k = 1; k < n; ++k) {
        const int choice = static_cast<int>(rng() % 3);  // exactly on the line, or 2^-40 off either side
        ring.push_back({static_cast<double>(k) / static_cast<double>(n), (choice - 1) * 0x1p-40});
      }
      ring.push_back({1, 0});
      ring.push_back({1, 1});
      ring.push_back({0, 1});
      add_loop(d, ring, 1);
      break;
    }
    case DomainFamily::cocircular: {
      add_loop(d, spread_subset(lattice_circle(5 * 13 * 17 * 29), vertices), 1);
      std::vector<Point2> inner = lattice_circle(5 * 13 * 17);  // a concentric lattice circle: the hole
      std::reverse(inner.begin(), inner.end());
      add_loop(d, inner, 2);
      d.holes.push_back({0, 0});
      break;
    }
    case DomainFamily::tiny_angles: {
      const std::size_t m = 2 + vertices % 20;
      const int k = 10 + static_cast<int>(rng() % 41);
      const DomainVertex origin = add_point(d, {0, 0});
      std::vector<DomainVertex> right;
      for (std::size_t j = 0; j <= m; ++j) right.push_back(add_point(d, {1, std::ldexp(static_cast<double>(j), -k)}));
      add_segment(d, origin, right.front(), 1);
      for (std::size_t j = 0; j < m; ++j) add_segment(d, right[j], right[j + 1], 1);
      add_segment(d, right.back(), origin, 1);
      for (std::size_t j = 1; j < m; ++j) add_segment(d, origin, right[j], 4);  // cuts at angles ~2^-k
      break;
    }
  }
  scale(d, factor, scale_exponent);
  if (family == DomainFamily::star_with_crack) {
    // Radial cut from vertex k to its exact half: inside, since the origin is in the kernel.
    const auto k = static_cast<DomainVertex>(rng() % d.points.size());
    const Point2 p = d.points[k];
    add_segment(d, k, add_point(d, {p.x / 2, p.y / 2}), 4);
  }
  c.description = std::string(family_name(family)) + " n=" + std::to_string(d.points.size()) +
                  " scale=2^" + std::to_string(scale_exponent) + " seed=" + std::to_string(seed);
  return c;
}

namespace planar_detail {

// Mutations need a base whose geometry they can reason about exactly: the star families give
// rays through the origin (a point p and its halvings are exactly collinear with it), the comb
// gives integer coordinates.
inline void mutate_star(PlanarDomainCase& c, DomainMutation m, std::mt19937_64& rng) {
  PlanarDomain& d = c.domain;
  const std::size_t n = d.points.size();
  const auto k = static_cast<DomainVertex>(rng() % n);
  const Point2 p = d.points[k];
  const auto edge = static_cast<std::uint32_t>(rng() % d.segments.size());
  switch (m) {
    case DomainMutation::crossing_segment: {
      // From m/2 to 2m, m ~ the midpoint of edge (a, b): the ray from the origin through m meets
      // the boundary once, near the middle of that edge, so this segment crosses it there only.
      const DomainSegment e = d.segments[edge];
      const Point2 mid{(d.points[e.a].x + d.points[e.b].x) / 2, (d.points[e.a].y + d.points[e.b].y) / 2};
      const DomainVertex u = add_point(d, {mid.x / 2, mid.y / 2});
      const DomainVertex v = add_point(d, {mid.x * 2, mid.y * 2});
      c.segments = {edge, add_segment(d, u, v)};
      c.expected = DomainProblemKind::segments_cross;
      break;
    }
    case DomainMutation::collinear_overlap: {
      // p/4 -- p/2 -- ... : segments p/8..p/2 and p/4..p (exactly collinear, overlapping on p/4..p/2).
      const DomainVertex a = add_point(d, {p.x / 8, p.y / 8});
      const DomainVertex b = add_point(d, {p.x / 2, p.y / 2});
      const DomainVertex q = add_point(d, {p.x / 4, p.y / 4});
      const std::uint32_t s1 = add_segment(d, a, b);
      const std::uint32_t s2 = add_segment(d, q, k);
      c.segments = {s1, s2};
      c.expected = DomainProblemKind::segments_overlap;
      break;
    }
    case DomainMutation::vertex_on_segment: {
      // From p/2 to 2p: vertex k lies exactly inside it.
      const DomainVertex a = add_point(d, {p.x / 2, p.y / 2});
      const DomainVertex b = add_point(d, {p.x * 2, p.y * 2});
      c.segments = {add_segment(d, a, b)};
      c.vertices = {k};
      c.expected = DomainProblemKind::vertex_on_segment;
      break;
    }
    default: break;
  }
}

inline void mutate_any(PlanarDomainCase& c, DomainMutation m, std::mt19937_64& rng) {
  PlanarDomain& d = c.domain;
  const auto edge = static_cast<std::uint32_t>(rng() % d.segments.size());
  const DomainSegment e = d.segments[edge];
  switch (m) {
    case DomainMutation::duplicate_vertex: {
      const DomainVertex copy = add_point(d, d.points[e.b]);
      d.segments[edge].b = copy;
      c.vertices = {e.b, copy};
      c.expected = DomainProblemKind::duplicate_vertices;
      break;
    }
    case DomainMutation::zero_length_segment:
      c.segments = {add_segment(d, e.a, e.a)};
      c.vertices = {e.a};
      c.expected = DomainProblemKind::zero_length_segment;
      break;
    case DomainMutation::duplicate_segment:
      c.segments = {edge, add_segment(d, e.b, e.a)};
      c.expected = DomainProblemKind::duplicate_segments;
      break;
    case DomainMutation::isolated_vertex: {
      // Beyond the bounding box of everything, exactly: twice the largest |coordinate| + 1.
      double far = 1;
      for (const Point2& p : d.points) far = std::max({far, std::abs(p.x), std::abs(p.y)});
      c.vertices = {add_point(d, {2 * far, 2 * far})};
      c.expected = DomainProblemKind::isolated_vertex;
      break;
    }
    case DomainMutation::open_loop:
      // The outer loop's first edge is removed: its ends keep their other edges, so only the
      // domain triangulation (which finds the dangling edges) can refuse it.
      d.segments.erase(d.segments.begin());
      c.expected = DomainProblemKind::open_boundary;
      break;
    case DomainMutation::nan_coordinate:
      d.points[e.a].y = std::nan("");
      c.vertices = {e.a};
      c.expected = DomainProblemKind::non_finite_coordinate;
      break;
    default: break;
  }
}

}  // namespace planar_detail

/// A valid domain (star polygon or star with a crack) turned invalid by mutation `m`.
inline PlanarDomainCase make_invalid_domain(DomainMutation m, std::uint64_t seed, std::size_t vertices,
                                            int scale_exponent) {
  const bool crack = seed % 2 == 1;
  PlanarDomainCase c = make_valid_domain(crack ? DomainFamily::star_with_crack : DomainFamily::star_polygon, seed,
                                         vertices, scale_exponent);
  std::mt19937_64 rng(seed ^ 0x9e3779b97f4a7c15ULL);
  c.valid = false;
  if (m == DomainMutation::crossing_segment || m == DomainMutation::collinear_overlap ||
      m == DomainMutation::vertex_on_segment) {
    // The crack's inner end p/2 sits on the ray of one vertex; keep mutations to the boundary
    // loop's vertices and edges, whose rays meet nothing else.
    if (crack) {
      c.domain.points.pop_back();
      c.domain.segments.pop_back();
    }
    planar_detail::mutate_star(c, m, rng);
  } else {
    planar_detail::mutate_any(c, m, rng);
  }
  c.description += std::string(" mutation=") + mutation_name(m);
  return c;
}

/// RapidCheck: a valid domain of any family with 3 to `max_vertices` boundary vertices, at
/// scale 2^-30 (~1e-9), 1, or 2^40 (~1e12), or any power of two in [-35, 45].
inline rc::Gen<PlanarDomainCase> valid_planar_domain(std::size_t max_vertices) {
  return rc::gen::exec([max_vertices] {
    const auto family = static_cast<DomainFamily>(*rc::gen::inRange(0, kDomainFamilies));
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto vertices = *rc::gen::inRange<std::size_t>(3, max_vertices + 1);
    const int exponent = *rc::gen::oneOf(rc::gen::element(0, -30, 40), rc::gen::inRange(-35, 46));
    return make_valid_domain(family, seed, vertices, exponent);
  });
}

/// RapidCheck: a domain made invalid by one mutation (any kind, open_loop included).
inline rc::Gen<PlanarDomainCase> invalid_planar_domain(std::size_t max_vertices) {
  return rc::gen::exec([max_vertices] {
    const auto mutation = static_cast<DomainMutation>(*rc::gen::inRange(0, kDomainMutations));
    const auto seed = *rc::gen::arbitrary<std::uint64_t>();
    const auto vertices = *rc::gen::inRange<std::size_t>(3, max_vertices + 1);
    const int exponent = *rc::gen::oneOf(rc::gen::element(0, -30, 40), rc::gen::inRange(-35, 46));
    return make_invalid_domain(mutation, seed, vertices, exponent);
  });
}

/// Shown by RapidCheck on failure: the parameters that rebuild the case.
inline void showValue(const PlanarDomainCase& c, std::ostream& os) { os << c.description; }

}  // namespace certimesh::fuzz
