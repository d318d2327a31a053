// validate_domain and the .poly conversion: a hand case for every kind of problem, generated
// valid domains accepted (and an independent O(n^2) rational oracle agreeing on small ones),
// generated invalid domains refused with the right kind and ids, a .poly round trip, and 10^5
// segments validated quickly.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <gmpxx.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "certimesh/fuzz/planar_domains.h"
#include "certimesh/generators/domain/curves_2.h"
#include "certimesh/generators/domain/default_domains.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/io/mesh_file.h"
#include "rational_oracle.h"

namespace certimesh::generators {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr std::size_t kLargeSegments = 20000;
#else
constexpr std::size_t kLargeSegments = 100000;
#endif

// ---- the independent oracle: GMP rationals, every pair of segments ------------------------

int orient(const Point2& a, const Point2& b, const Point2& c) {
  return testing::oracle_orient2d(a.x, a.y, b.x, b.y, c.x, c.y);
}

// p collinear with [a, b]: is it in the closed segment? (rational comparisons)
bool in_closed_box(const Point2& p, const Point2& a, const Point2& b) {
  return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
         p.y <= std::max(a.y, b.y);
}

bool closed_segments_meet(const Point2& a, const Point2& b, const Point2& c, const Point2& d) {
  const int d1 = orient(a, b, c), d2 = orient(a, b, d), d3 = orient(c, d, a), d4 = orient(c, d, b);
  if (d1 * d2 < 0 && d3 * d4 < 0) return true;
  return (d1 == 0 && in_closed_box(c, a, b)) || (d2 == 0 && in_closed_box(d, a, b)) ||
         (d3 == 0 && in_closed_box(a, c, d)) || (d4 == 0 && in_closed_box(b, c, d));
}

// Segments (v, p) and (v, q) meet beyond v iff collinear and (p - v) . (q - v) > 0.
bool meet_beyond_shared(const Point2& v, const Point2& p, const Point2& q) {
  if (orient(v, p, q) != 0) return false;
  const mpq_class dot = (mpq_class(p.x) - v.x) * (mpq_class(q.x) - v.x) + (mpq_class(p.y) - v.y) * (mpq_class(q.y) - v.y);
  return dot > 0;
}

bool oracle_valid(const PlanarDomain& d) {
  for (const Point2& p : d.points) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) return false;
  }
  for (std::size_t i = 0; i < d.points.size(); ++i) {
    for (std::size_t j = i + 1; j < d.points.size(); ++j) {
      if (d.points[i].x == d.points[j].x && d.points[i].y == d.points[j].y) return false;
    }
  }
  std::vector<bool> used(d.points.size(), false);
  for (const DomainSegment& s : d.segments) {
    if (s.a >= d.points.size() || s.b >= d.points.size() || s.a == s.b) return false;
    used[s.a] = used[s.b] = true;
  }
  // A vertex on no segment is valid (design decision 8) unless it lies on a segment (distinct
  // points, so inside it: a T-junction).
  for (std::size_t v = 0; v < d.points.size(); ++v) {
    if (used[v]) continue;
    for (const DomainSegment& s : d.segments) {
      if (orient(d.points[s.a], d.points[s.b], d.points[v]) == 0 && in_closed_box(d.points[v], d.points[s.a], d.points[s.b]))
        return false;
    }
  }
  for (std::size_t i = 0; i < d.segments.size(); ++i) {
    for (std::size_t j = i + 1; j < d.segments.size(); ++j) {
      const DomainSegment &s = d.segments[i], &t = d.segments[j];
      const std::set<DomainVertex> ids{s.a, s.b, t.a, t.b};
      if (ids.size() == 2) return false;  // the same pair twice
      if (ids.size() == 4) {
        if (closed_segments_meet(d.points[s.a], d.points[s.b], d.points[t.a], d.points[t.b])) return false;
        continue;
      }
      const DomainVertex v = (s.a == t.a || s.a == t.b) ? s.a : s.b;
      const DomainVertex p = s.a == v ? s.b : s.a;
      const DomainVertex q = t.a == v ? t.b : t.a;
      if (meet_beyond_shared(d.points[v], d.points[p], d.points[q])) return false;
    }
  }
  return true;
}

// ---- helpers -------------------------------------------------------------------------------

PlanarDomain polygon(const std::vector<Point2>& ring) {
  PlanarDomain d;
  d.points = ring;
  const auto n = static_cast<DomainVertex>(ring.size());
  for (DomainVertex i = 0; i < n; ++i) d.segments.push_back({i, (i + 1) % n, 1});
  return d;
}

