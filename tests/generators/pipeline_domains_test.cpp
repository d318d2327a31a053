// The 2D pipeline (mesh_domain_2) on hand-made domains: every mesh is certified against its
// domain by the independent checker, with both algorithms; region labels against the
// geometry; invalid domains refused with the right reason; determinism; sizes followed.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/generators/domain/domain_problem.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/generators/mesh_domain_2.h"

namespace {

using namespace certimesh::generators;
using certimesh::io::MeshData;

PlanarDomain polygon(const std::vector<Point2>& ring, certimesh::io::Label label = 1) {
  PlanarDomain d;
  d.points = ring;
  for (std::uint32_t i = 0; i < ring.size(); ++i) {
    d.segments.push_back({i, static_cast<std::uint32_t>((i + 1) % ring.size()), label});
  }
  return d;
}

void add_loop(PlanarDomain& d, const std::vector<Point2>& ring, certimesh::io::Label label) {
  const auto base = static_cast<std::uint32_t>(d.points.size());
  for (std::uint32_t i = 0; i < ring.size(); ++i) {
    d.points.push_back(ring[i]);
    d.segments.push_back({base + i, base + static_cast<std::uint32_t>((i + 1) % ring.size()), label});
  }
}

std::vector<Point2> square(double x0, double y0, double side) {
  return {{x0, y0}, {x0 + side, y0}, {x0 + side, y0 + side}, {x0, y0 + side}};
}

// Meshes and certifies; returns the mesh.
MeshData mesh_and_certify(const PlanarDomain& d, MeshAlgorithm2 algorithm, double size) {
  MeshDomainOptions2 options;
  options.algorithm = algorithm;
  options.size.uniform_size = size;
  const MeshDomainResult2 result = mesh_domain_2(d, options);
  const MeshData domain_data = to_mesh_data(d);
  const auto report = certimesh::certificate::check_mesh(result.mesh, &domain_data);
  EXPECT_TRUE(report.valid) << report.finding.message;
  EXPECT_EQ(result.stats.triangles, result.mesh.triangle_count());
  return result.mesh;
}

class BothAlgorithms : public ::testing::TestWithParam<MeshAlgorithm2> {};

TEST_P(BothAlgorithms, UnitSquareIsCertifiedAndFollowsTheSize) {
  const MeshData m = mesh_and_certify(polygon(square(0, 0, 1)), GetParam(), 0.05);
  // Equilateral triangles of side h tile area A with about 4A/(√3 h²) of them.
  const double expected = 4.0 / (std::sqrt(3.0) * 0.05 * 0.05);
  EXPECT_GT(static_cast<double>(m.triangle_count()), 0.6 * expected);
  // Delaunay refinement bounds the longest side by h, so its triangles are smaller on average.
  EXPECT_LT(static_cast<double>(m.triangle_count()), 2.5 * expected);
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const auto a = m.triangles[3 * t + static_cast<std::size_t>(i)];
      const auto b = m.triangles[3 * t + static_cast<std::size_t>((i + 1) % 3)];
      const double length = std::hypot(m.coordinates[2 * a] - m.coordinates[2 * b],
                                       m.coordinates[2 * a + 1] - m.coordinates[2 * b + 1]);
      EXPECT_LT(length, 1.6 * 0.05) << "triangle " << t;
    }
  }
}

TEST_P(BothAlgorithms, SquareWithHoleAndTwoComponents) {
  PlanarDomain d = polygon(square(0, 0, 1));
  add_loop(d, square(0.4, 0.4, 0.2), 2);
  d.holes.push_back({0.5, 0.5});
  add_loop(d, square(2, 0, 1), 3);  // a second component
  mesh_and_certify(d, GetParam(), 0.1);
}

TEST_P(BothAlgorithms, CrackIsAnInteriorConstraint) {
  // A crack from the middle of the bottom edge into the square: domain on both sides.
  PlanarDomain d = polygon({{0, 0}, {0.5, 0}, {1, 0}, {1, 1}, {0, 1}});
  d.points.push_back({0.5, 0.25});
  d.points.push_back({0.5, 0.5});
  d.segments.push_back({1, 5, 4});
  d.segments.push_back({5, 6, 4});
  const MeshData m = mesh_and_certify(d, GetParam(), 0.1);
  // Both crack segments are split into mesh edges that appear among the output segments.
  std::size_t crack_pieces = 0;
  for (std::size_t s = 0; s < m.segment_count(); ++s) crack_pieces += m.segment_labels[s] == 4;
  EXPECT_GE(crack_pieces, 2u);
}

