// The default size follows the boundary (issue 12, item 10): a unit square with a notch of
// width and depth w = 10^-3 in its bottom side. Hand-derived expectations:
//  - the triangles at the notch's corners are about as small as the notch (longest edge at most
//    5 w: lfs = w there, and the size grows by g = 0.25 per unit of distance);
//  - the short segments force small sizes only near themselves: a mesh at size w everywhere
//    would need about 1 / ((√3/4) w²) = 2.3·10^6 triangles; the graded size needs about
//    ∫ dA / ((√3/4) (w + g r)²) over a half disc plus the square at H = 0.141, under 3·10^3:
//    the test allows 10^4;
//  - the triangles next to the notch are good: worst quality at least 0.7, with and without
//    --size (before: 0.11 with --size 0.05 and 0.29 by Delaunay refinement).
// Every mesh is certified.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/generators/mesh_domain_2.h"

namespace {

using namespace certimesh::generators;

constexpr double kNotch = 1e-3;

PlanarDomain square_with_notch() {
  PlanarDomain d;
  d.points = {{0, 0}, {0.5, 0}, {0.5, -kNotch}, {0.5 + kNotch, -kNotch}, {0.5 + kNotch, 0}, {1, 0}, {1, 1}, {0, 1}};
  for (std::uint32_t i = 0; i < 8; ++i) d.segments.push_back({i, (i + 1) % 8, 1});
  return d;
}

struct Case {
  MeshAlgorithm2 algorithm;
  double size;
};

class Grading : public ::testing::TestWithParam<Case> {};

TEST_P(Grading, ANotchForcesSmallGoodTrianglesOnlyNearItself) {
  const PlanarDomain d = square_with_notch();
  MeshDomainOptions2 options;
  options.algorithm = GetParam().algorithm;
  options.size.uniform_size = GetParam().size;
  const MeshDomainResult2 r = mesh_domain_2(d, options);
  const certimesh::io::MeshData domain = to_mesh_data(d);
  const auto report = certimesh::certificate::check_mesh(r.mesh, &domain);
  ASSERT_TRUE(report.valid) << report.finding.message;

  EXPECT_GE(r.stats.worst_quality, 0.7);
  EXPECT_LT(r.mesh.triangle_count(), 10000u);
  EXPECT_GT(r.mesh.triangle_count(), 100u);  // the notch is resolved, not a handful of slivers

  const auto& c = r.mesh.coordinates;
  double longest_at_notch = 0.0;
  for (std::size_t t = 0; t < r.mesh.triangle_count(); ++t) {
    const auto v = [&](int i) { return r.mesh.triangles[3 * t + static_cast<std::size_t>(i)]; };
    const bool at_notch = v(0) - 1 < 4 || v(1) - 1 < 4 || v(2) - 1 < 4;  // input vertices 1-4: the notch
    if (!at_notch) continue;
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = v(i), b = v((i + 1) % 3);
      longest_at_notch = std::max(longest_at_notch, std::hypot(c[2 * a] - c[2 * b], c[2 * a + 1] - c[2 * b + 1]));
    }
  }
  EXPECT_GT(longest_at_notch, 0.0);
  EXPECT_LE(longest_at_notch, 5 * kNotch);
}

INSTANTIATE_TEST_SUITE_P(DefaultAndGivenSize, Grading,
                         ::testing::Values(Case{MeshAlgorithm2::advancing_front, 0.0},
                                           Case{MeshAlgorithm2::advancing_front, 0.05},
                                           Case{MeshAlgorithm2::delaunay, 0.0}, Case{MeshAlgorithm2::delaunay, 0.05}),
                         [](const ::testing::TestParamInfo<Case>& p) {
                           return std::string(p.param.algorithm == MeshAlgorithm2::delaunay ? "delaunay" : "front") +
                                  (p.param.size > 0.0 ? "_size" : "_default");
                         });

}  // namespace
