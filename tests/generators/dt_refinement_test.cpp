// Delaunay refinement: every inside triangle meets the size bound, no constrained edge is
// split (every boundary segment is still an edge, with no vertex inside it), and the
// independent certificate accepts the mesh for its domain.
#include <gtest/gtest.h>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/generators/delaunay/delaunay_refinement_2.h"
#include "certimesh/predicates/orient2d.h"
#include "dt_triangulation_checks.h"

namespace certimesh::testing {
namespace {

using generators::DelaunayRefinementOptions;
using generators::RegionSeed;

struct Domain {
  std::vector<Point2> points;
  std::vector<Edge> segments;
  std::vector<Point2> holes;
};

void add_loop(Domain& d, const std::vector<Point2>& loop) {
  const auto base = static_cast<std::uint32_t>(d.points.size());
  for (std::size_t i = 0; i < loop.size(); ++i) {
    d.points.push_back(loop[i]);
    d.segments.push_back({base + std::uint32_t(i), base + std::uint32_t((i + 1) % loop.size())});
  }
}

// A loop from corner to corner with sides cut into pieces no longer than `step`.
std::vector<Point2> subdivided(const std::vector<Point2>& corners, double step) {
  std::vector<Point2> out;
  for (std::size_t i = 0; i < corners.size(); ++i) {
    const Point2 a = corners[i], b = corners[(i + 1) % corners.size()];
    const int pieces = std::max(1, int(std::ceil(std::hypot(b.x - a.x, b.y - a.y) / step)));
    for (int k = 0; k < pieces; ++k)
      out.push_back({a.x + (b.x - a.x) * k / pieces, a.y + (b.y - a.y) * k / pieces});
  }
  return out;
}

io::MeshData domain_data(const Domain& d) {
  io::MeshData m;
  for (const Point2& p : d.points) m.coordinates.insert(m.coordinates.end(), {p.x, p.y});
  for (const Edge& e : d.segments) m.segments.insert(m.segments.end(), {e[0], e[1]});
  for (const Point2& h : d.holes) m.holes.insert(m.holes.end(), {h.x, h.y});
  return m;
}

struct Refined {
  std::vector<Point2> points;
  std::vector<Triangle> triangles;
  generators::DelaunayRefinementStats stats;
};

Refined refine(const Domain& d, const DelaunayRefinementOptions& options) {
  ConstrainedDelaunay2 cdt(d.points);
  for (const Edge& e : d.segments) cdt.insert_constraint(e[0], e[1]);
  std::vector<int> labels = cdt.classify(d.holes, std::vector<RegionSeed>{});
  Refined r;
  r.stats = generators::refine_delaunay_2(cdt, labels, options);
  for (std::uint32_t v = 0; v < cdt.vertex_count(); ++v) r.points.push_back(cdt.point(v));
  for (std::uint32_t t = 0; t < cdt.triangle_slot_count(); ++t)
    if (cdt.is_live(t) && labels[t] >= 0) r.triangles.push_back(cdt.vertices(t));
  return r;
}

void expect_certified(const Domain& d, const Refined& r) {
  io::MeshData mesh;
  for (const Point2& p : r.points) mesh.coordinates.insert(mesh.coordinates.end(), {p.x, p.y});
  for (const Triangle& t : r.triangles) mesh.triangles.insert(mesh.triangles.end(), {t[0], t[1], t[2]});
  const io::MeshData domain = domain_data(d);
  const certificate::Report report = certificate::check_mesh(mesh, &domain);
  EXPECT_TRUE(report.valid) << report.finding.message;
  // No constrained edge split: every segment is still an edge of the mesh.
  const TriangulationFindings f = check_triangulation(r.points, r.triangles, d.segments);
  EXPECT_EQ(f.missing_constraints, 0u);
  EXPECT_EQ(f.non_positive, 0u);
}

Domain square_with_hole(double step) {
  Domain d;
  add_loop(d, subdivided({{0, 0}, {1, 0}, {1, 1}, {0, 1}}, step));
  add_loop(d, subdivided({{0.3, 0.3}, {0.3, 0.6}, {0.7, 0.55}, {0.6, 0.3}}, step));
  d.holes.push_back({0.5, 0.45});
  return d;
}

TEST(dt_refinement, UniformSizeIsMetAndTheMeshIsCertified) {
  for (double h : {0.2, 0.05, 0.02}) {
    const Domain d = square_with_hole(0.9 * h);  // boundary pieces safely below h
    DelaunayRefinementOptions options;
    options.size.uniform_size = h;
    const Refined r = refine(d, options);
    EXPECT_FALSE(r.stats.bound_reached);
    EXPECT_GT(r.stats.inserted, 0u);
    for (const Triangle& t : r.triangles)
      EXPECT_LE(generators::longest_side(r.points[t[0]], r.points[t[1]], r.points[t[2]]), h) << "h " << h;
    expect_certified(d, r);
    // Every original boundary vertex kept its place; the new ones are interior.
    for (std::size_t v = 0; v < d.points.size(); ++v) EXPECT_EQ(r.points[v], d.points[v]);
  }
}

TEST(dt_refinement, SizeFunctionAndDeterminism) {
  const Domain d = square_with_hole(0.02);
  DelaunayRefinementOptions options;
  options.size.size_function = [](const Point2& p) { return 0.02 + 0.2 * p.x; };
  const Refined a = refine(d, options), b = refine(d, options);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.triangles, b.triangles);
  for (const Triangle& t : a.triangles) {
    const Point2 g{(a.points[t[0]].x + a.points[t[1]].x + a.points[t[2]].x) / 3,
                   (a.points[t[0]].y + a.points[t[1]].y + a.points[t[2]].y) / 3};
    EXPECT_LE(generators::longest_side(a.points[t[0]], a.points[t[1]], a.points[t[2]]), options.size.at(g));
  }
  expect_certified(d, a);
}

TEST(dt_refinement, AutomaticSizeAndQualityOnAPolygonWithASharpAngle) {
  Domain d;
  add_loop(d, subdivided({{0, 0}, {2, 0}, {2, 0.05}, {0.2, 0.3}, {0, 1}}, 0.1));
  const Refined r = refine(d, DelaunayRefinementOptions{});
  EXPECT_FALSE(r.stats.bound_reached);
  expect_certified(d, r);
}


// A side cut into pieces of alternating lengths 2.3h and 3.2h (as the graded boundary of a
// star of 2000 spikes was, 2026-12), each point the rounding of a point of the side: where a
// point is rounded outward, the triangle of it and its two neighbours is a flat sliver inside
// the domain, too big for h, and the rounded midpoint of its long edge can fall across the
// subsegments, outside the region. Inserted there, it put triangles outside the domain.
TEST(dt_refinement, RoundedMidpointsNextToASegmentStayInside) {
  const double h = 0.05;
  for (const double slope : {0.3, 0.7, 1.9}) {
    for (const double shift : {0.1234567, 0.7654321, 3.3}) {
      const Point2 a{shift, shift / 3}, b{shift + 1, shift / 3 + slope};
      const double length = std::hypot(b.x - a.x, b.y - a.y), u = 2.3 * h, v = 3.2 * h;
      std::vector<Point2> loop;
      for (double t = 0; t < length - v; t += loop.size() % 2 ? v : u)
        loop.push_back({a.x + (b.x - a.x) * (t / length), a.y + (b.y - a.y) * (t / length)});
      std::vector<Point2> rest = subdivided({b, {b.x, b.y + 1}, {a.x, a.y + 1}, a}, 0.9 * h);
      rest.erase(std::find(rest.begin(), rest.end(), a), rest.end());  // the pieces of (a, b)
      loop.insert(loop.end(), rest.begin(), rest.end());
      Domain d;
      add_loop(d, loop);
      DelaunayRefinementOptions options;
      options.size.uniform_size = h;
      SCOPED_TRACE("slope " + std::to_string(slope) + " shift " + std::to_string(shift));
      expect_certified(d, refine(d, options));
    }
  }
}

}  // namespace
}  // namespace certimesh::testing
