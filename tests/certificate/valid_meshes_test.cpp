// Valid meshes are accepted, 2D and 3D, with and without their domain: jittered Kuhn grids,
// grids with a hole, and the statistics the certificate reports for them match counts
// derived independently from the grid's shape.
#include "rc_support.h"

#include "pinch_meshes.h"

#include <cmath>

namespace certimesh::testing {
namespace {

using certificate::check_mesh;

// Boundary facets of an nx x ny (x nz) Kuhn grid: 2 per unit square of boundary face in 3D,
// 1 per unit edge in 2D; a removed block adds its own surface.
std::size_t expected_boundary_facets(const fuzz::GridSpec& g) {
  const auto box = [&](std::array<int, 3> n) -> std::size_t {
    if (g.dimension == 2) return static_cast<std::size_t>(2 * (n[0] + n[1]));
    return static_cast<std::size_t>(4 * (n[0] * n[1] + n[1] * n[2] + n[0] * n[2]));
  };
  std::size_t facets = box(g.cells);
  if (!g.hole.empty())
    facets += box({g.hole.hi[0] - g.hole.lo[0], g.hole.hi[1] - g.hole.lo[1], g.hole.hi[2] - g.hole.lo[2]});
  return facets;
}

void expect_statistics_match(const fuzz::GridSpec& g, const io::MeshData& mesh, const certificate::Report& r) {
  const std::size_t elements = fuzz::element_count(mesh);
  RC_ASSERT(r.statistics.dimension == g.dimension);
  RC_ASSERT(r.statistics.vertices == mesh.point_count());
  RC_ASSERT(r.statistics.elements == elements);
  RC_ASSERT(r.statistics.boundary_facets == expected_boundary_facets(g));
  // Every element has dim + 1 facets; each interior facet is counted twice.
  RC_ASSERT(r.statistics.interior_facets * 2 + r.statistics.boundary_facets ==
            elements * static_cast<std::size_t>(g.dimension + 1));
  RC_ASSERT(r.statistics.boundary_components == (g.hole.empty() ? 1u : 2u));
  RC_ASSERT(r.statistics.worst_quality > 0.0 && r.statistics.worst_quality <= 1.0);
}

fuzz::CellBlock centred_hole(const fuzz::GridSpec& g) {
  fuzz::CellBlock b;
  const int axes = g.dimension;
  for (std::size_t c = 0; c < 3; ++c) {
    if (static_cast<int>(c) >= axes) {
      b.lo[c] = 0, b.hi[c] = 1;
      continue;
    }
    b.lo[c] = *rc::gen::inRange(1, g.cells[c] - 1);
    b.hi[c] = *rc::gen::inRange(b.lo[c] + 1, g.cells[c]);
  }
  return b;
}

void check_grid(int dimension) {
  const DrawnGrid g = draw_grid(dimension, *rc::gen::arbitrary<bool>());
  const certificate::Report alone = check_mesh(g.mesh);
  if (!alone.valid) RC_FAIL("rejected: " + describe(alone.finding));
  RC_ASSERT(alone.finding.defect == certificate::Defect::none);
  expect_statistics_match(g.spec, g.mesh, alone);
  expect_accepted(g.mesh, &g.domain);
}

void check_grid_with_hole(int dimension) {
  DrawnGrid g = draw_grid(dimension);
  g.spec.hole = centred_hole(g.spec);
  g.mesh = fuzz::kuhn_grid(g.spec);
  RC_ASSERT(all_elements_positive(g.mesh));
  const certificate::Report alone = check_mesh(g.mesh);
  if (!alone.valid) RC_FAIL("rejected: " + describe(alone.finding));
  expect_statistics_match(g.spec, g.mesh, alone);
  if (dimension == 2) {
    const io::MeshData domain = fuzz::square_domain(g.spec);
    expect_accepted(g.mesh, &domain);
  }
}

RC_GTEST_PROP(ValidMeshes, KuhnGrid2dAccepted, ()) { check_grid(2); }
RC_GTEST_PROP(ValidMeshes, KuhnGrid3dAccepted, ()) { check_grid(3); }
RC_GTEST_PROP(ValidMeshes, GridWithHole2dAccepted, ()) { check_grid_with_hole(2); }
RC_GTEST_PROP(ValidMeshes, GridWithHole3dAccepted, ()) { check_grid_with_hole(3); }

// 3D domain with a cavity: the cube [0,4]^3 minus the box [1,3]^3 (inner surface oriented
// into the cavity, hole point at its centre), meshed by the grid without that block.
TEST(ValidMeshes, CubeWithCavityAgainstItsDomain) {
  fuzz::GridSpec g;
  g.dimension = 3;
  g.cells = {4, 4, 4};
  g.hole = {{1, 1, 1}, {3, 3, 3}};
  g.jitter_seed = 7;
  const io::MeshData mesh = fuzz::kuhn_grid(g);
  ASSERT_TRUE(all_elements_positive(mesh));
  io::MeshData domain = fuzz::cube_surface_domain(4);
  fuzz::append_box_surface(domain, 1, 3, true);
  domain.holes = {2, 2, 2};
  const certificate::Report r = check_mesh(mesh, &domain);
  EXPECT_TRUE(r.valid) << describe(r.finding);
  EXPECT_EQ(r.statistics.boundary_components, 2u);
}

// The worst quality of an unjittered 2D Kuhn grid is that of its right isosceles triangles:
// 12 sqrt(3) (1/2) / (2 + sqrt(2))^2; of a 3D one, that of the Kuhn tetrahedron (edges 1, 1,
// 1, sqrt(2), sqrt(2), sqrt(3), volume 1/6): 6^4 sqrt(2) (1/6) / P^3.
TEST(ValidMeshes, WorstQualityOfUnjitteredGrids) {
  fuzz::GridSpec g2;
  g2.cells = {5, 3, 1};
  const certificate::Report r2 = check_mesh(fuzz::kuhn_grid(g2));
  ASSERT_TRUE(r2.valid) << describe(r2.finding);
  EXPECT_NEAR(r2.statistics.worst_quality, 6 * std::sqrt(3.0) / std::pow(2 + std::sqrt(2.0), 2), 1e-9);
  fuzz::GridSpec g3;
  g3.dimension = 3;
  g3.cells = {2, 3, 2};
  const certificate::Report r3 = check_mesh(fuzz::kuhn_grid(g3));
  ASSERT_TRUE(r3.valid) << describe(r3.finding);
  const double perimeter = 3 + 2 * std::sqrt(2.0) + std::sqrt(3.0);
  EXPECT_NEAR(r3.statistics.worst_quality, 216 * std::sqrt(2.0) / std::pow(perimeter, 3), 1e-9);
}

// Pinches (design decision 8), certified alone and against the domain whose boundary is the
// mesh's own (read off with plain counting, pinch_meshes.h). The component counts follow the
// pairing rule of proofs/mesh_certificate.md (across the unmeshed side at a pinch): two
// squares sharing a corner are one curve, a hole touching the outer loop is a curve of its
// own; solids sharing only a vertex are two surfaces, solids sharing an edge one.
// A 2D hole needs its hole point (`holes`); a 3D cavity is one by its orientation.
void expect_pinch_certified(const io::MeshData& mesh, std::size_t components, std::vector<double> holes = {}) {
  ASSERT_TRUE(all_elements_positive(mesh));
  const certificate::Report alone = check_mesh(mesh);
  EXPECT_TRUE(alone.valid) << describe(alone.finding);
  EXPECT_EQ(alone.statistics.boundary_components, components);
  io::MeshData domain = certificate::test::boundary_as_domain(mesh);
  domain.holes = std::move(holes);
  const certificate::Report with_domain = check_mesh(mesh, &domain);
  EXPECT_TRUE(with_domain.valid) << describe(with_domain.finding);
}

TEST(ValidMeshes, TwoSquaresSharingACorner) {
  expect_pinch_certified(certificate::test::kept_squares(2, [](int i, int j) { return i == j; }), 1);
}

TEST(ValidMeshes, HoleTouchingTheOuterLoopAtAVertex) {
  io::MeshData m = certificate::test::square_grid(4);
  const std::size_t e = certificate::test::element_touching_boundary(m, 4, 1);
  ASSERT_NE(e, SIZE_MAX);
  std::vector<double> inside(2, 0.0);  // the removed triangle's rounded centroid: strictly inside it
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 2; ++k) inside[static_cast<std::size_t>(k)] += m.coordinates[2 * m.triangles[3 * e + static_cast<std::size_t>(i)] + static_cast<std::size_t>(k)] / 3;
  certificate::test::erase_element(m, e);
  expect_pinch_certified(m, 2, inside);
}

TEST(ValidMeshes, TwoCubesSharingAVertex) {
  expect_pinch_certified(certificate::test::kept_cubes(2, [](int i, int j, int k) { return i == j && j == k; }), 2);
}

TEST(ValidMeshes, TwoCubesSharingAnEdge) {
  expect_pinch_certified(certificate::test::kept_cubes(2, [](int i, int j, int k) { return i == j && k == 0; }), 1);
}

TEST(ValidMeshes, CavityTouchingTheOuterShellAtAVertexOrAlongAnEdge) {
  for (int count : {1, 2}) {
    io::MeshData m = certificate::test::kuhn_grid(3);
    const std::size_t e = certificate::test::element_touching_boundary(m, 3, count);
    ASSERT_NE(e, SIZE_MAX);
    certificate::test::erase_element(m, e);
    expect_pinch_certified(m, 2);
  }
}

}  // namespace
}  // namespace certimesh::testing
