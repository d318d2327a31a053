// Unit tests of the certificate's condition 6 (the mesh against its domain) on small
// hand-built meshes and domains, 2D (.poly-like: segments + holes) and 3D (a closed surface).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "certimesh/certificate/check_mesh.h"
#include "unit_meshes.h"

namespace certimesh::certificate::test {
namespace {

Report expect_defect(const MeshData& m, const MeshData& domain, Defect defect) {
  const Report r = check_mesh(m, &domain);
  EXPECT_EQ(defect_name(r.finding.defect), defect_name(defect)) << r.finding.message;
  EXPECT_EQ(r.valid, defect == Defect::none);
  return r;
}

// The boundary of the square [lo, hi]^2 as four segments, appended to d.
void add_square(MeshData& d, double lo, double hi) {
  const auto first = static_cast<Index>(d.coordinates.size() / 2);
  for (double c : {lo, lo, hi, lo, hi, hi, lo, hi}) d.coordinates.push_back(c);
  for (Index i = 0; i < 4; ++i) append(d.segments, {first + i, first + (i + 1) % 4});
}

MeshData square_domain(double size) {
  MeshData d;
  add_square(d, 0, size);
  return d;
}

// The surface of the cube [lo, hi]^3, each face cut along the diagonal from its smallest to its
// largest corner (as the Kuhn grid cuts its boundary squares), appended to d.
void add_cube(MeshData& d, double lo, double hi) {
  d.dimension = 3;
  const auto first = static_cast<Index>(d.coordinates.size() / 3);
  for (int c = 0; c < 8; ++c)
    for (int k = 0; k < 3; ++k) d.coordinates.push_back((c >> k & 1) ? hi : lo);
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      const int u = 1 << ((axis + 1) % 3), w = 1 << ((axis + 2) % 3), base = side << axis;
      const Index a = first + static_cast<Index>(base), b = first + static_cast<Index>(base + u),
                  c = first + static_cast<Index>(base + u + w), e = first + static_cast<Index>(base + w);
      append(d.triangles, {a, b, c, a, c, e});
    }
}

TEST(CertificateDomain, GridOnSquare) {
  const Report r = expect_defect(square_grid(3), square_domain(3), Defect::none);
  EXPECT_EQ(r.statistics.vertices_exactly_on_domain_boundary, 12u);
  EXPECT_EQ(r.statistics.vertices_in_rounding_box_only, 0u);
}

// A vertex at the rounding of the exact point (2, 1/3) of the segment (3,0)-(0,1).
MeshData rounded_split(double y) {
  MeshData m;
  m.coordinates = {0, 0, 3, 0, 2, y, 0, 1};
  m.triangles = {0, 1, 2, 0, 2, 3};
  return m;
}

TEST(CertificateDomain, RoundedVertexIsOnItsSegment) {
  MeshData d;
  d.coordinates = {0, 0, 3, 0, 0, 1};
  d.segments = {0, 1, 1, 2, 2, 0};
  const Report r = expect_defect(rounded_split(1.0 / 3.0), d, Defect::none);
  EXPECT_EQ(r.statistics.vertices_exactly_on_domain_boundary, 3u);
  EXPECT_EQ(r.statistics.vertices_in_rounding_box_only, 1u);
  EXPECT_GT(r.statistics.max_boundary_deviation, 0.0);
  EXPECT_LT(r.statistics.max_boundary_deviation, 1e-16);
  // Two ulps away is off the segment: the rule is half an ulp, not a tolerance.
  const double off = std::nextafter(std::nextafter(1.0 / 3.0, 1.0), 1.0);
  EXPECT_EQ(expect_defect(rounded_split(off), d, Defect::vertex_off_domain_boundary).finding.vertex, 2);
}

// Meshes written by other tools: vertices a few ulps or 1e-15 off their segment are refused by
// the exact rule (with the segment and the distance named) and accepted with a tolerance.
TEST(CertificateDomain, BoundaryTolerance) {
  MeshData d;
  d.coordinates = {0, 0, 3, 0, 0, 1};
  d.segments = {0, 1, 1, 2, 2, 0};
  double y = 1.0 / 3.0;
  for (int i = 0; i < 3; ++i) y = std::nextafter(y, 1.0);  // three ulps off
  const MeshData three_ulps = rounded_split(y), gmsh = rounded_split(0.33333333333333);  // 14 digits
  for (const MeshData* m : {&three_ulps, &gmsh}) {
    const Report exact = expect_defect(*m, d, Defect::vertex_off_domain_boundary);
    EXPECT_EQ(exact.finding.vertex, 2);
    EXPECT_EQ(exact.finding.other, 1) << "the nearest segment, (3,0)-(0,1)";
    EXPECT_NE(exact.finding.message.find("segment: the nearest, 1, is"), std::string::npos) << exact.finding.message;
  }
  CheckOptions ulps;
  ulps.boundary_tolerance.ulps = 4;
  EXPECT_TRUE(check_mesh(three_ulps, &d, ulps).valid);
  EXPECT_FALSE(check_mesh(gmsh, &d, ulps).valid) << "3.3e-15 is more than 4 ulps";
  CheckOptions absolute;
  absolute.boundary_tolerance.absolute = 1e-12;
  for (const MeshData* m : {&three_ulps, &gmsh}) {
    const Report r = check_mesh(*m, &d, absolute);
    EXPECT_TRUE(r.valid) << r.finding.message;
    EXPECT_EQ(r.statistics.vertices_in_rounding_box_only, 1u);
    EXPECT_GT(r.statistics.max_boundary_deviation, 0.0);
    EXPECT_LT(r.statistics.max_boundary_deviation, 1e-14);
    EXPECT_LE(std::abs(r.statistics.measure_difference), r.statistics.measure_difference_bound);
  }
  absolute.boundary_tolerance.absolute = 1e-16;
  EXPECT_EQ(defect_name(check_mesh(gmsh, &d, absolute).finding.defect), defect_name(Defect::vertex_off_domain_boundary));
}

TEST(CertificateDomain, CutCornerIsOffTheDomain) {
  MeshData m;  // the square [0,2]^2 without the corner beyond (2,1)-(1,2)
  m.coordinates = {0, 0, 2, 0, 2, 1, 1, 2, 0, 2};
  m.triangles = {0, 1, 2, 0, 2, 3, 0, 3, 4};
  EXPECT_EQ(expect_defect(m, square_domain(2), Defect::facet_off_domain_boundary).finding.element, 1);
}

TEST(CertificateDomain, InternalConstraintMustBeMeshEdges) {
  MeshData d = square_domain(2);
  append(d.segments, {0, 2});  // the diagonal the grid's edges follow
  expect_defect(square_grid(2), d, Defect::none);
  d.segments.back() = 1, d.segments[d.segments.size() - 2] = 3;  // the other diagonal
  EXPECT_EQ(expect_defect(square_grid(2), d, Defect::domain_boundary_not_covered).finding.other, 4);
}

TEST(CertificateDomain, HolesAndRegions) {
  MeshData d = square_domain(3);
  add_square(d, 1, 2);
  const MeshData annulus = square_grid(3, [](int i, int j) { return i == 1 && j == 1; });
  expect_defect(annulus, d, Defect::region_not_meshed);
  d.holes = {1.5, 1.5};
  expect_defect(annulus, d, Defect::none);
  EXPECT_EQ(expect_defect(square_grid(3), d, Defect::hole_covered).finding.other, 0);
  d.holes = {1.5, 1.0};  // on the cavity's boundary: not strictly outside
  expect_defect(annulus, d, Defect::hole_covered);
}

TEST(CertificateDomain, InvalidDomains) {
  MeshData d = square_domain(2);
  append(d.segments, {0, 2});
  append(d.segments, {1, 3});  // the two diagonals cross
  expect_defect(square_grid(2), d, Defect::invalid_domain);
  d = square_domain(2);
  d.coordinates[0] = std::numeric_limits<double>::infinity();
  expect_defect(square_grid(2), d, Defect::invalid_domain);
  MeshData cube;
  add_cube(cube, 0, 2);
  expect_defect(square_grid(2), cube, Defect::invalid_domain);  // 3D domain for a 2D mesh
  expect_defect(kuhn_grid(2), cube, Defect::none);
  cube.triangles.resize(cube.triangles.size() - 3);  // one triangle missing: not closed
  expect_defect(kuhn_grid(2), cube, Defect::invalid_domain);
}

TEST(CertificateDomain, SecondDomainComponentNotMeshed) {
  MeshData d;
  add_cube(d, 0, 2);
  add_cube(d, 3, 4);
  EXPECT_EQ(expect_defect(kuhn_grid(2), d, Defect::domain_boundary_not_covered).finding.other, 12);
}

TEST(CertificateDomain, KuhnGridOnCube) {
  MeshData d;
  add_cube(d, 0, 2);
  const Report r = expect_defect(kuhn_grid(2), d, Defect::none);
  EXPECT_EQ(r.statistics.vertices_exactly_on_domain_boundary, 26u);
  d.holes = {0.5, 0.5, 0.5};
  expect_defect(kuhn_grid(2), d, Defect::hole_covered);
  MeshData moved = kuhn_grid(2);
  moved.coordinates[3 * grid_vertex(2, 1, 1, 0) + 2] = -0.25;  // pulled off the face z = 0
  EXPECT_EQ(expect_defect(moved, d, Defect::vertex_off_domain_boundary).finding.vertex, grid_vertex(2, 1, 1, 0));
}

TEST(CertificateDomain, CubeFacesMustBeConformal) {
  MeshData other;
  add_cube(other, 0, 2);
  // face x = 0 (corners 0, 2, 6, 4): cut along 2-4 instead of 0-6
  other.triangles[0] = 0, other.triangles[1] = 2, other.triangles[2] = 4;
  other.triangles[3] = 2, other.triangles[4] = 6, other.triangles[5] = 4;
  expect_defect(kuhn_grid(2), other, Defect::facet_off_domain_boundary);
}

// The surface of the cube [lo, hi]^3 oriented consistently: every triangle's normal (right-hand
// rule, checked here with a small-integer cross product) points outward, or inward if asked.
void add_oriented_cube(MeshData& d, double lo, double hi, bool inward) {
  const auto first = static_cast<Index>(d.coordinates.size() / 3);
  add_cube(d, lo, hi);
  const double mid = (lo + hi) / 2;
  for (std::size_t t = first == 0 ? 0 : d.triangles.size() - 36; t < d.triangles.size(); t += 3) {
    auto at = [&](std::size_t i, int k) { return d.coordinates[3 * d.triangles[t + i] + k]; };
    double n[3], centre[3];
    for (int k = 0; k < 3; ++k) {
      const int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
      n[k] = (at(1, k1) - at(0, k1)) * (at(2, k2) - at(0, k2)) - (at(1, k2) - at(0, k2)) * (at(2, k1) - at(0, k1));
      centre[k] = (at(0, k) + at(1, k) + at(2, k)) / 3 - mid;
    }
    const bool outward = n[0] * centre[0] + n[1] * centre[1] + n[2] * centre[2] > 0;
    if (outward == inward) std::swap(d.triangles[t + 1], d.triangles[t + 2]);
  }
}

// Decision 8 in 3D: the solid is where the winding number of the oriented shells is non-zero.
TEST(CertificateDomain, CavityByOrientation3D) {
  const MeshData shell = kuhn_grid(3, [](int i, int j, int k) { return i == 1 && j == 1 && k == 1; });
  MeshData inward;
  add_oriented_cube(inward, 0, 3, false);
  add_oriented_cube(inward, 1, 2, true);
  const Report r = check_mesh(shell, &inward);
  EXPECT_TRUE(r.valid) << "an inner shell oriented inward is a cavity, no hole point needed: " << r.finding.message;
  expect_defect(kuhn_grid(3), inward, Defect::hole_covered);  // the cavity filled
  MeshData outward;
  add_oriented_cube(outward, 0, 3, false);
  add_oriented_cube(outward, 1, 2, false);
  expect_defect(shell, outward, Defect::region_not_meshed);  // winding 2 inside: solid, not meshed
  expect_defect(kuhn_grid(3), outward, Defect::none);       // an interface between two regions
}

TEST(CertificateDomain, CavityNeedsAHole3D) {
  MeshData d;
  add_cube(d, 0, 3);
  add_cube(d, 1, 2);
  const MeshData shell = kuhn_grid(3, [](int i, int j, int k) { return i == 1 && j == 1 && k == 1; });
  expect_defect(shell, d, Defect::region_not_meshed);
  d.holes = {1.5, 1.5, 1.5};
  expect_defect(shell, d, Defect::none);
}

}  // namespace
}  // namespace certimesh::certificate::test
