// The shapes that attain the certificate's worst cases (fuzz/worst_case_meshes.h), small:
// confirmed valid by the rational oracle and plain geometry, certified, and, once broken in
// one place, refused with the defect the break makes. Their timing at 1e5..1e6 elements is
// bench_certificate_worst (bench/RESULTS.md), never a unit test.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/fuzz/worst_case_meshes.h"
#include "certimesh/predicates/intersection/triangle_triangle_3d.h"
#include "mesh_oracle.h"
#include "stages.h"  // detail::first_contact, the 3D embedding check on a triangle soup
#include "vertex_fans.h"  // detail::fan_is_embedded: which fans a case leaves to the z sweep

namespace certimesh::certificate::test {
namespace {

using io::MeshData;

std::string defect_of(const MeshData& m, const MeshData* domain = nullptr) {
  return std::string(defect_name(check_mesh(m, domain).finding.defect));
}

TEST(WorstCaseShapes, StarPolygonFan) {
  MeshData m = fuzz::star_fan_2d(500);
  ASSERT_TRUE(testing::all_elements_positive(m));
  EXPECT_EQ(defect_of(m), "none");
  // A notch moved out along its own ray to radius 1.5, beyond the tips: its boundary edges
  // now reach past its neighbours' but stay in its wedge, so the star is still simple (no
  // false contact among boxes that all overlap).
  m.coordinates[2 * 2] *= 96, m.coordinates[2 * 2 + 1] *= 96;  // vertex 2 is a notch (r = 1/64)
  ASSERT_TRUE(testing::all_elements_positive(m));
  EXPECT_EQ(defect_of(m), "none") << "a notch pulled out along its ray is still a simple star";
  // Reflect one tip across the x axis: two fan triangles turn over.
  MeshData flipped = fuzz::star_fan_2d(500);
  flipped.coordinates[2 * 3 + 1] = -flipped.coordinates[2 * 3 + 1];
  EXPECT_EQ(defect_of(flipped), "inverted_element");
}

// Every segment of a spiked star carries Steiner points rounded off its line by a fraction of
// an ulp: each is on its segment by the rounding-box rule, and pushed 10^-9 outward it is not.
TEST(WorstCaseShapes, SpikedStarWithRoundedSteinerPoints) {
  MeshData domain;
  MeshData m = fuzz::spiked_star_2d(300, 8, domain);
  ASSERT_TRUE(testing::all_elements_positive(m));
  const Report r = check_mesh(m, &domain);
  EXPECT_EQ(defect_name(r.finding.defect), std::string("none")) << r.finding.message;
  EXPECT_GT(r.statistics.vertices_in_rounding_box_only, 2000u);  // most of the 4200 Steiner points
  const io::Index v = 1 + 600 + 3;  // a Steiner point of the first spike
  m.coordinates[2 * v] *= 1 + 1e-9, m.coordinates[2 * v + 1] *= 1 + 1e-9;
  ASSERT_TRUE(testing::all_elements_positive(m));
  EXPECT_EQ(defect_of(m, &domain), "vertex_off_domain_boundary");
}

TEST(WorstCaseShapes, EdgeInManyTetrahedra) {
  const MeshData m = fuzz::book_3d(300);
  ASSERT_TRUE(testing::all_elements_positive(m));
  const Report r = check_mesh(m);
  EXPECT_TRUE(r.valid) << r.finding.message;
  EXPECT_EQ(r.statistics.boundary_facets, 600u);
  MeshData twice = m;  // the same book again, nested: one double cover
  const auto first = static_cast<io::Index>(twice.point_count());
  for (std::size_t i = 0; i < m.coordinates.size(); ++i) twice.coordinates.push_back(m.coordinates[i] * 0.5 + (i % 3 == 2 ? 0x1p-20 : 0));
  for (io::Index v : m.tetrahedra) twice.tetrahedra.push_back(first + v);
  ASSERT_TRUE(testing::all_elements_positive(twice));
  EXPECT_EQ(defect_of(twice), "multiple_cover");
}

TEST(WorstCaseShapes, AHolePointPerHole) {
  MeshData domain;
  const MeshData m = fuzz::holey_grid_2d(21, domain);
  ASSERT_TRUE(testing::all_elements_positive(m));
  EXPECT_EQ(domain.hole_count(), 100u);
  EXPECT_EQ(defect_of(m, &domain), "none");
  MeshData no_hole_point = domain;  // one hole square without its hole point: a region to mesh
  no_hole_point.holes.resize(no_hole_point.holes.size() - 2);
  EXPECT_EQ(defect_of(m, &no_hole_point), "region_not_meshed");
  MeshData inside = domain;  // a hole point moved into a meshed square
  inside.holes[0] += 1;
  EXPECT_EQ(defect_of(m, &inside), "hole_covered");
  MeshData on_edge = domain;  // a hole point on a vertical mesh boundary edge
  on_edge.holes[0] += 0.5;
  EXPECT_EQ(defect_of(m, &on_edge), "hole_covered");
  MeshData on_horizontal = domain;  // on a horizontal one (the sweep line runs along it)
  on_horizontal.holes[1] += 0.5;
  EXPECT_EQ(defect_of(m, &on_horizontal), "hole_covered");
  MeshData at_corner = domain;  // at a corner of a hole square: a mesh vertex
  at_corner.holes[0] += 0.5, at_corner.holes[1] += 0.5;
  EXPECT_EQ(defect_of(m, &at_corner), "hole_covered");
}

TEST(WorstCaseShapes, NestedRings) {
  const MeshData m = fuzz::nested_rings_2d(200);
  ASSERT_TRUE(testing::all_elements_positive(m));
  const Report r = check_mesh(m);
  EXPECT_TRUE(r.valid) << r.finding.message;
  EXPECT_EQ(r.statistics.boundary_components, 400u);
  MeshData filled = m;  // fill the gap between rings 100 and 101 with the same ring twice
  const auto first = static_cast<io::Index>(100 * 8);  // ring 100's vertices
  for (io::Index i = 0; i < 4; ++i) {
    const io::Index a = first + i, b = first + (i + 1) % 4, c = first + 4 + i, d = first + 4 + (i + 1) % 4;
    filled.triangles.insert(filled.triangles.end(), {a, c, d, a, d, b});
  }
  EXPECT_EQ(defect_of(filled), "duplicate_element");
}

// Appends (3 a + b) / 8 and (a + 3 b) / 8 for vertices a, b of m; returns the first new index.
io::Index append_between(MeshData& m, io::Index a, io::Index b) {
  const auto first = static_cast<io::Index>(m.point_count());
  const auto d = static_cast<std::size_t>(m.dimension);
  for (int w : {3, 1})
    for (std::size_t k = 0; k < d; ++k) m.coordinates.push_back((w * m.coordinates[a * d + k] + (4 - w) * m.coordinates[b * d + k]) / 8);
  return first;
}

// k parts pinched at one vertex (design decision 8): 2k boundary edges there, paired by one
// angular sort. Valid alone and against its own boundary as the domain; a second sheet inside
// one part, glued at the pinch, is refused (its edges there leave, leave, enter, enter).
TEST(WorstCaseShapes, PinwheelOfManyParts) {
  const MeshData m = fuzz::pinwheel_2d(500);
  ASSERT_TRUE(testing::all_elements_positive(m));
  const Report r = check_mesh(m);
  EXPECT_TRUE(r.valid) << r.finding.message;
  EXPECT_EQ(r.statistics.boundary_components, 1u) << "paired across the empty wedges: one curve around all parts";
  MeshData domain;
  domain.dimension = 2;
  domain.coordinates = m.coordinates;
  for (std::size_t t = 0; t < m.triangle_count(); ++t)
    for (int i = 0; i < 3; ++i) domain.segments.insert(domain.segments.end(), {m.triangles[3 * t + i], m.triangles[3 * t + (i + 1) % 3]});
  EXPECT_EQ(defect_of(m, &domain), "none");
  MeshData nested = m;  // inside part 0 (0, p0, p1): the triangle (0, (3 p0 + p1) / 8, (p0 + 3 p1) / 8)
  const io::Index first = append_between(nested, 1, 2);
  nested.triangles.insert(nested.triangles.end(), {0, first, first + 1});
  ASSERT_TRUE(testing::all_elements_positive(nested));
  EXPECT_EQ(defect_of(nested), "non_manifold_boundary");
}

// k tetrahedra in every other wedge around one edge: the edge in 2k boundary triangles, paired
// by one sort around it. A tetrahedron nested in one of them on the same edge is refused.
TEST(WorstCaseShapes, OpenBookAroundAnEdge) {
  const MeshData m = fuzz::open_book_3d(300);
  ASSERT_TRUE(testing::all_elements_positive(m));
  const Report r = check_mesh(m);
  EXPECT_TRUE(r.valid) << r.finding.message;
  EXPECT_EQ(r.statistics.boundary_facets, 1200u);
  EXPECT_EQ(r.statistics.boundary_components, 1u) << "paired across the empty wedges: one surface";
  MeshData nested = m;  // (S, (3 r0 + r1) / 8, (r0 + 3 r1) / 8, N): strictly inside page 0 (S, r0, r1, N)
  const io::Index first = append_between(nested, 2, 3);
  nested.tetrahedra.insert(nested.tetrahedra.end(), {0, first, first + 1, 1});
  ASSERT_TRUE(testing::all_elements_positive(nested));
  EXPECT_EQ(defect_of(nested), "non_manifold_boundary");
}

// The cone test's line through the spine S N of an open book whose z coordinates are +-1e308:
// the points it derives (N - S, and S moved along an axis by that length) overflow to
// infinity, and orient3d refused them, so a valid mesh was reported invalid_domain ("a
// predicate refused the input") with no domain given. The fan is left undecided then and
// the box grid decides, as below 32 triangles at a vertex.
TEST(WorstCaseShapes, OpenBookNearTheLargestDouble) {
  for (int k : {10, 11}) {  // 30 and 33 boundary triangles at S: grid only, and a fan
    MeshData m = fuzz::open_book_3d(k);
    for (std::size_t v = 0; v < m.coordinates.size() / 3; ++v) m.coordinates[3 * v + 2] *= 1e308;
    ASSERT_TRUE(testing::all_elements_positive(m));
    const Report r = check_mesh(m);
    EXPECT_TRUE(r.valid) << k << ": " << r.finding.message;
    MeshData doubled = m;  // one more tetrahedron strictly inside page 0: refused (OpenBookAroundAnEdge)
    const io::Index first = append_between(doubled, 2, 3);
    doubled.tetrahedra.insert(doubled.tetrahedra.end(), {0, first, first + 1, 1});
    EXPECT_FALSE(check_mesh(doubled).valid) << k;
  }
}

// A prism over a star polygon against its TetGen domain: two polygonal facets of 2k corners,
// cut by the certificate into long triangles whose boxes overlap (the quadratic case of the
// polygonal facets, proofs/mesh_certificate.md section 6). Certified; the top centre lifted
// 2^-30 off the top facet is refused, and so is the mesh with one wedge left out.
TEST(WorstCaseShapes, PrismOverAStarPolygonFacet) {
  MeshData domain;
  const MeshData m = fuzz::star_prism_3d(60, domain);
  ASSERT_TRUE(testing::all_elements_positive(m));
  EXPECT_EQ(m.tetrahedron_count(), 360u);
  EXPECT_EQ(domain.facets.facet_count(), 122u);
  // Oracle: the tetrahedra's volumes in rationals add up to the star's area (height 1).
  auto q = [](const MeshData& x, io::Index v, int c) { return mpq_class(x.coordinates[3 * v + static_cast<std::size_t>(c)]); };
  mpq_class six_volume = 0, twice_area = 0;
  for (std::size_t t = 0; t < m.tetrahedron_count(); ++t) {
    const io::Index* x = m.tetrahedra.data() + 4 * t;
    mpq_class e[3][3];
    for (int i = 0; i < 3; ++i)
      for (int c = 0; c < 3; ++c) e[i][c] = q(m, x[i + 1], c) - q(m, x[0], c);
    six_volume += e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) - e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
                  e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  }
  for (io::Index i = 0; i < 120; ++i) {  // the top facet's corners 120 .. 239, counterclockwise
    const io::Index a = 120 + i, b = 120 + (i + 1) % 120;
    twice_area += q(domain, a, 0) * q(domain, b, 1) - q(domain, a, 1) * q(domain, b, 0);
  }
  EXPECT_EQ(six_volume, 3 * twice_area);
  const Report r = check_mesh(m, &domain);
  EXPECT_TRUE(r.valid) << r.finding.message;
  MeshData lifted = m;  // mesh vertex 1 is the top centre (0, 0, 1)
  lifted.coordinates[3 * 1 + 2] += 0x1p-30;
  ASSERT_TRUE(testing::all_elements_positive(lifted));
  EXPECT_EQ(defect_of(lifted, &domain), "vertex_off_domain_boundary");
  MeshData notched = m;  // wedge 0's three tetrahedra left out
  notched.tetrahedra.erase(notched.tetrahedra.begin(), notched.tetrahedra.begin() + 12);
  notched.coordinates = m.coordinates;
  ASSERT_TRUE(testing::all_elements_positive(notched));
  EXPECT_EQ(defect_of(notched, &domain), "facet_off_domain_boundary");
}

// The 3D embedding check (detail::first_contact) on triangle soups built around fans of many
// triangles at one vertex, the shapes its cone test and z sweep decide without the box grid
// (proofs/mesh_certificate.md section 6), against the brute-force oracle: every pair tested
// with the exact triangle-triangle predicate (shared ids: the allowed contact).
struct Soup {
  std::vector<double> xyz;
  std::vector<io::Index> tri;
  io::Index point(double x, double y, double z) {
    xyz.insert(xyz.end(), {x, y, z});
    return static_cast<io::Index>(xyz.size() / 3 - 1);
  }
  void add(io::Index a, io::Index b, io::Index c) { tri.insert(tri.end(), {a, b, c}); }
  std::array<predicates::Vertex3, 3> triangle(std::size_t t) const {
    std::array<predicates::Vertex3, 3> r;
    for (int k = 0; k < 3; ++k) {
      const io::Index v = tri[3 * t + static_cast<std::size_t>(k)];
      r[static_cast<std::size_t>(k)] = {{xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]}, v};
    }
    return r;
  }
  bool brute_force_meet() const {
    for (std::size_t i = 0; i < tri.size() / 3; ++i)
      for (std::size_t j = i + 1; j < tri.size() / 3; ++j)
        if (predicates::triangle_triangle_3d(triangle(i), triangle(j), predicates::IntersectionMode::exact) == predicates::Overlap::intersect)
          return true;
    return false;
  }
  bool checker_meet() const {
    detail::MeshView m;
    m.dim = 3;
    m.xyz = xyz.data();
    m.vertex_count = xyz.size() / 3;
    detail::FacetSet set;
    set.dim = 3;
    set.vertices = tri;
    for (std::size_t t = 0; t < tri.size() / 3; ++t) set.owner.push_back(static_cast<std::int64_t>(t));
    return detail::first_contact(m, set, Defect::t_junction, Defect::boundary_intersection, "boundary triangle").defect != Defect::none;
  }
};

