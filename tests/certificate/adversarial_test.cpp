// Meshes built to fool the certificate (issue 12): rounding slack that joins two domain
// components, a floating-point sum whose error bound ignores underflow, and statistics that
// overflow. Every mesh here is first confirmed with the GMP oracle (element signs, exact
// areas) and by plain geometry, independently of the checker; then the checker is asked.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/fuzz/valid_meshes.h"
#include "certimesh/fuzz/worst_case_meshes.h"
#include "mesh_oracle.h"
#include "pinch_meshes.h"
#include "unit_meshes.h"

namespace certimesh::certificate::test {
namespace {

// Twice the signed area of the triangle (a, b, c) of a 2D mesh, exactly.
mpq_class twice_area(const MeshData& m, Index a, Index b, Index c) {
  auto q = [&](Index v, int k) { return mpq_class(m.coordinates[2 * v + k]); };
  return (q(b, 0) - q(a, 0)) * (q(c, 1) - q(a, 1)) - (q(b, 1) - q(a, 1)) * (q(c, 0) - q(a, 0));
}

// The exact area of a 2D mesh (sum of its triangles) and of a polygon given by vertex ids.
mpq_class mesh_area(const MeshData& m) {
  mpq_class sum = 0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) sum += twice_area(m, m.triangles[3 * t], m.triangles[3 * t + 1], m.triangles[3 * t + 2]);
  return sum / 2;
}
mpq_class polygon_area(const MeshData& m, const std::vector<Index>& loop) {
  mpq_class sum = 0;
  for (std::size_t i = 1; i + 1 < loop.size(); ++i) sum += twice_area(m, loop[0], loop[i], loop[i + 1]);
  return sum / 2;
}

// The domain: the quad A(0,0) B(6,2) C(6,4) D(0,4), whose bottom segment S = AB has slope 1/3,
// and a second component whose two top vertices w1 = (1, fl(1/3)) and w2 = (4, fl(4/3)) lie
// strictly below S (fl rounds 1/3 and 4/3 down) but inside S's rounding box: a U with a notch
// w2 -> c -> w1. The mesh covers both components and the notch region between them, which is
// outside the domain, and its boundary runs A -> w1 -> d1 -> d2 -> w2 -> B: it hops onto the
// second component at w1 and back at w2, through S's rounding box.
MeshData hop_mesh() {
  MeshData m;
  append(m.coordinates, {0, 0, 6, 2, 6, 4, 0, 4, 1, 1.0 / 3, 1, -3, 4, -3, 4, 4.0 / 3, 2.5, -1});
  append(m.triangles, {0, 4, 3, 4, 7, 3, 7, 1, 2, 7, 2, 3,  // the quad, above S
                       4, 8, 7,                             // the notch, outside the domain
                       4, 5, 8, 5, 6, 8, 6, 7, 8});         // the U
  return m;
}
MeshData hop_domain() {
  MeshData d = hop_mesh();
  d.triangles.clear();
  append(d.segments, {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 8, 8, 4});
  return d;
}

TEST(CertificateAdversary, RoundingSlackMustNotJoinComponents) {
  const MeshData m = hop_mesh(), d = hop_domain();
  ASSERT_TRUE(testing::all_elements_positive(m));
  // w1 and w2 are strictly below S: the two components do not touch.
  ASSERT_LT(twice_area(m, 0, 1, 4), 0);
  ASSERT_LT(twice_area(m, 0, 1, 7), 0);
  // The mesh covers 2.75 more than the domain: the notch triangle (w1, c, w2) of that area
  // (and two slivers of about 1e-16 between S and A-w1-w2-B).
  const mpq_class domain_area = polygon_area(d, {0, 1, 2, 3}) + polygon_area(d, {4, 5, 6, 7, 8});
  ASSERT_GT(polygon_area(m, {4, 8, 7}), mpq_class(27, 10));
  ASSERT_GT(mesh_area(m) - domain_area, mpq_class(27, 10));
  EXPECT_TRUE(check_mesh(m).valid) << "on its own the mesh is a valid tiling";
  const Report r = check_mesh(m, &d);
  EXPECT_FALSE(r.valid);
  EXPECT_EQ(defect_name(r.finding.defect), defect_name(Defect::facet_off_domain_boundary)) << r.finding.message;
  // A boundary tolerance widens the rule for Steiner points, never for domain vertices.
  CheckOptions loose;
  loose.boundary_tolerance.absolute = 1e-6;
  EXPECT_FALSE(check_mesh(m, &d, loose).valid);
}

// A sub-ulp gap between two segments that never touch: S = AB as above, and T from
// t0 = (1, fl(1/3)) to t1 = (4, fl(4/3)), the top of a second component below S. The mesh
// fills the gap between them with two sliver triangles whose outer vertices p (above t0) and
// q (near t1) lie in the rounding boxes of both S and T, so every boundary facet has both ends
// on one domain segment; the mesh still joins what the domain keeps apart.
MeshData gap_mesh() {
  MeshData m;
  append(m.coordinates, {0, 0, 6, 2, 6, 4, 0, 4, 1, 1.0 / 3, 1, -2, 4, -2, 4, 4.0 / 3,
                         1, 0x1.5555555555556p-2, 0x1.fffffffffffffp+1, 0x1.5555555555555p+0});
  append(m.triangles, {0, 8, 3, 8, 9, 3, 9, 1, 2, 9, 2, 3,  // above S
                       8, 4, 7, 8, 7, 9,                    // the gap
                       4, 5, 6, 4, 6, 7});                  // below T
  return m;
}

TEST(CertificateAdversary, SubUlpGapMustNotBeBridged) {
  const MeshData m = gap_mesh();
  MeshData d = m;
  d.triangles.clear();
  d.coordinates.resize(16);  // the domain has no p, q
  append(d.segments, {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 7, 7, 4});
  ASSERT_TRUE(testing::all_elements_positive(m));
  ASSERT_LT(twice_area(m, 0, 1, 4), 0) << "t0 below S";
  ASSERT_LT(twice_area(m, 0, 1, 7), 0) << "t1 below S";
  ASSERT_TRUE(check_mesh(m).valid);
  const Report r = check_mesh(m, &d);
  EXPECT_FALSE(r.valid) << "the mesh joins the two components across their gap";
  EXPECT_EQ(defect_name(r.finding.defect), defect_name(Defect::domain_boundary_not_covered)) << r.finding.message;
}

// The triangle (0,0) (3,0) (0,1) scaled by 2^s, and a mesh of it with a vertex at the rounding
// of the exact point (2, 1/3) of its segment (3,0)-(0,1).
struct RoundedSplit {
  MeshData mesh, domain;
  explicit RoundedSplit(int s) {
    for (double x : {0.0, 0.0, 3.0, 0.0, 2.0, 1.0 / 3.0, 0.0, 1.0}) mesh.coordinates.push_back(std::ldexp(x, s));
    append(mesh.triangles, {0, 1, 2, 0, 2, 3});
    for (double x : {0.0, 0.0, 3.0, 0.0, 0.0, 1.0}) domain.coordinates.push_back(std::ldexp(x, s));
    append(domain.segments, {0, 1, 1, 2, 2, 0});
  }
};

// The measured area differs from the domain's by less than the bound, both reported.
TEST(CertificateAdversary, MeasureDifferenceIsBoundedAndReported) {
  for (int s : {0, 400, -400}) {
    const RoundedSplit split(s);
    const MeshData &m = split.mesh, &d = split.domain;
    const Report r = check_mesh(m, &d);
    ASSERT_TRUE(r.valid) << r.finding.message;
    const mpq_class exact = mesh_area(m) - polygon_area(d, {0, 1, 2});  // oracle
    ASSERT_NE(exact, 0);
    EXPECT_EQ(r.statistics.measure_difference, exact.get_d()) << "scale 2^" << s;
    EXPECT_GE(r.statistics.measure_difference_bound, std::abs(r.statistics.measure_difference));
    EXPECT_LT(r.statistics.measure_difference_bound, std::ldexp(1e-15, 2 * s));
    EXPECT_EQ(r.statistics.domain_measure, std::ldexp(1.5, 2 * s));
  }
}

// The bound on the area between the mesh boundary and the domain (6d) against its definition in
// rationals: per domain segment ab with chain p_0 = a .. p_k = b, the trapezoids
// |(q - p).u| (|u x (p - a)| + |u x (q - a)|) / (2 |u|^2), u = b - a. The reported bound is at
// least that sum (it may round up, within 2^-40 relative) at scales where the certificate
// bounds each chain in double (2^0, 2^-100) and where it takes the exact quotient (2^-250,
// 2^300: parts outside [2^-480, 2^480]). Mesh: a small spiked star whose Steiner points are
// rounded off their segments (fuzz/worst_case_meshes.h: vertex 0 the centre, then the 2k
// corners, then per spike the left and right Steiner points in turn).
TEST(CertificateAdversary, MeasureBoundIsTheTrapezoidsRoundedUp) {
  const int k = 40, n = 7;
  for (int scale : {0, -100, -250, 300}) {
    MeshData d;
    MeshData m = certimesh::fuzz::spiked_star_2d(k, n, d);
    for (double& x : m.coordinates) x = std::ldexp(x, scale);  // exact: no overflow, no subnormals
    for (double& x : d.coordinates) x = std::ldexp(x, scale);
    const Report r = check_mesh(m, &d);
    ASSERT_TRUE(r.valid) << r.finding.message;
    ASSERT_GT(r.statistics.vertices_in_rounding_box_only, 0u);
    auto q = [&](Index v, int c) { return mpq_class(m.coordinates[2 * v + c]); };
    mpq_class want = 0;
    for (int i = 0; i < k; ++i) {
      const Index notch = static_cast<Index>(1 + 2 * i), tip = notch + 1, next = static_cast<Index>(1 + (2 * i + 2) % (2 * k));
      const Index first = static_cast<Index>(1 + 2 * k + i * 2 * (n - 1));
      for (int side = 0; side < 2; ++side) {
        std::vector<Index> chain{side == 0 ? notch : next};
        for (int j = 1; j < n; ++j) chain.push_back(first + static_cast<Index>(2 * (j - 1) + side));
        chain.push_back(tip);
        const Index a = chain.front(), b = chain.back();
        const mpq_class ux = q(b, 0) - q(a, 0), uy = q(b, 1) - q(a, 1), uu = ux * ux + uy * uy;
        auto off = [&](Index p) -> mpq_class { return abs(ux * (q(p, 1) - q(a, 1)) - uy * (q(p, 0) - q(a, 0))); };
        for (std::size_t e = 0; e + 1 < chain.size(); ++e) {
          const Index p = chain[e], r2 = chain[e + 1];
          want += abs((q(r2, 0) - q(p, 0)) * ux + (q(r2, 1) - q(p, 1)) * uy) * (off(p) + off(r2)) / (2 * uu);
        }
      }
    }
    ASSERT_GT(want, 0);
    EXPECT_GE(mpq_class(r.statistics.measure_difference_bound), want) << "scale 2^" << scale;
    EXPECT_LE(mpq_class(r.statistics.measure_difference_bound), want * (1 + mpq_class(1, 1L << 40))) << "scale 2^" << scale;
  }
}

// The domain's area is summed exactly even when one polygon mixes exponents 1000 apart (the
// sum is kept in units of its smallest product, not rounded per term).
TEST(CertificateAdversary, DomainMeasureIsExactAcrossExponents) {
  MeshData m;
  m.dimension = 2;
  const double big = std::ldexp(1.0, 500), small = std::ldexp(3.0, -500);
  m.coordinates = {0, 0, big, 0, big, small, 0, 1};
  m.triangles = {0, 1, 2, 0, 2, 3};  // a convex quadrilateral fanned from vertex 0
  MeshData d = m;
  d.triangles.clear();
  d.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  const Report r = check_mesh(m, &d);
  ASSERT_TRUE(r.valid) << r.finding.message;
  const mpq_class exact = polygon_area(d, {0, 1, 2, 3});  // oracle: the shoelace sum in rationals
  EXPECT_EQ(exact, mesh_area(m));
  EXPECT_EQ(r.statistics.domain_measure, exact.get_d());
  EXPECT_EQ(r.statistics.measure, exact.get_d());
  EXPECT_EQ(r.statistics.measure_difference, 0.0);
}

// The rounding-box rule (design decision 2) at the edge of the box: a triangle split at a
// vertex v near the middle of its side BC, v the rounding of a point of BC moved by -2..2 ulps
// per coordinate, at scales 2^-1000 to 2^1000 and for sides of every slope sign (and axis-
// parallel ones). The mesh is valid exactly when BC meets v's rounding box. Oracle: the box's
// ends as rationals (half-way to the neighbouring doubles) and the sign of the line's equation
// at its four corners, plus the axis ranges.
bool side_meets_rounding_box(const double* b, const double* c, const double* v) {
  mpq_class lo[2], hi[2];
  for (int k = 0; k < 2; ++k) {
    const double below = std::nextafter(v[k], -INFINITY), above = std::nextafter(v[k], INFINITY);
    lo[k] = std::isfinite(below) ? (mpq_class(v[k]) + mpq_class(below)) / 2 : mpq_class(v[k]);
    hi[k] = std::isfinite(above) ? (mpq_class(v[k]) + mpq_class(above)) / 2 : mpq_class(v[k]);
    if (mpq_class(std::max(b[k], c[k])) < lo[k] || mpq_class(std::min(b[k], c[k])) > hi[k]) return false;
  }
  int negative = 0, positive = 0;
  for (int corner = 0; corner < 4; ++corner) {
    const mpq_class x = corner & 1 ? hi[0] : lo[0], y = corner & 2 ? hi[1] : lo[1];
    const mpq_class f = (mpq_class(c[0]) - b[0]) * (y - b[1]) - (mpq_class(c[1]) - b[1]) * (x - b[0]);
    negative += f < 0, positive += f > 0;
  }
  return negative < 4 && positive < 4;
}

TEST(CertificateAdversary, RoundingBoxRuleAtTheEdgeOfTheBox) {
  std::mt19937_64 random(12);
  std::uniform_real_distribution<double> unit(0.25, 1.0);
  int accepted = 0, refused = 0;
  for (int trial = 0; trial < 600; ++trial) {
    const int s = std::vector<int>{0, 7, -30, 1000, -1000, 500}[static_cast<std::size_t>(trial % 6)];
    const int slope = trial / 6 % 4;  // BC falling, rising, horizontal, vertical
    double bx = 1, by = 0, cx = 0, cy = 1;
    if (slope == 1) bx = 0, by = 0, cx = 1, cy = 1;
    if (slope == 2) bx = 1, by = 0.5, cx = 0, cy = 0.5;
    if (slope == 3) bx = 0.5, by = 0, cx = 0.5, cy = 1;
    const double kb = unit(random), kc = unit(random);
    MeshData m;
    m.dimension = 2;
    // A = the corner off BC; B or C moved along one coordinate: BC has a random slope.
    const double ax = slope == 1 ? 1 : 0, ay = 0;
    const double b0 = std::ldexp(bx * (slope == 0 ? 1 + kb : 1), s), b1 = std::ldexp(by, s);
    const double c0 = std::ldexp(cx, s), c1 = std::ldexp(cy * (slope == 3 || slope == 2 ? 1 : 1 + kc), s);
    const double t = 0.3 + 0.4 * unit(random);
    double v[2] = {b0 + (c0 - b0) * t, b1 + (c1 - b1) * t};
    for (double& x : v) {
      const int ulps = static_cast<int>(random() % 5) - 2;
      for (int i = 0; i < std::abs(ulps); ++i) x = std::nextafter(x, ulps > 0 ? INFINITY : -INFINITY);
    }
    m.coordinates = {std::ldexp(ax, s), std::ldexp(ay, s), b0, b1, c0, c1, v[0], v[1]};
    if (twice_area(m, 0, 1, 2) < 0) std::swap(m.coordinates[2], m.coordinates[4]), std::swap(m.coordinates[3], m.coordinates[5]);
    m.triangles = {0, 1, 3, 0, 3, 2};
    ASSERT_GT(twice_area(m, 0, 1, 3), 0);
    ASSERT_GT(twice_area(m, 0, 3, 2), 0);
    MeshData d = m;
    d.triangles.clear();
    d.coordinates.resize(6);
    d.segments = {0, 1, 1, 2, 2, 0};
    const bool expected = side_meets_rounding_box(&m.coordinates[2], &m.coordinates[4], v);
    const Report r = check_mesh(m, &d);
    EXPECT_EQ(r.valid, expected) << "trial " << trial << ": " << r.finding.message;
    (expected ? accepted : refused) += 1;
  }
  EXPECT_GT(accepted, 100);  // both answers occur
  EXPECT_GT(refused, 100);
}

// Statistics at coordinates near 2^900 and 2^-1000: the deviation of the rounded vertex scales
// with the mesh (it used to read 0: squares overflowed or underflowed).
TEST(CertificateAdversary, DeviationDoesNotOverflowOrUnderflow) {
  auto deviation_at = [](int s) {
    const RoundedSplit split(s);
    const Report r = check_mesh(split.mesh, &split.domain);
    EXPECT_TRUE(r.valid) << r.finding.message;
    return r.statistics.max_boundary_deviation;
  };
  // The exact distance of (2, fl(1/3)) to the line x + 3y = 3 is |3 fl(1/3) - 1| / sqrt(10).
  const double expected = std::abs(mpq_class(mpq_class(1.0 / 3.0) * 3 - 1).get_d()) / std::sqrt(10.0);
  ASSERT_GT(expected, 0);
  EXPECT_DOUBLE_EQ(deviation_at(0), expected);
  EXPECT_NEAR(deviation_at(900) / std::ldexp(expected, 900), 1.0, 1e-12);
  EXPECT_NEAR(deviation_at(-1000) / std::ldexp(expected, -1000), 1.0, 1e-4);  // subnormal: fewer digits
}

// One positive tetrahedron whose enclosed-volume sum has a 2x2 minor that underflows and is
// then multiplied by 2^100: det = 2^100 * 2^-1080 - 2^-441 * 2^-540 = 2^-981 > 0, while the
// double evaluation gives -2^-981. Vertex 0 is the reference point of the sum.
std::vector<double> sliver(int s) {
  std::vector<double> x{0, 0, 0, 0x1p100, 0x1p-441, 0, 1, 0x1p-540, 0, 0, 0, 0x1p-540};
  for (double& c : x) c = std::ldexp(c, s);
  return x;
}

TEST(CertificateAdversary, UnderflowInTheEnclosedVolume) {
  for (int s : {0, -300, -530, 400}) {
    MeshData m = simplices(3, {sliver(s)});
    ASSERT_TRUE(testing::all_elements_positive(m)) << "scale 2^" << s;
    const Report r = check_mesh(m);
    EXPECT_TRUE(r.valid) << "scale 2^" << s << ": " << r.finding.message;
  }
}

TEST(CertificateAdversary, UnderflowCannotHideADoubleCover) {
  for (int s : {0, -300, -530, 400}) {
    MeshData m = kuhn_grid(1);  // the cube [-2^(101+s), 2^(101+s)]^3 around the sliver
    for (double& c : m.coordinates) c = std::ldexp(2 * c - 1, 101 + s);
    const auto first = static_cast<Index>(m.point_count());
    for (double c : sliver(s)) m.coordinates.push_back(c);
    append(m.tetrahedra, {first, first + 1, first + 2, first + 3});
    ASSERT_TRUE(testing::all_elements_positive(m));
    const Report r = check_mesh(m);
    EXPECT_EQ(defect_name(r.finding.defect), defect_name(Defect::multiple_cover)) << "scale 2^" << s << ": " << r.finding.message;
  }
}

// ---- Pinches (issue 12 item 5, design decision 8): the neighbours of each valid pinch that an
// adversary would try. The valid pinches themselves are in valid_meshes_test.cpp.

std::string defect_of(const MeshData& m, const MeshData* domain = nullptr) {
  return std::string(defect_name(check_mesh(m, domain).finding.defect));
}

// Whether point p of m lies in the closed triangle (a, b, c) of m, exactly.
bool in_triangle(const MeshData& m, Index p, Index a, Index b, Index c) {
  return twice_area(m, a, b, p) >= 0 && twice_area(m, b, c, p) >= 0 && twice_area(m, c, a, p) >= 0;
}

// Two sheets glued at a vertex covering an area twice. A triangle inside another, sharing a
// corner: the boundary edges at that corner leave, leave, enter, enter (counterclockwise), so
// no pairing closes curves with the mesh on one side. Two fans around one centre, one inside the
// other: the centre is interior to both, the boundary two disjoint loops, W = 2 inside the
// small one.
TEST(CertificateAdversary, TwoSheetsGluedAtAVertex2d) {
  MeshData nested;
  nested.dimension = 2;
  append(nested.coordinates, {0, 0, 4, 0, 0, 4, 2, 1, 1, 2});
  append(nested.triangles, {0, 1, 2, 0, 3, 4});
  ASSERT_TRUE(testing::all_elements_positive(nested));
  ASSERT_TRUE(in_triangle(nested, 3, 0, 1, 2) && in_triangle(nested, 4, 0, 1, 2)) << "the small sheet lies in the big one";
  EXPECT_EQ(defect_of(nested), "non_manifold_boundary");
  MeshData fans;
  fans.dimension = 2;
  append(fans.coordinates, {0, 0, 2, 0, 0, 2, -2, 0, 0, -2, 0.5, 0.5, -0.5, 0.5, -0.5, -0.5, 0.5, -0.5});
  for (Index i = 0; i < 4; ++i) append(fans.triangles, {0, 1 + i, 1 + (i + 1) % 4, 0, 5 + i, 5 + (i + 1) % 4});
  ASSERT_TRUE(testing::all_elements_positive(fans));
  ASSERT_GT(twice_area(fans, 1, 2, 5), 0) << "the small fan's ring lies strictly inside the big one's";
  EXPECT_EQ(defect_of(fans), "multiple_cover");
}

// The same in 3D: a small tetrahedron inside a big one sharing a vertex (winding 2 in it), and
// sharing an edge (the four boundary triangles around the edge do not alternate).
TEST(CertificateAdversary, TwoSheetsGluedAtAVertexOrEdge3d) {
  MeshData at_vertex = simplices(3, {{0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4}});
  append(at_vertex.coordinates, {1, 1, 0.5, 0.5, 1, 1, 1, 0.5, 1});
  append(at_vertex.tetrahedra, {0, 4, 5, 6});
  if (det3(at_vertex, &at_vertex.tetrahedra[4]) < 0) std::swap(at_vertex.tetrahedra[5], at_vertex.tetrahedra[6]);
  ASSERT_TRUE(testing::all_elements_positive(at_vertex));
  EXPECT_EQ(defect_of(at_vertex), "multiple_cover");
  MeshData at_edge = simplices(3, {{0, 0, 0, 4, 0, 0, 0, 4, 0, 0, 0, 4}});
  append(at_edge.coordinates, {1, 1, 0.5, 1, 0.5, 1});
  append(at_edge.tetrahedra, {0, 1, 4, 5});
  if (det3(at_edge, &at_edge.tetrahedra[4]) < 0) std::swap(at_edge.tetrahedra[6], at_edge.tetrahedra[7]);
  ASSERT_TRUE(testing::all_elements_positive(at_edge));
  EXPECT_EQ(defect_of(at_edge), "non_manifold_boundary");
}

// A bow-tie whose elements pass through the pinch: the unit square at the origin and a triangle
// with an edge from the shared corner into the square (it overlaps the square's corner); and a
// triangle whose edge passes through the square's corner without having it as a vertex.
TEST(CertificateAdversary, ElementsThroughThePinch) {
  MeshData into;
  into.dimension = 2;
  append(into.coordinates, {0, 0, 1, 0, 1, 1, 0, 1, 0.5, 2, -1, 0});
  append(into.triangles, {0, 1, 2, 0, 2, 3, 0, 4, 5});
  ASSERT_TRUE(testing::all_elements_positive(into));
  ASSERT_GT(twice_area(into, 0, 4, 3), 0) << "the triangle's edge 0-4 enters the square's corner";
  EXPECT_EQ(defect_of(into), "non_manifold_boundary");
  MeshData through;
  through.dimension = 2;
  append(through.coordinates, {0, 0, 1, 0, 1, 1, 0, 1, 1, -1, -1, 1, -1, -1});
  append(through.triangles, {0, 1, 2, 0, 2, 3, 4, 5, 6});
  ASSERT_TRUE(testing::all_elements_positive(through));
  ASSERT_EQ(twice_area(through, 4, 5, 0), 0) << "the corner lies on the triangle's edge";
  EXPECT_EQ(defect_of(through), "t_junction");
}

// Two squares sharing a corner against their domain: one part missing; a part doubled (a copy
// on new vertices with the same coordinates, a copy shrunk about the pinch, a copy shrunk
// about its own centre).
TEST(CertificateAdversary, PinchedPartMissingOrDoubled) {
  const MeshData both = kept_squares(2, [](int i, int j) { return i == j; });
  const MeshData domain = boundary_as_domain(both);
  ASSERT_TRUE(check_mesh(both, &domain).valid);
  const MeshData one = kept_squares(2, [](int i, int j) { return i == 0 && j == 0; });
  EXPECT_EQ(defect_of(one, &domain), "domain_boundary_not_covered");
  Index pinch = 0;  // the vertex (1, 1)
  while (both.coordinates[2 * pinch] != 1 || both.coordinates[2 * pinch + 1] != 1) ++pinch;
  auto doubled = [&](double scale, double cx, double cy, bool share_pinch) {
    MeshData m = both;
    const auto first = static_cast<Index>(m.point_count());
    for (Index v = 0; v < both.point_count(); ++v)
      append(m.coordinates, {cx + scale * (both.coordinates[2 * v] - cx), cy + scale * (both.coordinates[2 * v + 1] - cy)});
    for (std::size_t t = 6; t < 12; ++t) {  // the second square's two triangles
      const Index v = both.triangles[t];
      m.triangles.push_back(share_pinch && v == pinch ? pinch : first + v);
    }
    drop_unused_vertices(m);
    return m;
  };
  ASSERT_EQ(both.coordinates[2 * both.triangles[6]], 1) << "triangles 2, 3 are the square [1,2]^2";
  EXPECT_EQ(defect_of(doubled(1, 0, 0, false)), "duplicate_vertex");
  const MeshData shrunk_at_pinch = doubled(0.5, 1, 1, true);
  ASSERT_TRUE(testing::all_elements_positive(shrunk_at_pinch));
  EXPECT_EQ(defect_of(shrunk_at_pinch), "t_junction") << "its edges at the pinch run along the big square's";
  const MeshData shrunk_inside = doubled(0.5, 1.5, 1.5, false);
  ASSERT_TRUE(testing::all_elements_positive(shrunk_inside));
  EXPECT_EQ(defect_of(shrunk_inside), "multiple_cover");
  EXPECT_EQ(defect_of(shrunk_inside, &domain), "multiple_cover");
}

// A pairing across the meshed side of a pinch would join a hole touching the outer loop to it
// in one counterclockwise curve: no cavity, and an empty region of the domain would go
// unnoticed. 2D: the 4 x 4 grid without a triangle that touches the boundary at one vertex,
// against the domain with that triangle's segments and no hole point; 3D: the 3^3 grid without
// a tetrahedron touching the boundary along an edge, against a domain whose cavity shell is
// oriented like the outer one (winding number 2 inside: solid, decision 8).
TEST(CertificateAdversary, EmptyRegionAtAPinchIsNotMeshed) {
  for (int dim : {2, 3}) {
    const int n = dim == 2 ? 4 : 3;
    MeshData m = dim == 2 ? square_grid(n) : kuhn_grid(n);
    auto& cells = dim == 2 ? m.triangles : m.tetrahedra;
    const auto k1 = static_cast<std::size_t>(dim + 1);
    const std::size_t removed = element_touching_boundary(m, n, dim - 1);  // 2D: at a vertex; 3D: along an edge
    ASSERT_NE(removed, SIZE_MAX);
    const std::vector<Index> gone(cells.begin() + static_cast<std::ptrdiff_t>(removed * k1), cells.begin() + static_cast<std::ptrdiff_t>((removed + 1) * k1));
    std::vector<double> centre(static_cast<std::size_t>(dim), 0.0);  // strictly inside it (exact in 3D)
    for (Index v : gone)
      for (int k = 0; k < dim; ++k) centre[static_cast<std::size_t>(k)] += m.coordinates[v * static_cast<std::size_t>(dim) + k];
    for (double& c : centre) c /= static_cast<double>(dim + 1);
    erase_element(m, removed);
    ASSERT_TRUE(check_mesh(m).valid);
    MeshData domain = boundary_as_domain(m);
    if (dim == 3)  // the cavity's triangles (all three vertices on the removed tetrahedron) turned outward
      for (std::size_t t = 0; t < domain.triangle_count(); ++t) {
        Index* x = &domain.triangles[3 * t];
        if (std::all_of(x, x + 3, [&](Index v) { return std::count(gone.begin(), gone.end(), v) > 0; })) std::swap(x[1], x[2]);
      }
    EXPECT_EQ(defect_of(m, &domain), "region_not_meshed") << dim << "D";
    domain.holes = centre;
    EXPECT_EQ(defect_of(m, &domain), "none") << dim << "D, with a hole point in the cavity";
  }
}

// The lowest vertex of a hole is a pinch with the outer loop: the square [0,2]^2 without the
// triangle (0,0) (1,1/2) (1/2,1) at its corner. Just left of (0,0) lies outside the mesh, but
// next to the hole the outer loop winds once: W there is read counterclockwise of the hole's
// last edge at the corner, past the outer loop's entering edge (a correction of +1).
TEST(CertificateAdversary, HoleAtTheCornerOfTheOuterLoop) {
  MeshData m;
  m.dimension = 2;
  append(m.coordinates, {0, 0, 2, 0, 2, 2, 0, 2, 1, 0.5, 0.5, 1});
  append(m.triangles, {0, 1, 4, 1, 2, 4, 4, 2, 5, 2, 3, 5, 3, 0, 5});
  ASSERT_TRUE(testing::all_elements_positive(m));
  EXPECT_EQ(mesh_area(m), 4 - polygon_area(m, {0, 4, 5})) << "the elements tile the square minus the hole";
  const Report r = check_mesh(m);
  EXPECT_TRUE(r.valid) << r.finding.message;
  EXPECT_EQ(r.statistics.boundary_components, 2u);
  MeshData with_hole = boundary_as_domain(m);
  with_hole.holes = {0.5, 0.5};
  EXPECT_EQ(defect_of(m, &with_hole), "none");
  MeshData filled = m;  // the hole filled
  append(filled.triangles, {0, 4, 5});
  EXPECT_EQ(defect_of(filled), "none");
  EXPECT_EQ(defect_of(filled, &with_hole), "hole_covered");
}

// The mesh pinches where the domain has a sub-ulp gap: the quad A(0,0) B(6,2) C(6,4) D(0,4)
// with a triangular hole whose corner w = (1, 0x1.5555555555556p-2) lies strictly above the
// segment AB (y = x/3), inside its rounding box. The mesh takes w as a vertex of its outer loop
// (A -> w -> B): its boundary edge A-w lies on no single domain segment (w, a domain vertex,
// is on AB only exactly, and it is not).
TEST(CertificateAdversary, MeshPinchesAcrossASubUlpGap) {
  MeshData m;
  m.dimension = 2;
  append(m.coordinates, {0, 0, 6, 2, 6, 4, 0, 4, 1, 0x1.5555555555556p-2, 2, 2, 1, 2});
  append(m.triangles, {0, 4, 3, 4, 6, 3, 6, 2, 3, 6, 5, 2, 5, 1, 2, 4, 1, 5});
  ASSERT_TRUE(testing::all_elements_positive(m));
  ASSERT_GT(twice_area(m, 0, 1, 4), 0) << "w is strictly above AB: the domain's hole does not touch AB";
  EXPECT_TRUE(check_mesh(m).valid) << "alone, a valid mesh pinched at w";
  MeshData d = m;
  d.triangles.clear();
  append(d.segments, {0, 1, 1, 2, 2, 3, 3, 0, 4, 5, 5, 6, 6, 4});
  d.holes = {1.25, 1.5};
  EXPECT_EQ(defect_of(m, &d), "facet_off_domain_boundary");
}

// The domain pinches where the mesh does not: the 4 x 4 square whose hole, a triangle, touches
// the bottom side at (1,0), against the full grid (the hole meshed).
TEST(CertificateAdversary, DomainPinchesMeshDoesNot) {
  MeshData holed = square_grid(4);
  const std::int64_t t = element_with(holed, {grid_vertex(4, 1, 0), grid_vertex(4, 2, 1), grid_vertex(4, 1, 1)});
  ASSERT_GE(t, 0);
  erase_element(holed, static_cast<std::size_t>(t));
  MeshData domain = boundary_as_domain(holed);
  domain.holes = {1.25, 0.5};
  ASSERT_TRUE(check_mesh(holed, &domain).valid);
  EXPECT_EQ(defect_of(square_grid(4), &domain), "hole_covered");
  // 3D: two cubes sharing an edge, against a mesh that also fills one of the cubes beside it.
  const MeshData two = kept_cubes(2, [](int i, int j, int k) { return i == j && k == 0; });
  const MeshData three = kept_cubes(2, [](int i, int j, int k) { return j == 0 && k == 0 ? true : i == j && k == 0; });
  const MeshData cubes = boundary_as_domain(two);
  ASSERT_TRUE(check_mesh(two, &cubes).valid);
  ASSERT_TRUE(check_mesh(three).valid);
  // Its face triangle (1,0,0) (2,1,0) (1,1,0) has every vertex on the domain, no two cubes' faces in common.
  EXPECT_EQ(defect_of(three, &cubes), "facet_off_domain_boundary");
}

// Item 1 in 3D: the mesh triangles on a domain triangle are all boundary triangles with their
// elements on one side, or all interior. The grid of [0,2]^3 plus a slab [2, 2 + 2^-20] x
// [0,1] x [0,2] glued to its face x = 2 is a valid mesh; with a boundary tolerance of 2^-10 the
// slab's outer vertices count as on that face, so every boundary facet lies on one domain
// triangle and every boundary vertex on the domain, but the face x = 2 is then covered by
// interior triangles (where the slab is glued) and by boundary ones (elsewhere, and the slab's
// outer side): the mesh boundary leaves the face through the tolerance. Refused.
TEST(CertificateAdversary, DomainTriangleBoundedFromOneSideOnly3d) {
  MeshData m = kuhn_grid(2);
  MeshData slab = kept_cubes(2, [](int i, int j, int) { return i == 0 && j == 0; });  // [0,1] x [0,1] x [0,2]
  const auto first = static_cast<Index>(m.point_count());
  std::vector<Index> id(slab.point_count());
  for (Index v = 0; v < slab.point_count(); ++v) {
    const double* p = &slab.coordinates[3 * v];
    if (p[0] == 0) {  // on x = 2: the grid's own vertex there
      id[v] = grid_vertex(2, 2, static_cast<int>(p[1]), static_cast<int>(p[2]));
      continue;
    }
    id[v] = static_cast<Index>(m.point_count());
    append(m.coordinates, {2 + 0x1p-20, p[1], p[2]});
  }
  for (Index v : slab.tetrahedra) m.tetrahedra.push_back(id[v]);
  ASSERT_GT(m.point_count(), first);
  ASSERT_TRUE(testing::all_elements_positive(m));
  ASSERT_TRUE(check_mesh(m).valid) << "alone, a valid mesh of the cube and the slab";
  const MeshData cube = fuzz::cube_surface_domain(2);
  ASSERT_TRUE(check_mesh(kuhn_grid(2), &cube).valid);
  EXPECT_EQ(defect_of(m, &cube), "vertex_off_domain_boundary") << "by the exact rule the slab is off the domain";
  CheckOptions loose;
  loose.boundary_tolerance.absolute = 0x1p-10;
  ASSERT_TRUE(check_mesh(kuhn_grid(2), &cube, loose).valid);
  const Report r = check_mesh(m, &cube, loose);
  EXPECT_EQ(defect_name(r.finding.defect), defect_name(Defect::domain_boundary_not_covered)) << r.finding.message;
  EXPECT_NE(r.finding.message.find("partly by mesh boundary triangles and partly by interior ones"), std::string::npos) << r.finding.message;
}

// The 3D limitation of proofs/mesh_certificate.md section 7, pinned: a tetrahedron touching four
// others, one at each corner (each the point reflection of it through that corner, so they meet
// it only there), is a valid tiling, but none of its vertices is off the other components, where
// their winding numbers would be read: refused, saying why, rather than read at a pinch.
TEST(CertificateAdversary, ComponentWithEveryVertexShared3d) {
  MeshData m = simplices(3, {{0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1}});
  for (Index p = 0; p < 4; ++p) {
    const auto first = static_cast<Index>(m.point_count());
    std::vector<Index> tet{p};
    for (Index q = 0; q < 4; ++q) {
      if (q == p) continue;
      for (int k = 0; k < 3; ++k) m.coordinates.push_back(2 * m.coordinates[3 * p + k] - m.coordinates[3 * q + k]);
      tet.push_back(static_cast<Index>(m.point_count() - 1));
    }
    if (testing::oracle_element_sign(m, tet) < 0) std::swap(tet[2], tet[3]);
    m.tetrahedra.insert(m.tetrahedra.end(), tet.begin(), tet.end());
    ASSERT_EQ(m.point_count(), first + 3);
  }
  ASSERT_TRUE(testing::all_elements_positive(m));
  const Report r = check_mesh(m);
  EXPECT_EQ(defect_name(r.finding.defect), defect_name(Defect::non_manifold_boundary));
  EXPECT_NE(r.finding.message.find("limitation"), std::string::npos) << r.finding.message;
  MeshData three_corners = m;  // with one corner free the same tiling is certified
  three_corners.tetrahedra.resize(16);
  drop_unused_vertices(three_corners);
  EXPECT_TRUE(check_mesh(three_corners).valid) << check_mesh(three_corners).finding.message;
}


// Two ladders of triangles (strips) that overlap, crossing where both boundaries run straight
// on: the crossing edges start at vertices where one boundary edge ends and the next begins,
// which the 2D sweep passes without a tree search (sweep_2d.cpp, pass_through). The oracle is
// brute force: every pair of boundary edges of the two strips tested in exact rationals. Each
// strip alone is certified; together they must be refused as crossing (or touching, when a
// vertex of one lands on the other), never certified and never as some later defect.
MeshData ladder(double ox, double oy, double sx, double sy, double wx, double wy, int rungs) {
  MeshData m;
  m.dimension = 2;
  for (int j = 0; j <= rungs; ++j) append(m.coordinates, {ox + j * sx, oy + j * sy, ox + j * sx + wx, oy + j * sy + wy});
  for (Index j = 0; j < static_cast<Index>(rungs); ++j) append(m.triangles, {2 * j, 2 * j + 1, 2 * j + 3, 2 * j, 2 * j + 3, 2 * j + 2});
  return m;
}
// The boundary edges of a ladder (its two long sides and two ends), as vertex pairs.
std::vector<std::pair<Index, Index>> ladder_boundary(int rungs) {
  std::vector<std::pair<Index, Index>> e{{0, 1}, {static_cast<Index>(2 * rungs), static_cast<Index>(2 * rungs + 1)}};
  for (Index j = 0; j < static_cast<Index>(rungs); ++j) e.push_back({2 * j, 2 * j + 2}), e.push_back({2 * j + 1, 2 * j + 3});
  return e;
}
bool closed_segments_meet(const MeshData& m, Index a, Index b, Index c, Index d) {
  const int o1 = sgn(twice_area(m, a, b, c)), o2 = sgn(twice_area(m, a, b, d));
  const int o3 = sgn(twice_area(m, c, d, a)), o4 = sgn(twice_area(m, c, d, b));
  if (o1 * o2 > 0 || o3 * o4 > 0) return false;
  if (o1 != 0 || o2 != 0 || o3 != 0 || o4 != 0) return true;
  auto q = [&](Index v, int k) { return mpq_class(m.coordinates[2 * v + k]); };  // collinear: ranges overlap
  for (int k = 0; k < 2; ++k)
    if (std::max(q(a, k), q(b, k)) < std::min(q(c, k), q(d, k)) || std::max(q(c, k), q(d, k)) < std::min(q(a, k), q(b, k))) return false;
  return true;
}

TEST(CertificateAdversary, StripsCrossingWhereBoundariesRunStraight) {
  std::mt19937 rng(20261202);
  std::uniform_int_distribution<int> offset(-64, 64);
  int crossing = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const int n = 12;
    const MeshData a = ladder(0, 0, 0, 1, 1, 0, n);  // upright: sides x = 0 and x = 1
    // Tilted, climbing to the right: its long sides climb too, vertex after vertex.
    const MeshData b = ladder(-4 + offset(rng) / 64.0, 3 + offset(rng) / 32.0, 0.75, 0.3125 + offset(rng) / 1024.0, 0.125, -0.875, n);
    MeshData both = a;
    const auto shift = static_cast<Index>(a.point_count());
    both.coordinates.insert(both.coordinates.end(), b.coordinates.begin(), b.coordinates.end());
    for (Index v : b.triangles) both.triangles.push_back(v + shift);
    ASSERT_TRUE(testing::all_elements_positive(both));
    ASSERT_TRUE(check_mesh(a).valid && check_mesh(b).valid);
    bool meet = false;
    for (const auto& [p, q] : ladder_boundary(n))
      for (const auto& [r, s] : ladder_boundary(n)) meet = meet || closed_segments_meet(both, p, q, r + shift, s + shift);
    ASSERT_TRUE(meet) << "trial " << trial << ": the strips are placed to overlap";
    const std::string d = defect_of(both);
    EXPECT_TRUE(d == "boundary_intersection" || d == "t_junction") << "trial " << trial << ": " << d;
    crossing += d == "boundary_intersection";
  }
  EXPECT_GT(crossing, 200);  // most trials cross properly (no vertex exactly on the other strip)
}
// Random rectangles (two triangles each) and right triangles with corners on a small integer
// grid, sharing vertex ids where they share corners: disjoint, nested, touching at corners,
// sharing whole edges, overlapping. Nearly every boundary edge is horizontal or vertical, the
// case where the 2D sweep's recorded prefix sums (sweep_2d.cpp) must survive horizontal runs;
// nesting without contact is caught only by those winding numbers. The oracle: how many
// triangles contain each of a lattice of sample points (exact rationals; the points are off
// every grid line and diagonal), and whether the shapes are conforming (no corner inside
// another shape's boundary edge, no two boundary edges crossing or overlapping). Certified
// implies no point covered twice; conforming and no point covered twice implies certified.
TEST(CertificateAdversary, RectanglesNestedTouchingAndOverlapping) {
  std::mt19937 rng(20261202);
  int certified = 0, multiple = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const int grid = 9;
    MeshData m;
    m.dimension = 2;
    std::vector<std::int64_t> id((grid + 1) * (grid + 1), -1);
    auto vertex = [&](int x, int y) {
      std::int64_t& v = id[static_cast<std::size_t>(y * (grid + 1) + x)];
      if (v < 0) v = static_cast<std::int64_t>(m.point_count()), append(m.coordinates, {double(x), double(y)});
      return static_cast<Index>(v);
    };
    std::vector<std::vector<Index>> loops;  // each shape's boundary, counterclockwise
    const int shapes = 2 + static_cast<int>(rng() % 3);
    for (int k = 0; k < shapes; ++k) {
      int x0 = static_cast<int>(rng() % grid), y0 = static_cast<int>(rng() % grid);
      int x1 = x0 + 1 + static_cast<int>(rng() % static_cast<unsigned>(grid - x0)), y1 = y0 + 1 + static_cast<int>(rng() % static_cast<unsigned>(grid - y0));
      if (trial % 2 == 0 && k < 2) {  // every other trial: a shape strictly inside a rectangle
        x0 = y0 = k == 0 ? 0 : 1 + static_cast<int>(rng() % 3);
        x1 = y1 = k == 0 ? grid : x0 + 1 + static_cast<int>(rng() % 3);
      }
      const unsigned kind = k == 0 && trial % 2 == 0 ? 2 : rng() % 4;
      auto a = [&] { return vertex(x0, y0); };
      auto b = [&] { return vertex(x1, y0); };
      auto c = [&] { return vertex(x1, y1); };
      auto d = [&] { return vertex(x0, y1); };
      if (kind == 0) loops.push_back({a(), b(), c()});  // right triangles
      else if (kind == 1) loops.push_back({a(), c(), d()});
      else loops.push_back({a(), b(), c(), d()});
      const std::vector<Index>& l = loops.back();
      if (l.size() == 3) append(m.triangles, {l[0], l[1], l[2]});
      else if (rng() % 2) append(m.triangles, {l[0], l[1], l[2], l[0], l[2], l[3]});
      else append(m.triangles, {l[0], l[1], l[3], l[1], l[2], l[3]});
    }
    ASSERT_TRUE(testing::all_elements_positive(m));
    // Sample points (4i + 1)/16 + 1/97, (4j + 1)/16 + 3/89, in integers over D = 16 * 97 * 89:
    // off every line through two grid points here (slopes p/q with |p|, |q| <= 9).
    const std::int64_t D = 16 * 97 * 89;
    int most = 0;  // the largest number of triangles over one sample point
    for (int i = 0; i < 4 * grid; ++i)
      for (int j = 0; j < 4 * grid; ++j) {
        const std::int64_t px = (4 * i + 1) * 97 * 89 + 16 * 89, py = (4 * j + 1) * 97 * 89 + 16 * 3 * 97;
        int over = 0;
        for (std::size_t t = 0; t < m.triangle_count(); ++t) {
          bool inside = true;
          for (int e = 0; e < 3 && inside; ++e) {
            const Index u = m.triangles[3 * t + static_cast<std::size_t>(e)], w = m.triangles[3 * t + static_cast<std::size_t>((e + 1) % 3)];
            auto at = [&](Index v, int k) { return static_cast<std::int64_t>(m.coordinates[2 * v + static_cast<std::size_t>(k)]) * D; };
            inside = (at(w, 0) - at(u, 0)) * (py - at(u, 1)) - (at(w, 1) - at(u, 1)) * (px - at(u, 0)) > 0;
          }
          over += inside;
        }
        most = std::max(most, over);
      }
    bool conforming = true;
    for (std::size_t p = 0; p < loops.size() && conforming; ++p)
      for (std::size_t q = p + 1; q < loops.size() && conforming; ++q)
        for (std::size_t i = 0; i < loops[p].size() && conforming; ++i)
          for (std::size_t j = 0; j < loops[q].size() && conforming; ++j) {
            const Index a = loops[p][i], b = loops[p][(i + 1) % loops[p].size()];
            const Index c = loops[q][j], d = loops[q][(j + 1) % loops[q].size()];
            if (std::minmax(a, b) == std::minmax(c, d)) continue;  // the same edge
            const Index shared = a == c || a == d ? a : (b == c || b == d ? b : Index(-1));
            if (shared == Index(-1)) {
              conforming = !closed_segments_meet(m, a, b, c, d);
              continue;
            }
            // One common end: they meet elsewhere only when collinear and pointing the same way.
            const Index u = a == shared ? b : a, w = c == shared ? d : c;
            if (sgn(twice_area(m, shared, u, w)) != 0) continue;
            const double dot = (m.coordinates[2 * u] - m.coordinates[2 * shared]) * (m.coordinates[2 * w] - m.coordinates[2 * shared]) +
                               (m.coordinates[2 * u + 1] - m.coordinates[2 * shared + 1]) * (m.coordinates[2 * w + 1] - m.coordinates[2 * shared + 1]);
            conforming = dot < 0;
          }
    const Report r = check_mesh(m);
    if (r.valid) {
      EXPECT_LE(most, 1) << "trial " << trial << ": certified, yet a point is covered " << most << " times";
    }
    if (conforming && most <= 1) {
      EXPECT_TRUE(r.valid) << "trial " << trial << ": a conforming single cover refused: " << r.finding.message;
    }
    if (conforming && most > 1) {
      EXPECT_FALSE(r.valid) << "trial " << trial;
    }
    certified += r.valid;
    multiple += conforming && most > 1;
  }
  EXPECT_GT(certified, 40);  // both verdicts occur often enough to mean something
  EXPECT_GT(multiple, 20);   // conforming but nested: only the winding numbers see it
}
}  // namespace
}  // namespace certimesh::certificate::test
