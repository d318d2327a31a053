// Constructive geometry: areas of boolean operations on rectangles exactly (rational shoelace
// of the resulting domain's rings), on discs approximately (analytic areas), hole points
// strictly inside their holes (exact), and the `certimesh domain` command on script files.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <gmpxx.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "certimesh/generators/domain/constructive_geometry_2.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/io/mesh_file.h"

namespace certimesh::generators {
namespace {

// Exact area of a region: the rational shoelace of its rings (outer counterclockwise, inner
// clockwise, so the signed sum is the area).
mpq_class exact_area(const Region2& region) {
  mpq_class twice = 0;
  auto ring_sum = [&](const std::vector<Point2>& ring) {
    for (std::size_t i = 0; i < ring.size(); ++i) {
      const Point2& p = ring[i];
      const Point2& q = ring[(i + 1) % ring.size()];
      twice += mpq_class(p.x) * mpq_class(q.y) - mpq_class(p.y) * mpq_class(q.x);
    }
  };
  for (const PolygonWithHoles2& polygon : region.polygons) {
    ring_sum(polygon.outer);
    for (const auto& inner : polygon.inners) ring_sum(inner);
  }
  return twice / 2;
}

struct Box {
  mpq_class x0, y0, x1, y1;
  mpq_class area() const { return (x1 - x0) * (y1 - y0); }
};

mpq_class overlap_area(const Box& a, const Box& b) {
  const mpq_class w = std::min(a.x1, b.x1) - std::max(a.x0, b.x0);
  const mpq_class h = std::min(a.y1, b.y1) - std::max(a.y0, b.y0);
  return (w > 0 && h > 0) ? mpq_class(w * h) : mpq_class(0);
}

TEST(dom_ConstructiveGeometry, OverlappingRectanglesExactAreas) {
  const Region2 a = rectangle_region(0, 0, 3, 2), b = rectangle_region(1, 1, 4, 3);
  EXPECT_EQ(exact_area(region_union(a, b)), 10);
  EXPECT_EQ(exact_area(region_difference(a, b)), 4);
  EXPECT_EQ(exact_area(region_intersection(a, b)), 2);
  for (const Region2& r : {region_union(a, b), region_difference(a, b), region_intersection(a, b)}) {
    const PlanarDomain d = to_planar_domain(r);
    EXPECT_TRUE(validate_domain(d).empty());
    EXPECT_TRUE(d.holes.empty());
  }
}

RC_GTEST_PROP(dom_ConstructiveGeometryProperty, DyadicRectanglesExactAreas, ()) {
  // Corners on the grid of 1/8 in [-4, 4]: every crossing of rectangle edges is such a point.
  auto coordinate = [] { return *rc::gen::inRange(-32, 33) / 8.0; };
  auto box = [&] {
    double x0 = coordinate(), x1 = coordinate(), y0 = coordinate(), y1 = coordinate();
    RC_PRE(x0 != x1 && y0 != y1);
    return std::array<double, 4>{std::min(x0, x1), std::min(y0, y1), std::max(x0, x1), std::max(y0, y1)};
  };
  const auto p = box(), q = box();
  const Region2 a = rectangle_region(p[0], p[1], p[2], p[3]), b = rectangle_region(q[0], q[1], q[2], q[3]);
  const Box ea{p[0], p[1], p[2], p[3]}, eb{q[0], q[1], q[2], q[3]};
  const mpq_class common = overlap_area(ea, eb);
  RC_ASSERT(exact_area(region_intersection(a, b)) == common);
  RC_ASSERT(exact_area(region_union(a, b)) == ea.area() + eb.area() - common);
  RC_ASSERT(exact_area(region_difference(a, b)) == ea.area() - common);
  const Region2 u = region_union(a, b);
  const PlanarDomain d = to_planar_domain(u);  // throws InvalidDomain if Boost's rings were invalid
  RC_ASSERT(validate_domain(d).empty());
}

TEST(dom_ConstructiveGeometry, FarFromTheOriginStillExact) {
  // Rectangles near 2^20: the snap distance follows the operands' size, not their magnitude.
  const double o = 1048576;
  const Region2 a = rectangle_region(o, o, o + 0.75, o + 0.5), b = rectangle_region(o + 0.25, o + 0.125, o + 1, o + 1);
  EXPECT_EQ(exact_area(region_intersection(a, b)), mpq_class(1, 2) * mpq_class(3, 8));
  EXPECT_EQ(exact_area(region_union(a, b)), mpq_class(3, 8) + mpq_class(3, 4) * mpq_class(7, 8) - mpq_class(3, 16));
  EXPECT_TRUE(validate_domain(to_planar_domain(region_difference(a, b))).empty());
}

TEST(dom_ConstructiveGeometry, DiscAreasApproximately) {
  const double r = 1, step = 0.01;
  const Region2 a = disc_region({0, 0}, r, step), b = disc_region({1, 0}, r, step);
  // Lens of two unit discs at distance 1: 2 pi/3 - sqrt(3)/2.
  const double lens = 2 * std::numbers::pi / 3 - std::sqrt(3.0) / 2;
  const double disc = std::numbers::pi;
  EXPECT_NEAR(region_area(region_intersection(a, b)), lens, 1e-3);
  EXPECT_NEAR(region_area(region_union(a, b)), 2 * disc - lens, 1e-3);
  EXPECT_NEAR(region_area(region_difference(a, b)), disc - lens, 1e-3);
  EXPECT_NEAR(exact_area(region_union(a, b)).get_d(), region_area(region_union(a, b)), 1e-12);
  EXPECT_TRUE(validate_domain(to_planar_domain(region_union(a, b))).empty());
}

RC_GTEST_PROP(dom_ConstructiveGeometryProperty, RandomDiscsGiveValidDomains, ()) {
  // Centres and radii on a 1/64 grid (shrinkable); boundaries of three discs in general and in
  // special position (equal radii, common tangents, shared centres) alike.
  auto value = [](int lo, int hi) { return *rc::gen::inRange(lo, hi) / 64.0; };
  std::vector<Region2> discs;
  for (int i = 0; i < 3; ++i) discs.push_back(disc_region({value(-64, 65), value(-64, 65)}, value(8, 65), 0.05));
  const Region2 ab = region_union(discs[0], discs[1]);
  const Region2 ab_c = region_difference(ab, discs[2]);
  const Region2 a_and_b = region_intersection(discs[0], discs[1]);
  // Inclusion-exclusion holds for the polygons up to slivers narrower than Boost's overlay grid
  // (~1e-7 of the box), which one operation may keep and another drop (near-tangent discs: a
  // sliver of area ~6e-9 was seen); a wrong construction would be off by far more.
  const double lhs = region_area(ab) + region_area(a_and_b);
  const double rhs = region_area(discs[0]) + region_area(discs[1]);
  RC_LOG() << "union " << region_area(ab) << " intersection " << region_area(a_and_b) << " discs "
            << region_area(discs[0]) << " " << region_area(discs[1]) << "\n";
  RC_ASSERT(std::abs(lhs - rhs) <= 1e-7 * rhs);
  for (const Region2& r : {ab, ab_c, a_and_b}) {
    if (r.polygons.empty()) continue;
    const PlanarDomain d = to_planar_domain(r);  // throws InvalidDomain on an invalid result
    RC_ASSERT(validate_domain(d).empty());
    std::size_t inner_rings = 0;
    for (const PolygonWithHoles2& p : r.polygons) inner_rings += p.inners.size();
    RC_ASSERT(d.holes.size() == inner_rings);
  }
}

TEST(dom_ConstructiveGeometry, DiscMinusInnerDiscHasItsHolePointInside) {
  const Region2 r = region_difference(disc_region({0, 0}, 1, 0.02), disc_region({0.3, 0.1}, 0.05, 0.01));
  const PlanarDomain d = to_planar_domain(r);
  ASSERT_EQ(d.holes.size(), 1u);
  EXPECT_LT(std::hypot(d.holes[0].x - 0.3, d.holes[0].y - 0.1), 0.05);
}

TEST(dom_ConstructiveGeometry, HolePointsLieStrictlyInTheirHolesNotOnIslands) {
  // A frame [0,10]^2 - [2,8]^2 with an island [4,6]^2 inside its hole.
  const Region2 frame = region_difference(rectangle_region(0, 0, 10, 10), rectangle_region(2, 2, 8, 8));
  const Region2 r = region_union(frame, rectangle_region(4, 4, 6, 6));
  ASSERT_EQ(r.polygons.size(), 2u);
  const PlanarDomain d = to_planar_domain(r, 3);
  EXPECT_EQ(d.points.size(), 12u);
  EXPECT_EQ(d.segments.size(), 12u);
  ASSERT_EQ(d.holes.size(), 1u);
  const Point2 h = d.holes.front();
  EXPECT_TRUE(h.x > 2 && h.x < 8 && h.y > 2 && h.y < 8) << h.x << " " << h.y;
  EXPECT_FALSE(h.x >= 4 && h.x <= 6 && h.y >= 4 && h.y <= 6) << h.x << " " << h.y;
  for (const DomainSegment& s : d.segments) EXPECT_EQ(s.label, 3);
}

TEST(dom_ConstructiveGeometry, RectanglesTouchingAtACornerShareOneVertex) {
  const Region2 r = region_union(rectangle_region(0, 0, 1, 1), rectangle_region(1, 1, 2, 2));
  const PlanarDomain d = to_planar_domain(r);
  EXPECT_EQ(d.points.size(), 7u);  // (1,1) merged
  EXPECT_EQ(d.segments.size(), 8u);
  EXPECT_TRUE(validate_domain(d).empty());
}

TEST(dom_ConstructiveGeometry, RefusalsNameTheProblem) {
  EXPECT_THROW(rectangle_region(1, 0, 0, 1), std::invalid_argument);
  try {
    polygon_region({{0, 0}, {1, 1}, {1, 0}, {0, 1}});  // a bow tie
    ADD_FAILURE();
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not simple"), std::string::npos) << e.what();
  }
  const Region2 none = region_intersection(rectangle_region(0, 0, 1, 1), rectangle_region(2, 2, 3, 3));
  EXPECT_TRUE(none.polygons.empty());
  EXPECT_THROW(to_planar_domain(none), InvalidDomain);
}

// ---- the command -----------------------------------------------------------------------------

struct CommandResult {
  int status;
  std::string output;
};

CommandResult run(const std::string& arguments) {
  const std::filesystem::path log = std::filesystem::temp_directory_path() / "certimesh_dom_cli.log";
  const std::string command = std::string(CERTIMESH_CLI) + " " + arguments + " > " + log.string() + " 2>&1";
  const int raw = std::system(command.c_str());
  std::ifstream in(log);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::filesystem::remove(log);
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, text};
}

std::filesystem::path write_script(const std::string& name, const std::string& text) {
  const std::filesystem::path path = std::filesystem::temp_directory_path() / name;
  std::ofstream(path) << text;
  return path;
}

TEST(dom_DomainCommand, ScriptWritesAValidPolyDomain) {
  const std::filesystem::path script = write_script("certimesh_dom_plate.csg",
                                                    "# a plate with a round hole and a notch\n"
                                                    "rect plate 0 0 4 2\n"
                                                    "disc hole 1 1 0.4 0.05   # step 0.05\n"
                                                    "polygon notch 3 -1 3.5 1 4 -1\n"
                                                    "difference a plate hole\n"
                                                    "difference b a notch\n"
                                                    "output b\n");
  const std::filesystem::path out = std::filesystem::temp_directory_path() / "certimesh_dom_plate.poly";
  const CommandResult r = run("domain " + script.string() + " -o " + out.string());
  ASSERT_EQ(r.status, 0) << r.output;
  const PlanarDomain d = planar_domain_from_mesh_data(io::read_mesh(out));
  EXPECT_TRUE(validate_domain(d).empty());
  ASSERT_EQ(d.holes.size(), 1u);
  EXPECT_LT(std::hypot(d.holes[0].x - 1, d.holes[0].y - 1), 0.4);
  std::filesystem::remove(out);
  std::filesystem::remove(script);
}

TEST(dom_DomainCommand, BadScriptsNameFileAndLine) {
  const struct {
    const char* text;
    int line;
    const char* why;
  } cases[] = {
      {"rect a 0 0 1 1\nfrobnicate b\n", 2, "unknown statement 'frobnicate'"},
      {"rect a 0 0 1\n", 1, "takes 5 arguments"},
      {"rect a 0 0 1 1\nunion c a b\noutput c\n", 2, "'b' is not defined"},
      {"rect a 0 0 x 1\n", 1, "'x' is not a finite number"},
      {"rect a 0 0 1 1\n# nothing else\n", 2, "no 'output NAME' line"},
      {"rect a 0 0 1 1\nrect b 2 2 3 3\nintersection c a b\noutput c\n", 4, "not a valid domain"},
      {"polygon p 0 0 1 1 1 0 0 1\n", 1, "not simple"},
  };
  const std::filesystem::path script = write_script("certimesh_dom_bad.csg", "");
  for (const auto& c : cases) {
    write_script("certimesh_dom_bad.csg", c.text);
    const CommandResult r = run("domain " + script.string() + " -o " +
                                (std::filesystem::temp_directory_path() / "certimesh_dom_bad.poly").string());
    EXPECT_EQ(r.status, 1) << c.text << r.output;
    EXPECT_NE(r.output.find("error: " + script.string() + ":" + std::to_string(c.line) + ": "), std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(c.why), std::string::npos) << r.output;
  }
  std::filesystem::remove(script);
  EXPECT_EQ(run("domain /nonexistent/certimesh.csg -o x.poly").status, 2);
}

}  // namespace
}  // namespace certimesh::generators