// A ring of k points at height z around the z axis, radius r, angles offset by `turn` steps.
std::vector<io::Index> ring(Soup& s, int k, double r, double z, double turn = 0) {
  std::vector<io::Index> ids;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < k; ++i) ids.push_back(s.point(r * std::cos(2 * pi * (i + turn) / k), r * std::sin(2 * pi * (i + turn) / k), z));
  return ids;
}
void fan(Soup& s, io::Index apex, const std::vector<io::Index>& rim, bool closed = true) {
  for (std::size_t i = 0; i + (closed ? 0 : 1) < rim.size(); ++i) s.add(apex, rim[i], rim[(i + 1) % rim.size()]);
}

TEST(WorstCaseShapes, FansDecidedByTheirConesAgreeWithAllPairs) {
  const int k = 48;  // above the cone test's threshold of 32 triangles at a vertex
  auto expect = [](const Soup& s, bool meet, const char* what) {
    ASSERT_EQ(s.brute_force_meet(), meet) << what << ": the oracle";
    EXPECT_EQ(s.checker_meet(), meet) << what;
  };
  {  // book_3d's boundary: the lower and upper fans, meeting only along the chords in z = 0
    Soup s;
    const io::Index south = s.point(0, 0, -1), north = s.point(0, 0, 1);
    const auto r = ring(s, k, 1, 0);
    fan(s, south, r), fan(s, north, r);
    expect(s, false, "book");
    Soup apart = s;  // two more triangles, crossing each other far from the book and its fans
    const io::Index p = apart.point(5, 0, 0), q = apart.point(6, 0, 0), t = apart.point(5, 1, 0);
    apart.add(p, q, t);
    apart.add(apart.point(5.2, 0.2, -1), apart.point(5.3, 0.2, 1), apart.point(5.2, 0.3, 1));
    expect(apart, true, "book and, apart from it, two crossing triangles");
    Soup crossing;  // the upper fan on the same circle turned half a step: chords cross in z = 0 only
    const io::Index a = crossing.point(0, 0, -1), b = crossing.point(0, 0, 1);
    fan(crossing, a, ring(crossing, k, 1, 0)), fan(crossing, b, ring(crossing, k, 1, 0, 0.5));
    expect(crossing, true, "book with its pages meeting only in the plane z = 0");
    Soup inside;  // the upper fan's rim at radius 1/2 in z = 0: touches nothing
    const io::Index c = inside.point(0, 0, -1), d = inside.point(0, 0, 1);
    fan(inside, c, ring(inside, k, 1, 0)), fan(inside, d, ring(inside, k, 0.5, 0, 0.5));
    expect(inside, false, "book whose upper rim lies inside the lower one in z = 0");
  }
  {  // one rim vertex pulled past its neighbour's ray: two fan triangles overlap beyond the apex
    Soup s;
    const io::Index apex = s.point(0, 0, -1);
    const auto r = ring(s, k, 1, 0);
    Soup along = s, outside = s;
    const double pi = std::acos(-1.0);  // vertex 5 moved on the circle to between 6 and 7: chords 4-5 and 6-7 cross
    s.xyz[3 * r[5]] = std::cos(2 * pi * 6.5 / k), s.xyz[3 * r[5] + 1] = std::sin(2 * pi * 6.5 / k);
    fan(s, apex, r);
    expect(s, true, "fan with one pair meeting beyond its apex");
    // Vertex 5 moved out to 1.25 times vertex 7: the wedges around the axis overlap, yet the
    // triangles pass outside one another (the cone test cannot decide it; the grid does).
    outside.xyz[3 * r[5]] = 1.25 * outside.xyz[3 * r[7]], outside.xyz[3 * r[5] + 1] = 1.25 * outside.xyz[3 * r[7] + 1];
    fan(outside, apex, r);
    expect(outside, false, "fan folded over itself without meeting");
    // Rim vertex 5 on the ray from the apex through vertex 7 (1.5 times as far, at z = 1/2):
    // the edges to 5 and 7 overlap along that ray, a contact only at collinear edges.
    along.xyz[3 * r[5]] = 1.5 * along.xyz[3 * r[7]], along.xyz[3 * r[5] + 1] = 1.5 * along.xyz[3 * r[7] + 1], along.xyz[3 * r[5] + 2] = 0.5;
    fan(along, apex, r);
    expect(along, true, "fan with two edges along one ray from its apex");
  }
  {  // a double cone: two fans at one apex, one up, one down, touching only at the apex
    Soup s;
    const io::Index apex = s.point(0, 0, 0);
    fan(s, apex, ring(s, k, 1, 1)), fan(s, apex, ring(s, k, 1, -1));
    expect(s, false, "double cone touching only at its apex");
    Soup same_side;  // both cones up, the inner one steeper: they meet only at the apex too
    const io::Index b = same_side.point(0, 0, 0);
    fan(same_side, b, ring(same_side, k, 1, 1)), fan(same_side, b, ring(same_side, k, 0.5, 1, 0.5));
    expect(same_side, false, "nested cones at one apex");
    Soup crossing;  // the inner cone's rim outside the outer cone on one side: crosses it
    const io::Index c = crossing.point(0, 0, 0);
    fan(crossing, c, ring(crossing, k, 1, 1));
    auto inner = ring(crossing, k, 0.5, 1, 0.5);
    crossing.xyz[3 * inner[3]] *= 3, crossing.xyz[3 * inner[3] + 1] *= 3;
    fan(crossing, c, inner);
    expect(crossing, true, "a cone at the apex leaving the other");
  }
  {  // a flat fan (star_prism_3d's bottom) and one more triangle at its centre in its plane
    Soup s;
    const io::Index centre = s.point(0, 0, 0);
    const auto r = ring(s, k, 1, 0);
    fan(s, centre, r);
    expect(s, false, "flat fan");
    Soup overlap = s;
    overlap.add(centre, r[2], r[4]);  // covers fan triangles 2 and 3: coplanar overlap at the centre
    expect(overlap, true, "coplanar triangles overlapping at the centre");
    Soup open = s;  // the fan open, one more triangle in the gap touching the fan along two edges
    open.tri.resize(open.tri.size() - 6);
    open.add(centre, r[k - 2], r[0]);
    expect(open, false, "flat fan with a wide triangle in its gap");
    Soup through = s;  // a triangle through the plane, meeting the fan only at the centre
    const io::Index up = through.point(0.3, 0.2, 1), down = through.point(0.1, -0.3, 1);
    through.add(centre, up, down);
    expect(through, false, "a triangle standing on the centre");
    const io::Index low = through.point(0.2, 0.1, -1);
    through.add(centre, up, low);  // crosses the fan's plane beyond the centre
    expect(through, true, "a triangle through the fan's plane at its centre");
  }
  {  // open_book_3d's spine: 2k pages on the edge S N and k bottoms and tops
    Soup s;
    const io::Index south = s.point(0, 0, -1), north = s.point(0, 0, 1);
    const auto r = ring(s, 2 * k, 1, 0);
    for (int i = 0; i < k; ++i) {
      const io::Index a = r[static_cast<std::size_t>(2 * i)], b = r[static_cast<std::size_t>(2 * i + 1)];
      s.add(south, north, a), s.add(south, b, north), s.add(south, a, b), s.add(north, b, a);
    }
    expect(s, false, "open book");
    Soup doubled = s;  // one page twice, on one side of the spine: coplanar along the edge
    const io::Index beyond = doubled.point(2 * doubled.xyz[3 * r[0]], 2 * doubled.xyz[3 * r[0] + 1], 0);
    doubled.add(south, north, beyond);
    expect(doubled, true, "two pages on the spine in one half-plane");
  }
  // Random: a fan of k triangles at the origin over a jittered ring on small integers (many
  // ties: collinear rim points, rims in one plane with the apex), some rim points moved at random.
  std::mt19937 rng(12);
  int meeting = 0;
  for (int trial = 0; trial < 60; ++trial) {
    Soup s;
    const io::Index apex = s.point(0, 0, 0);
    std::vector<io::Index> rim;
    const double pi = std::acos(-1.0);
    for (int i = 0; i < k; ++i) {
      const double a = 2 * pi * i / k;
      rim.push_back(s.point(std::round(8 * std::cos(a)), std::round(8 * std::sin(a)), double(rng() % 3) - (trial % 2)));
    }
    for (int moved = static_cast<int>(rng() % 3); moved > 0; --moved) {
      const io::Index v = rim[rng() % rim.size()];
      for (int c = 0; c < 3; ++c) s.xyz[3 * v + static_cast<std::size_t>(c)] = double(static_cast<int>(rng() % 9) - 4);
    }
    fan(s, apex, rim, trial % 3 != 0);
    if (trial % 4 == 0) s.add(apex, rim[rng() % rim.size()], s.point(double(rng() % 5) - 2, double(rng() % 5) - 2, 3));
    const bool meet = s.brute_force_meet();
    meeting += meet;
    EXPECT_EQ(s.checker_meet(), meet) << "random fan " << trial;
  }
  EXPECT_GT(meeting, 5);
  EXPECT_LT(meeting, 55);
}
// How many vertices of the soup in 32 or more triangles the cone test decides: the cases
// below that mean to reach the z sweep check that they do.
int fans_decided(const Soup& s) {
  detail::MeshView m;
  m.dim = 3;
  m.xyz = s.xyz.data();
  m.vertex_count = s.xyz.size() / 3;
  detail::FacetSet set;
  set.dim = 3;
  set.vertices = s.tri;
  std::vector<std::vector<std::size_t>> at(m.vertex_count);
  for (std::size_t t = 0; t < s.tri.size() / 3; ++t)
    for (std::size_t k = 0; k < 3; ++k) at[s.tri[3 * t + k]].push_back(t);
  int decided = 0;
  for (std::size_t v = 0; v < m.vertex_count; ++v)
    decided += at[v].size() >= 32 && detail::fan_is_embedded(m, set, static_cast<io::Index>(v), at[v], [&](std::size_t i, std::size_t j) {
                 return predicates::triangle_triangle_3d(s.triangle(i), s.triangle(j), predicates::IntersectionMode::exact) == predicates::Overlap::intersect;
               });
  return decided;
}