bool contains(const std::vector<std::uint32_t>& ids, std::uint32_t id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// The single problem of `kind` (there must be exactly one of that kind).
DomainProblem only_problem_of(const std::vector<DomainProblem>& problems, DomainProblemKind kind) {
  std::vector<DomainProblem> found;
  for (const DomainProblem& p : problems) {
    if (p.kind == kind) found.push_back(p);
  }
  EXPECT_EQ(found.size(), 1u) << to_string(kind);
  return found.empty() ? DomainProblem{} : found.front();
}

// ---- hand cases, one per kind ----------------------------------------------------------------

TEST(dom_DomainValidation, BuiltInDomainsAreValid) {
  for (const PlanarDomain& d : {unit_square(), square_with_two_holes(), plate_with_holes_and_crack()}) {
    EXPECT_TRUE(validate_domain(d).empty());
    EXPECT_TRUE(oracle_valid(d));
  }
}

TEST(dom_DefaultDomains, PlateHasTwoHolesAndACrackWithAFreeTip) {
  const PlanarDomain d = plate_with_holes_and_crack();
  EXPECT_EQ(d.points.size(), 72u);    // 5 outer, 3 crack, 2 x 32 hole vertices
  EXPECT_EQ(d.segments.size(), 72u);  // 5 outer, 3 crack, 2 x 32 hole segments
  std::vector<int> degree(d.points.size(), 0);
  std::map<io::Label, int> per_label;
  for (const DomainSegment& s : d.segments) {
    ++degree[s.a];
    ++degree[s.b];
    ++per_label[s.label];
  }
  EXPECT_EQ(per_label, (std::map<io::Label, int>{{1, 5}, {2, 32}, {3, 32}, {4, 3}}));
  EXPECT_EQ(std::count(degree.begin(), degree.end(), 1), 1);  // the crack tip only
  EXPECT_EQ(degree[1], 3);                                      // the crack mouth (2, 0)
  EXPECT_EQ(d.points[1], (Point2{2, 0}));
  ASSERT_EQ(d.holes.size(), 2u);
  EXPECT_EQ(d.holes[0], (Point2{1, 1}));
  EXPECT_EQ(d.holes[1], (Point2{3, 1}));
  const PlanarDomain s = square_with_two_holes(20);
  EXPECT_EQ(s.segments.size(), 44u);
  EXPECT_EQ(s.holes, (std::vector<Point2>{{0.3, 0.5}, {0.7, 0.5}}));
}

TEST(dom_DomainValidation, CrossingSegmentsNamedWithReadableCoordinates) {
  PlanarDomain d = polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  d.points.push_back({0.5, -1});
  d.points.push_back({0.5, 1.5});
  d.segments.push_back({4, 5, 2});
  const std::vector<DomainProblem> problems = validate_domain(d);
  ASSERT_EQ(problems.size(), 2u);  // the bottom and the top edge are crossed
  EXPECT_EQ(problems[0].kind, DomainProblemKind::segments_cross);
  EXPECT_EQ(problems[0].message, "segments 0 (0 0)-(1 0) and 4 (0.5 -1)-(0.5 1.5) cross");
  EXPECT_EQ(problems[0].segments, (std::vector<std::uint32_t>{0, 4}));
  EXPECT_EQ(problems[1].message, "segments 2 (1 1)-(0 1) and 4 (0.5 -1)-(0.5 1.5) cross");
}

TEST(dom_DomainValidation, CoordinatesInMessagesReadBackExactly) {
  const double third = 1.0 / 3.0;
  PlanarDomain d = polygon({{0, 0}, {1, 0}, {third, 1}});
  d.points.push_back({third, 1});
  d.segments[1].b = 3;  // vertices 2 and 3 at the same point
  const DomainProblem p = only_problem_of(validate_domain(d), DomainProblemKind::duplicate_vertices);
  EXPECT_EQ(p.vertices, (std::vector<std::uint32_t>{2, 3}));
  const std::size_t open = p.message.find('(');
  ASSERT_NE(open, std::string::npos);
  EXPECT_EQ(std::stod(p.message.substr(open + 1)), third) << p.message;
}

TEST(dom_DomainValidation, CollinearOverlapWithAndWithoutSharedVertex) {
  PlanarDomain d = polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  d.points.push_back({1, 0});
  d.points.push_back({2, 0});
  d.segments.push_back({4, 5, 2});  // inside the bottom edge
  DomainProblem p = only_problem_of(validate_domain(d), DomainProblemKind::segments_overlap);
  EXPECT_EQ(p.segments, (std::vector<std::uint32_t>{0, 4}));
  EXPECT_TRUE(p.message.find("overlap") != std::string::npos);

  PlanarDomain e = polygon({{0, 0}, {4, 0}, {4, 4}, {0, 4}});
  e.points.push_back({2, 0});
  e.segments.push_back({0, 4, 2});  // from the corner along the bottom edge
  p = only_problem_of(validate_domain(e), DomainProblemKind::segments_overlap);
  EXPECT_EQ(p.segments, (std::vector<std::uint32_t>{0, 4}));
  EXPECT_EQ(p.vertices, (std::vector<std::uint32_t>{0}));
}

TEST(dom_DomainValidation, VertexInsideASegmentIsATJunction) {
  PlanarDomain d = polygon({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  d.points.push_back({1, 0});  // exactly inside the bottom edge
  d.points.push_back({1, 1});
  d.segments.push_back({4, 5, 4});
  const DomainProblem p = only_problem_of(validate_domain(d), DomainProblemKind::vertex_on_segment);
  EXPECT_EQ(p.vertices, (std::vector<std::uint32_t>{4}));
  EXPECT_TRUE(contains(p.segments, 0) && contains(p.segments, 4));
  EXPECT_EQ(p.message, "vertex 4 (1 0) of segment 4 lies inside segment 0 (0 0)-(2 0)");
}

TEST(dom_DomainValidation, NearlyOnASegmentIsNotOnIt) {
  // 2^-60 above the bottom edge: a tolerance would call it a T-junction; the exact test does not.
  PlanarDomain d = polygon({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  d.points.push_back({1, 0x1p-60});
  d.points.push_back({1, 1});
  d.segments.push_back({4, 5, 4});
  EXPECT_TRUE(validate_domain(d).empty());
}

TEST(dom_DomainValidation, ZeroLengthSegments) {
  PlanarDomain d = polygon({{0, 0}, {1, 0}, {0, 1}});
  d.segments.push_back({1, 1, 1});
  DomainProblem p = only_problem_of(validate_domain(d), DomainProblemKind::zero_length_segment);
  EXPECT_EQ(p.segments, (std::vector<std::uint32_t>{3}));
  EXPECT_EQ(p.message, "segment 3 has zero length: both ends are vertex 1 (1 0)");

  PlanarDomain e = polygon({{0, 0}, {1, 0}, {0, 1}});
  e.points.push_back({1, 0});
  e.segments.push_back({1, 3, 1});
  p = only_problem_of(validate_domain(e), DomainProblemKind::zero_length_segment);
  EXPECT_EQ(p.vertices, (std::vector<std::uint32_t>{1, 3}));
}

TEST(dom_DomainValidation, DuplicateSegmentsInEitherDirection) {
  PlanarDomain d = polygon({{0, 0}, {1, 0}, {0, 1}});
  d.segments.push_back({1, 0, 7});
  const DomainProblem p = only_problem_of(validate_domain(d), DomainProblemKind::duplicate_segments);
  EXPECT_EQ(p.segments, (std::vector<std::uint32_t>{0, 3}));
  EXPECT_EQ(p.message, "segments 0 and 3 both join vertices 0 and 1 (0 0)-(1 0)");
}

TEST(dom_DomainValidation, NonFiniteCoordinatesAnywhere) {
  PlanarDomain d = polygon({{0, 0}, {1, 0}, {0, 1}});
  d.points[1].x = std::numeric_limits<double>::infinity();
  d.holes.push_back({std::nan(""), 0});
  d.regions.push_back({{0.1, std::numeric_limits<double>::infinity()}, 3});
  const std::vector<DomainProblem> problems = validate_domain(d);
  ASSERT_EQ(problems.size(), 3u);
  for (const DomainProblem& p : problems) EXPECT_EQ(p.kind, DomainProblemKind::non_finite_coordinate);
  EXPECT_EQ(problems[0].message, "vertex 1 has a non-finite coordinate (inf 0)");
  EXPECT_EQ(problems[1].message, "hole point 0 has a non-finite coordinate (nan 0)");
  EXPECT_TRUE(problems[2].message.starts_with("region point 0"));
}

TEST(dom_DomainValidation, IndexOutOfRangeAndIsolatedVertex) {
  PlanarDomain d = polygon({{0, 0}, {1, 0}, {0, 1}});
  d.points.push_back({5, 5});
  d.segments.push_back({0, 9, 1});
  const std::vector<DomainProblem> problems = validate_domain(d);
  const DomainProblem range = only_problem_of(problems, DomainProblemKind::vertex_index_out_of_range);
  EXPECT_EQ(range.segments, (std::vector<std::uint32_t>{3}));
  EXPECT_EQ(range.vertices, (std::vector<std::uint32_t>{9}));
  // A vertex on no segment is a point the user wants in the mesh (design decision 8).
  EXPECT_EQ(problems.size(), 1u);
}

TEST(dom_DomainValidation, IsolatedVertexInsideASegmentIsAJunction) {
  PlanarDomain d = polygon({{0, 0}, {2, 0}, {0, 2}});
  d.points.push_back({1, 1});      // inside the hypotenuse, exactly
  d.points.push_back({0.5, 0.5});  // inside the triangle: fine
  const std::vector<DomainProblem> problems = validate_domain(d);
  ASSERT_EQ(problems.size(), 1u);
  EXPECT_EQ(problems[0].kind, DomainProblemKind::vertex_on_segment);
  EXPECT_EQ(problems[0].vertices, (std::vector<std::uint32_t>{3}));
  EXPECT_EQ(problems[0].segments, (std::vector<std::uint32_t>{1}));
  EXPECT_NE(problems[0].message.find("vertex 3 (1 1), on no segment, lies inside segment 1"), std::string::npos);
}

TEST(dom_DomainValidation, CapOnTheNumberOfProblems) {
  PlanarDomain d = polygon({{0, 0}, {1, 0}, {0, 1}});
  for (std::uint32_t i = 0; i < 50; ++i) {
    d.points.push_back({10.0 + i, 0});
    d.segments.push_back({3 + i, 3 + i, 0});  // zero length, one problem each
  }
  EXPECT_EQ(validate_domain(d, 16).size(), 16u);
  EXPECT_EQ(validate_domain(d, 100).size(), 50u);
}

TEST(dom_DomainValidation, InvalidDomainWhatNamesTheFirstProblem) {
  const InvalidDomain e({DomainProblem{DomainProblemKind::segments_cross, {1, 2}, {}, "segments 1 and 2 cross"},
                         DomainProblem{DomainProblemKind::isolated_vertex, {}, {4}, "vertex 4 is on no segment"}});
  EXPECT_STREQ(e.what(), "invalid domain: segments 1 and 2 cross (and 1 more problem)");
  EXPECT_STREQ(to_string(DomainProblemKind::open_boundary), "open_boundary");
}

// ---- .poly conversion ----------------------------------------------------------------------

TEST(dom_DomainMeshData, PolyFileRoundTripIsExact) {
  PlanarDomain d = plate_with_holes_and_crack();
  d.regions.push_back({{0.25, 0.25}, 7, 7.0});
  d.regions.push_back({{0.75, 0.25}, 2, 2.0, 0.125});  // a maximum area
  const std::filesystem::path path = std::filesystem::temp_directory_path() / "certimesh_dom_round_trip.poly";
  io::write_mesh(to_mesh_data(d), path);
  const PlanarDomain back = planar_domain_from_mesh_data(io::read_mesh(path));
  std::filesystem::remove(path);
  EXPECT_EQ(back.points, d.points);
  EXPECT_EQ(back.segments, d.segments);
  EXPECT_EQ(back.holes, d.holes);
  EXPECT_EQ(back.regions, d.regions);
}

TEST(dom_DomainMeshData, StructuralRefusals) {
  io::MeshData m;
  m.dimension = 3;
  try {
    planar_domain_from_mesh_data(m);
    ADD_FAILURE();
  } catch (const InvalidDomain& e) {
    EXPECT_EQ(e.problems().front().kind, DomainProblemKind::wrong_dimension);
  }
  m.dimension = 2;
  m.coordinates = {0, 0, 1, 0, 0, 1};
  try {
    planar_domain_from_mesh_data(m);
    ADD_FAILURE();
  } catch (const InvalidDomain& e) {
    EXPECT_EQ(e.problems().front().kind, DomainProblemKind::no_segments);
  }
  m.segments = {0, 1, 1, 2, 2, 3};
  try {
    planar_domain_from_mesh_data(m);
    ADD_FAILURE();
  } catch (const InvalidDomain& e) {
    EXPECT_EQ(e.problems().front().kind, DomainProblemKind::vertex_index_out_of_range);
    EXPECT_EQ(e.problems().front().segments, (std::vector<std::uint32_t>{2}));
  }
  m.segments = {0, 1, 1, 2, 2, 0};
  m.region_points = {0.1, 0.1};
  m.region_attributes = {std::numeric_limits<double>::infinity()};
  try {
    planar_domain_from_mesh_data(m);
    ADD_FAILURE();
  } catch (const InvalidDomain& e) {
    EXPECT_EQ(e.problems().front().kind, DomainProblemKind::bad_region_attribute);
    EXPECT_TRUE(e.problems().front().message.find("inf") != std::string::npos);
  }
  m.region_attributes = {3.0};
  EXPECT_EQ(planar_domain_from_mesh_data(m).regions.front().label, 3);
  // A real attribute (Triangle's 0.05) is kept; the label is then the region's 1-based index.
  m.region_points = {0.1, 0.1, 0.2, 0.1};
  m.region_attributes = {3.0, 0.05};
  m.region_max_measures = {-1.0, 0.01};
  const PlanarDomain real = planar_domain_from_mesh_data(m);
  EXPECT_EQ(real.regions[0].label, 1);
  EXPECT_EQ(real.regions[1].label, 2);
  EXPECT_EQ(real.regions[1].attribute, 0.05);
  EXPECT_EQ(real.regions[0].max_area, -1.0);
  EXPECT_EQ(real.regions[1].max_area, 0.01);
}

// ---- generated domains -----------------------------------------------------------------------

RC_GTEST_PROP(dom_DomainValidationProperty, GeneratedValidDomainsPass, ()) {
  const fuzz::PlanarDomainCase c = *fuzz::valid_planar_domain(400);
  const std::vector<DomainProblem> problems = validate_domain(c.domain);
  for (const DomainProblem& p : problems) RC_LOG() << p.message << "\n";
  RC_ASSERT(problems.empty());
}

RC_GTEST_PROP(dom_DomainValidationProperty, OracleAgreesOnSmallGeneratedDomains, ()) {
  const bool valid = *rc::gen::arbitrary<bool>();
  const fuzz::PlanarDomainCase c = valid ? *fuzz::valid_planar_domain(40) : *fuzz::invalid_planar_domain(40);
  if (c.domain.points.size() > 150) return;  // the cocircular family has a fixed inner ring
  RC_ASSERT(validate_domain(c.domain).empty() == oracle_valid(c.domain));
}

RC_GTEST_PROP(dom_DomainValidationProperty, GeneratedInvalidDomainsAreRefusedWithTheRightKindAndIds, ()) {
  const fuzz::PlanarDomainCase c = *fuzz::invalid_planar_domain(300);
  const std::vector<DomainProblem> problems = validate_domain(c.domain);
  if (c.expected == DomainProblemKind::open_boundary || c.expected == DomainProblemKind::isolated_vertex) {
    // An open loop is decided by the domain triangulation, not here; a vertex on no segment
    // (the mutation puts it outside everything) is valid: the mesher drops it.
    RC_ASSERT(problems.empty());
    return;
  }
  RC_ASSERT(!problems.empty());
  RC_ASSERT(problems.front().kind == c.expected);
  const bool named = std::any_of(problems.begin(), problems.end(), [&](const DomainProblem& p) {
    if (p.kind != c.expected) return false;
    for (const std::uint32_t s : c.segments) {
      if (!contains(p.segments, s) || p.message.find(std::to_string(s)) == std::string::npos) return false;
    }
    for (const std::uint32_t v : c.vertices) {
      if (!contains(p.vertices, v) || p.message.find(std::to_string(v)) == std::string::npos) return false;
    }
    return true;
  });
  RC_ASSERT(named);
}

TEST(dom_DomainValidation, ManySegmentsValidateQuickly) {
  // A disc of kLargeSegments / 2 edges with 100 round holes of kLargeSegments / 200 edges each
  // and one radial crack: short edges, as boundaries to be meshed have. (A spiky random star
  // of 10^5 edges is the bounding-box broad phase's worst case: ~10 s, see docs/domains.md.)
  PlanarDomain d;
  add_curve(d, circle_points({0, 0}, 100, kLargeSegments / 2), 1);
  for (int i = 0; i < 10; ++i) {
    for (int j = 0; j < 10; ++j) {
      const Point2 centre{-54.0 + 12.0 * i, -54.0 + 12.0 * j};
      add_curve(d, circle_points(centre, 4, kLargeSegments / 200), 2);
      d.holes.push_back(centre);
    }
  }
  d.points.push_back({50, 0.5});
  d.points.push_back({90, 0.5});
  d.segments.push_back({static_cast<DomainVertex>(d.points.size() - 2), static_cast<DomainVertex>(d.points.size() - 1), 4});
  const auto start = std::chrono::steady_clock::now();
  EXPECT_TRUE(validate_domain(d).empty());
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  RecordProperty("validate_seconds", std::to_string(seconds));
#if !defined(__SANITIZE_ADDRESS__)
  EXPECT_LT(seconds, 1.0) << d.segments.size() << " segments";
#endif
}

}  // namespace
}  // namespace certimesh::generators
