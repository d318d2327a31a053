// The worst triangle of the advancing-front pipeline on the unit square (the Table 3.1
// domain), checked on the certified mesh with a quality computed here, independently of the
// library's.
//
// The bound 0.9 is what the front used to miss: where the layers grown from one side reached
// a neighbouring side before that side's own first layer, and at the square's corners, the
// front left right isosceles triangles against boundary vertices, which the improvement
// cannot move. Such a triangle has quality 12√3·(1/2)/(2+√2)² = 0.8915 < 0.9, whatever the
// smoothing does to the rest, so any return of that pattern fails here. The meshes reach
// 0.906-0.934 at these sizes (h = 0.04 and 0.05 put a corner's two neighbours one step
// from the corner, where the bisector apex is what avoids the right triangle).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/generators/mesh_domain_2.h"

namespace {

using namespace certimesh::generators;

PlanarDomain unit_square() {
  PlanarDomain d;
  d.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  d.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  return d;
}

// 12√3·area/perimeter² in long double, from the mesh's coordinates.
long double shape_quality(const certimesh::io::MeshData& m, std::size_t t) {
  long double x[3], y[3];
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t v = m.triangles[3 * t + i];
    x[i] = m.coordinates[2 * v];
    y[i] = m.coordinates[2 * v + 1];
  }
  const long double area = 0.5L * ((x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]));
  long double perimeter = 0.0L;
  for (std::size_t i = 0; i < 3; ++i) perimeter += std::hypot(x[(i + 1) % 3] - x[i], y[(i + 1) % 3] - y[i]);
  return 12.0L * std::sqrt(3.0L) * area / (perimeter * perimeter);
}

class pipeline_UnitSquareWorstQuality : public ::testing::TestWithParam<double> {};

TEST_P(pipeline_UnitSquareWorstQuality, IsAtLeastPointNine) {
  const PlanarDomain domain = unit_square();
  MeshDomainOptions2 options;
  options.size.uniform_size = GetParam();
  const MeshDomainResult2 result = mesh_domain_2(domain, options);
  const certimesh::io::MeshData domain_data = to_mesh_data(domain);
  const auto report = certimesh::certificate::check_mesh(result.mesh, &domain_data);
  ASSERT_TRUE(report.valid) << report.finding.message;
  long double worst = 1.0L;
  std::size_t worst_triangle = 0;
  for (std::size_t t = 0; t < result.mesh.triangle_count(); ++t) {
    const long double q = shape_quality(result.mesh, t);
    if (q < worst) {
      worst = q;
      worst_triangle = t;
    }
  }
  const auto corner = [&](int i) {
    const std::size_t v = result.mesh.triangles[3 * worst_triangle + static_cast<std::size_t>(i)];
    return "(" + std::to_string(result.mesh.coordinates[2 * v]) + ", " + std::to_string(result.mesh.coordinates[2 * v + 1]) + ")";
  };
  EXPECT_GE(worst, 0.9L) << "worst triangle " << corner(0) << " " << corner(1) << " " << corner(2);
}

// Isolated input vertices (Triangle's points inside the domain, Gmsh's embedded points) are
// mesh vertices. Dropped into the front's mesh afterwards, one that lands next to a generated
// vertex left a sliver: worst 0.055 on Triangle's square_circle_hole.poly (691 points), where
// Gmsh reaches 0.73. Seeded points at least 1.2 h apart and from the sides (so a good mesh
// through them exists) at h = 0.05; quality computed here.
TEST(pipeline_IsolatedVertices, DoNotLeaveSlivers) {
  for (const std::uint64_t seed : {1u, 2u, 3u}) {
    PlanarDomain domain = unit_square();
    std::mt19937_64 random(seed);
    std::uniform_real_distribution<double> inside(0.06, 0.94);
    for (int attempt = 0; attempt < 2000; ++attempt) {
      const Point2 p{inside(random), inside(random)};
      if (std::all_of(domain.points.begin() + 4, domain.points.end(), [&](const Point2& q) { return std::hypot(p.x - q.x, p.y - q.y) >= 0.06; }))
        domain.points.push_back(p);
    }
    ASSERT_GT(domain.points.size(), 104u);
    MeshDomainOptions2 options;
    options.size.uniform_size = 0.05;
    const MeshDomainResult2 result = mesh_domain_2(domain, options);
    const certimesh::io::MeshData domain_data = to_mesh_data(domain);
    const auto report = certimesh::certificate::check_mesh(result.mesh, &domain_data);
    ASSERT_TRUE(report.valid) << report.finding.message;
    long double worst = 1.0L;
    for (std::size_t t = 0; t < result.mesh.triangle_count(); ++t) worst = std::min(worst, shape_quality(result.mesh, t));
    EXPECT_GE(worst, 0.45L) << "seed " << seed;  // 0.53-0.59 here; 0.09-0.27 before
  }
}

#if defined(__SANITIZE_ADDRESS__)
INSTANTIATE_TEST_SUITE_P(Pipeline, pipeline_UnitSquareWorstQuality, ::testing::Values(0.05, 0.04, 0.02));
#else
INSTANTIATE_TEST_SUITE_P(Pipeline, pipeline_UnitSquareWorstQuality, ::testing::Values(0.05, 0.04, 0.02, 0.01));
#endif

}  // namespace