// Attacks on the cone test and the z sweep (an adversarial review of both): shapes where a
// wrong cone or a pair left out of the sweep would accept triangles that meet, each against
// the all-pairs oracle, with the fans the sweep relies on checked to be decided.
TEST(WorstCaseShapes, FanAttacksAgreeWithAllPairs) {
  auto expect = [](const Soup& s, bool meet, const char* what, int decided = -1) {
    ASSERT_EQ(s.brute_force_meet(), meet) << what << ": the oracle";
    if (decided >= 0) {
      ASSERT_EQ(fans_decided(s), decided) << what << ": the fans the case is about";
    }
    EXPECT_EQ(s.checker_meet(), meet) << what;
  };
  const double pi = std::acos(-1.0);
  {  // a rim winding twice around the axis (no wedge order exists): apart, then crossing
    for (double inner : {0.5, 1.0}) {
      Soup s;
      const io::Index apex = s.point(0, 0, 0);
      std::vector<io::Index> rim;
      for (int i = 0; i < 40; ++i) {
        // the second turn half a step on: on the first's circle (its chords cross the first's),
        // or steeper, inside the first cone
        const double r = i < 20 ? 20 : 20 * inner, a = 4 * pi * (i < 20 ? i : i + 0.5) / 40;
        rim.push_back(s.point(std::round(r * std::cos(a)), std::round(r * std::sin(a)), i < 20 || inner == 1.0 ? 4 : 8));
      }
      fan(s, apex, rim, false);
      expect(s, inner == 1.0, inner == 1.0 ? "helix fan, second turn crossing the first" : "helix fan, second turn inside the first", 0);
    }
  }
  {  // a double cone with the lower rim reversed: the summed normal is exactly 0, no spine
    Soup s;
    const io::Index apex = s.point(0, 0, 0);
    auto down = ring(s, 24, 16, -5);
    std::reverse(down.begin(), down.end());
    fan(s, apex, ring(s, 24, 16, 5)), fan(s, apex, down);
    expect(s, false, "double cone, summed normal 0", 0);
    s.xyz[3 * down[3] + 2] = 6;  // a lower rim vertex pulled up through the upper cone
    expect(s, true, "double cone, summed normal 0, one lower triangle through the upper cone");
  }
  for (int k : {31, 32}) {  // at the threshold: a cone with one rim vertex past its neighbour's ray
    Soup s;
    const io::Index apex = s.point(0, 0, 0);
    const auto r = ring(s, k, 30, 6);
    s.xyz[3 * r[5]] = std::round(30 * std::cos(2 * pi * 6.5 / k)), s.xyz[3 * r[5] + 1] = std::round(30 * std::sin(2 * pi * 6.5 / k));
    fan(s, apex, r);
    expect(s, true, k == 31 ? "31 triangles, two crossing beyond the apex" : "32 triangles, two crossing beyond the apex", 0);
  }
  {  // two cones, the second's apex on the first's rim edge, where the first ends in z and the
     // second starts (a pair only the plane z = 4 holds); then half a unit outward
    for (double out : {0.0, 0.5}) {
      Soup s;
      const io::Index a = s.point(0, 0, 0);
      const auto r = ring(s, 40, 1, 4);
      for (io::Index v : r) s.xyz[3 * v] = std::round(20 * s.xyz[3 * v]), s.xyz[3 * v + 1] = std::round(20 * s.xyz[3 * v + 1]);
      fan(s, a, r);
      const double mx = (s.xyz[3 * r[0]] + s.xyz[3 * r[1]]) / 2 + out, my = (s.xyz[3 * r[0] + 1] + s.xyz[3 * r[1] + 1]) / 2;
      const io::Index b = s.point(mx, my, 4);
      const auto r2 = ring(s, 40, 1, 8);
      for (io::Index v : r2) s.xyz[3 * v] = mx + std::round(20 * s.xyz[3 * v]), s.xyz[3 * v + 1] = my + std::round(20 * s.xyz[3 * v + 1]);
      fan(s, b, r2);
      expect(s, out == 0, out == 0 ? "a cone's apex on another's rim edge in z = 4" : "a cone's apex beside another's rim edge in z = 4", 2);
    }
  }
  {  // a triangle ending at z = 0 whose top edge passes through a cone's apex (no shared id),
     // then lowered by half a unit
    for (double low : {0.0, -0.5}) {
      Soup s;
      const io::Index apex = s.point(0, 0, 0);
      fan(s, apex, ring(s, 40, 20, 5));
      s.add(s.point(-3, -2, low), s.point(3, 2, low), s.point(1, 0, -4));
      expect(s, low == 0, low == 0 ? "a triangle's top edge through a cone's apex" : "a triangle's top edge under a cone's apex", 1);
    }
  }
  {  // a flat fan in z = 0 and triangles meeting its plane from below: crossing a fan triangle,
     // touching a rim edge at its midpoint, and touching nothing
    Soup s;
    const io::Index centre = s.point(0, 0, 0);
    const auto r = ring(s, 40, 1, 0);
    for (io::Index v : r) s.xyz[3 * v] = std::round(20 * s.xyz[3 * v]), s.xyz[3 * v + 1] = std::round(20 * s.xyz[3 * v + 1]);
    fan(s, centre, r);
    Soup cross = s, touch = s, apart = s;
    cross.add(cross.point(5, 1, 0), cross.point(9, 2, 0), cross.point(7, 1, -3));
    expect(cross, true, "a triangle's top edge across a flat fan", 1);
    const double mx = (s.xyz[3 * r[7]] + s.xyz[3 * r[8]]) / 2, my = (s.xyz[3 * r[7] + 1] + s.xyz[3 * r[8] + 1]) / 2;
    touch.add(touch.point(mx, my, 0), touch.point(2 * mx, 2 * my, -1), touch.point(2 * mx, 2 * my + 1, -3));
    expect(touch, true, "a triangle touching a flat fan's rim edge at its midpoint", 1);
    apart.add(apart.point(1.1 * mx, 1.1 * my, 0), apart.point(2 * mx, 2 * my, -1), apart.point(2 * mx, 2 * my + 1, -3));
    expect(apart, false, "a triangle touching the flat fan's plane beside it", 1);
  }
  {  // pages on a spine S N, and a triangle at S whose plane holds the line S N: downward
     // (meets nothing, but no wedge: the fan stays undecided), upward (overlaps the spine edge)
    for (double dir : {-1.0, 1.0}) {
      Soup s;
      const io::Index south = s.point(0, 0, 0), north = s.point(0, 0, 10);
      const auto r = ring(s, 40, 20, 0);
      for (std::size_t i = 0; i < r.size(); i += 2) s.add(south, north, r[i]);
      fan(s, south, r);
      s.add(south, s.point(0, 0, 20 * dir), s.point(3, 1, 20 * dir));
      expect(s, dir > 0, dir > 0 ? "a triangle along the spine edge" : "a triangle on the spine's line, away from the spine", 0);
    }
  }
  {  // one rim point twice (same coordinates, two ids): the fan's triangles touch there
    Soup s;
    const io::Index apex = s.point(0, 0, 0);
    auto r = ring(s, 40, 20, 5);
    fan(s, apex, r);
    const std::size_t t = 3 * 7 + 2;  // triangle 7 is (apex, r7, r8): r8 by a copy
    s.tri[t] = s.point(s.xyz[3 * r[8]], s.xyz[3 * r[8] + 1], s.xyz[3 * r[8] + 2]);
    expect(s, true, "a rim point twice, with two ids");
  }
  {  // a cone's apex inside a flat triangle in z = 0 (a T-junction at the apex)
    Soup s;
    const io::Index apex = s.point(0, 0, 0);
    fan(s, apex, ring(s, 40, 20, 5));
    s.add(s.point(-3, -2, 0), s.point(3, -2, 0), s.point(0, 3, 0));
    expect(s, true, "a cone's apex inside a flat triangle", 1);
  }
  // Random: a decided cone (or flat fan) and one more triangle with a vertex exactly on a fan
  // triangle (at a vertex, an edge's midpoint, an interior point), sometimes moved half a
  // unit, its other vertices on one side of that z or in its plane: ties the sweep's plane
  // pieces must catch.
  std::mt19937 rng(7);
  int meeting = 0;
  for (int trial = 0; trial < 40; ++trial) {
    Soup s;
    const io::Index apex = s.point(0, 0, 0);
    const auto r = ring(s, 36, 1, trial % 3 == 0 ? 0 : 3);
    for (io::Index v : r) s.xyz[3 * v] = std::round(16 * s.xyz[3 * v]), s.xyz[3 * v + 1] = std::round(16 * s.xyz[3 * v + 1]);
    fan(s, apex, r);
    const io::Index* t = &s.tri[3 * (rng() % 36)];
    double p[3];
    const auto where = rng() % 3;
    for (std::size_t c = 0; c < 3; ++c) {
      const double a = s.xyz[3 * t[0] + c], b = s.xyz[3 * t[1] + c], d = s.xyz[3 * t[2] + c];
      p[c] = where == 0 ? b : where == 1 ? (b + d) / 2 : (a + b + 2 * d) / 4;
    }
    if (rng() % 3 == 0) p[rng() % 3] += rng() % 2 ? 0.5 : -0.5;
    const double side = double(rng() % 3) - 1;  // the other vertices below, in, or above z = p's
    auto off = [&](std::size_t c) { return c == 2 ? p[2] + side * double(rng() % 4) : p[c] + double(rng() % 9) - 4; };
    const io::Index q = s.point(off(0), off(1), off(2)), w = s.point(off(0), off(1), off(2));
    s.add(s.point(p[0], p[1], p[2]), q, w);
    const bool meet = s.brute_force_meet();
    meeting += meet;
    ASSERT_EQ(fans_decided(s), 1) << "random touch " << trial;
    EXPECT_EQ(s.checker_meet(), meet) << "random touch " << trial;
  }
  EXPECT_GT(meeting, 5);
  EXPECT_LT(meeting, 38);
}
}  // namespace
}  // namespace certimesh::certificate::test
