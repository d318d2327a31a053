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

#if defined(__SANITIZE_ADDRESS__)
INSTANTIATE_TEST_SUITE_P(Pipeline, pipeline_UnitSquareWorstQuality, ::testing::Values(0.05, 0.04, 0.02));
#else
INSTANTIATE_TEST_SUITE_P(Pipeline, pipeline_UnitSquareWorstQuality, ::testing::Values(0.05, 0.04, 0.02, 0.01));
#endif

}  // namespace
