// Scale invariance of the 2D pipeline (issue 12, item 12): a domain whose every coordinate
// is multiplied by 2^k gives the same mesh with every coordinate multiplied by 2^k, bit for
// bit, the same connectivity and labels -- for both algorithms, the default (boundary-adapted)
// size and a given --size scaled with the domain. The oracle is the relation itself: the
// mesh of the unscaled domain, scaled exactly by std::ldexp. Every mesh is certified.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/fuzz/planar_domains.h"
#include "certimesh/generators/domain/default_domains.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/generators/mesh_domain_2.h"

namespace {

using namespace certimesh::generators;

// A NACA 0012 profile (cosine spacing, dense at both edges) as a hole in a box: segments
// from 10^-4 to 10.
PlanarDomain airfoil_in_box(int n) {
  PlanarDomain d;
  d.points = {{-3, -3}, {4, -3}, {4, 3}, {-3, 3}};
  const auto thickness = [](double x) {
    return 0.6 * (0.2969 * std::sqrt(x) - 0.1260 * x - 0.3516 * x * x + 0.2843 * x * x * x - 0.1036 * x * x * x * x);
  };
  std::vector<double> xs;
  for (int i = 0; i < n; ++i) xs.push_back(0.5 * (1 - std::cos(3.14159265358979323846 * i / (n - 1))));
  for (int i = n - 1; i >= 0; --i) d.points.push_back({xs[static_cast<std::size_t>(i)], thickness(xs[static_cast<std::size_t>(i)])});
  for (int i = 1; i + 1 < n; ++i) d.points.push_back({xs[static_cast<std::size_t>(i)], -thickness(xs[static_cast<std::size_t>(i)])});
  for (std::uint32_t i = 0; i < 4; ++i) d.segments.push_back({i, (i + 1) % 4, 1});
  const auto m = static_cast<std::uint32_t>(d.points.size() - 4);
  for (std::uint32_t i = 0; i < m; ++i) d.segments.push_back({4 + i, 4 + (i + 1) % m, 2});
  d.holes = {{0.3, 0.0}};
  return d;
}

PlanarDomain scaled(PlanarDomain d, int k) {
  for (Point2& p : d.points) p = {std::ldexp(p.x, k), std::ldexp(p.y, k)};
  for (Point2& p : d.holes) p = {std::ldexp(p.x, k), std::ldexp(p.y, k)};
  for (RegionSeed& r : d.regions) r.point = {std::ldexp(r.point.x, k), std::ldexp(r.point.y, k)};
  return d;
}

struct Case {
  std::string name;
  PlanarDomain domain;
  double size;  // 0: the default size
};

std::vector<Case> cases() {
  std::vector<Case> out;
  out.push_back({"plate", plate_with_holes_and_crack(), 0.0});
  out.push_back({"plate --size 0.1", plate_with_holes_and_crack(), 0.1});
  out.push_back({"airfoil", airfoil_in_box(60), 0.0});
  out.push_back({"star with crack",
                 certimesh::fuzz::make_valid_domain(certimesh::fuzz::DomainFamily::star_with_crack, 5, 40, 0).domain, 0.0});
  out.push_back({"tiny angles",
                 certimesh::fuzz::make_valid_domain(certimesh::fuzz::DomainFamily::tiny_angles, 3, 12, 0).domain, 0.0});
  return out;
}

MeshDomainResult2 mesh(const PlanarDomain& d, MeshAlgorithm2 algorithm, double size) {
  MeshDomainOptions2 options;
  options.algorithm = algorithm;
  options.size.uniform_size = size;
  MeshDomainResult2 r = mesh_domain_2(d, options);
  const certimesh::io::MeshData domain = to_mesh_data(d);
  const auto report = certimesh::certificate::check_mesh(r.mesh, &domain);
  EXPECT_TRUE(report.valid) << report.finding.message;
  return r;
}

class ScaleInvariance : public ::testing::TestWithParam<MeshAlgorithm2> {};

TEST_P(ScaleInvariance, PowerOfTwoScalingScalesTheMeshBitForBit) {
  for (const Case& c : cases()) {
    const MeshDomainResult2 reference = mesh(c.domain, GetParam(), c.size);
    ASSERT_GT(reference.mesh.triangle_count(), 0u) << c.name;
    for (const int k : {-30, -60, 40, 500, -900}) {
      SCOPED_TRACE(c.name + " scaled by 2^" + std::to_string(k));
      const MeshDomainResult2 r = mesh(scaled(c.domain, k), GetParam(), c.size > 0.0 ? std::ldexp(c.size, k) : 0.0);
      ASSERT_EQ(r.mesh.triangles, reference.mesh.triangles);
      ASSERT_EQ(r.mesh.triangle_labels, reference.mesh.triangle_labels);
      ASSERT_EQ(r.mesh.segments, reference.mesh.segments);
      ASSERT_EQ(r.mesh.coordinates.size(), reference.mesh.coordinates.size());
      std::size_t differing = 0;
      for (std::size_t i = 0; i < r.mesh.coordinates.size(); ++i)
        differing += r.mesh.coordinates[i] != std::ldexp(reference.mesh.coordinates[i], k);
      EXPECT_EQ(differing, 0u);
      EXPECT_EQ(r.stats.worst_quality, reference.stats.worst_quality);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(BothAlgorithms, ScaleInvariance,
                         ::testing::Values(MeshAlgorithm2::advancing_front, MeshAlgorithm2::delaunay),
                         [](const ::testing::TestParamInfo<MeshAlgorithm2>& p) {
                           return std::string(p.param == MeshAlgorithm2::delaunay ? "delaunay" : "front");
                         });

}  // namespace
