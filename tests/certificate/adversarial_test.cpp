// Meshes built to fool the certificate (issue 12): rounding slack that joins two domain
// components, a floating-point sum whose error bound ignores underflow, and statistics that
// overflow. Every mesh here is first confirmed with the GMP oracle (element signs, exact
// areas) and by plain geometry, independently of the checker; then the checker is asked.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "mesh_oracle.h"
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

}  // namespace
}  // namespace certimesh::certificate::test