TEST_P(BothAlgorithms, RegionLabelsFollowTheInterface) {
  // Two regions separated by the segment x = 1; seeds label them 7 (left) and 9 (right).
  PlanarDomain d = polygon({{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}});
  d.segments.push_back({1, 4, 5});
  d.regions = {{{0.5, 0.5}, 7}, {{1.5, 0.5}, 9}};
  const MeshData m = mesh_and_certify(d, GetParam(), 0.2);
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    double cx = 0;
    for (int i = 0; i < 3; ++i) cx += m.coordinates[2 * m.triangles[3 * t + static_cast<std::size_t>(i)]];
    EXPECT_EQ(m.triangle_labels[t], cx / 3 < 1.0 ? 7 : 9) << "triangle " << t;
  }
}

TEST_P(BothAlgorithms, TinyAndHugeCoordinates) {
  for (const double scale : {std::ldexp(1.0, -30) * 3.0, 1e-9, 1e12}) {
    std::vector<Point2> ring = {{0, 0}, {1, 0.1}, {1.3, 1}, {0.2, 0.8}};
    for (Point2& p : ring) p = {p.x * scale, p.y * scale};
    mesh_and_certify(polygon(ring), GetParam(), 0.1 * scale);
  }
}

TEST_P(BothAlgorithms, AutomaticSizeFromTheBoundary) {
  PlanarDomain d = polygon({{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  MeshDomainOptions2 options;
  options.algorithm = GetParam();
  const MeshDomainResult2 r = mesh_domain_2(d, options);
  const MeshData domain_data = to_mesh_data(d);
  EXPECT_TRUE(certimesh::certificate::check_mesh(r.mesh, &domain_data).valid);
}

TEST_P(BothAlgorithms, SameInputSameOutput) {
  PlanarDomain d = polygon({{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 2}, {0, 2}});
  MeshDomainOptions2 options;
  options.algorithm = GetParam();
  options.size.uniform_size = 0.07;
  EXPECT_EQ(mesh_domain_2(d, options).mesh, mesh_domain_2(d, options).mesh);
}

INSTANTIATE_TEST_SUITE_P(Pipeline, BothAlgorithms,
                         ::testing::Values(MeshAlgorithm2::advancing_front, MeshAlgorithm2::delaunay),
                         [](const ::testing::TestParamInfo<MeshAlgorithm2>& param_info) {
                           return std::string(param_info.param == MeshAlgorithm2::delaunay ? "delaunay" : "front");
                         });

DomainProblemKind refusal_of(const PlanarDomain& d) {
  try {
    mesh_domain_2(d, MeshDomainOptions2{});
  } catch (const InvalidDomain& e) {
    EXPECT_FALSE(e.problems().empty());
    return e.problems().empty() ? DomainProblemKind::wrong_dimension : e.problems().front().kind;
  }
  ADD_FAILURE() << "the domain was accepted";
  return DomainProblemKind::wrong_dimension;
}

TEST(PipelineRefusals, SegmentOutsideTheDomainIsEaten) {
  // A square plus a dangling segment outside it: Triangle's holes (here the hull) eat it.
  PlanarDomain d = polygon(square(0, 0, 1));
  d.points.push_back({2, 0});
  d.points.push_back({3, 1});
  d.segments.push_back({4, 5, 0});
  const MeshDomainResult2 r = mesh_domain_2(d, MeshDomainOptions2{});
  EXPECT_EQ(r.stats.eaten_segments, 1u);
  EXPECT_EQ(r.stats.dropped_vertices, 2u);
  for (std::size_t v = 0; v < r.mesh.point_count(); ++v) EXPECT_LE(r.mesh.coordinates[2 * v], 1.0);
}

TEST(PipelineRefusals, OpenPolylineIsAnOpenLoop) {
  PlanarDomain d;
  d.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  d.segments = {{0, 1, 0}, {1, 2, 0}, {2, 3, 0}};  // not closed
  EXPECT_EQ(refusal_of(d), DomainProblemKind::open_boundary);
}

TEST(PipelineRefusals, EverythingAHoleIsEmpty) {
  PlanarDomain d = polygon(square(0, 0, 1));
  d.holes.push_back({0.5, 0.5});
  EXPECT_EQ(refusal_of(d), DomainProblemKind::empty_domain);
}

TEST(PipelineRefusals, CrossingSegments) {
  PlanarDomain d = polygon({{0, 0}, {1, 1}, {1, 0}, {0, 1}});  // a bow tie
  EXPECT_EQ(refusal_of(d), DomainProblemKind::segments_cross);
}

}  // namespace
