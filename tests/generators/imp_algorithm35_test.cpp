// Algorithm 35 (improve_quality_2): the worst quality never decreases (runs with growing
// budgets N1 are prefixes of one deterministic run, so their final worst qualities must be
// non-decreasing), the iteration count stays within N1, two runs are bit-identical, an easy
// case (a perturbed grid) reaches Q0, every result passes the certificate with its domain, and
// an invalid input is refused with the element named.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "certimesh/generators/improvement/quality_improvement_2.h"
#include "certimesh/topology/quality.h"
#include "imp_fixtures.h"

namespace certimesh {
namespace {

using generators::ImprovementOptions2;
using generators::improve_quality_2;
using imp_testing::TriangleMesh2;

fuzz::GridSpec jittered_grid(int n, std::uint64_t seed) {
  fuzz::GridSpec g;
  g.cells = {n, n, 1};
  g.jitter_seed = seed;
  return g;
}

// The worst shape quality, recomputed from scratch.
double worst_shape_quality(const TriangleMesh2& mesh) {
  double q = 2.0;
  for (std::uint32_t s = 0; s < mesh.element_slot_count(); ++s) {
    const topology::ElementId e{s};
    if (mesh.is_live(e)) q = std::min(q, topology::element_quality(mesh, e));
  }
  return q;
}

RC_GTEST_PROP(imp_Algorithm35, WorstNeverDecreasesAndBudgetHolds, ()) {
  const auto grid = jittered_grid(*rc::gen::inRange(3, imp_testing::sanitizer_divisor == 1 ? 8 : 5), *rc::gen::inRange<std::uint64_t>(1, 1u << 30));
  const io::MeshData domain = fuzz::square_domain(grid);
  const io::MeshData start = fuzz::kuhn_grid(grid);
  ImprovementOptions2 options;
  options.target_quality = 0.99;
  if (*rc::gen::arbitrary<bool>()) options.size.uniform_size = *rc::gen::element(0.5, 0.8, 1.6);
  options.coarsen_straight_boundary = *rc::gen::arbitrary<bool>();
  double previous = -1.0;
  // Budgets 1, 2, 4, ..., 64 (1, 10, 100 under the sanitizers, 5-10x slower).
  const std::uint64_t growth = imp_testing::sanitizer_divisor == 1 ? 2 : 10;
  for (std::uint64_t budget = 1; budget <= 100; budget *= growth) {
    TriangleMesh2 mesh = imp_testing::to_mesh(start);
    const mpq_class area = imp_testing::twice_signed_area(mesh);
    options.max_operations = budget;
    const auto stats = improve_quality_2(mesh, options);
    RC_ASSERT(stats.iterations <= budget);
    RC_ASSERT(stats.final_worst >= stats.initial_worst);
    RC_ASSERT(stats.final_worst >= previous);
    previous = stats.final_worst;
    const auto report = imp_testing::certify(mesh, &domain);
    if (!report.valid) RC_FAIL(report.finding.message);
    RC_ASSERT(imp_testing::twice_signed_area(mesh) == area);
    if (options.size.automatic()) RC_ASSERT(worst_shape_quality(mesh) == stats.final_worst);
  }
}

TEST(imp_Algorithm35, TwoRunsAreBitIdentical) {
  const io::MeshData start = fuzz::kuhn_grid(jittered_grid(imp_testing::sanitizer_divisor == 1 ? 10 : 6, 77));
  ImprovementOptions2 options;
  options.size.uniform_size = 0.7;  // every operation has work to do
  io::MeshData results[2];
  generators::ImprovementStats2 stats[2];
  for (int run = 0; run < 2; ++run) {
    TriangleMesh2 mesh = imp_testing::to_mesh(start);
    stats[run] = improve_quality_2(mesh, options);
    results[run] = topology::to_mesh_data(mesh);
  }
  EXPECT_EQ(results[0].coordinates, results[1].coordinates);  // doubles compared exactly
  EXPECT_EQ(results[0].triangles, results[1].triangles);
  EXPECT_EQ(stats[0].iterations, stats[1].iterations);
  EXPECT_EQ(stats[0].successes, stats[1].successes);
  EXPECT_EQ(stats[0].final_worst, stats[1].final_worst);
}

TEST(imp_Algorithm35, PerturbedGridReachesTheTarget) {
  // Kuhn triangles are isosceles right triangles (0.8915); jitter spoils them. Node shifts and
  // flips bring the worst back above 0.8 (the boundary stays a square grid).
  const auto grid = jittered_grid(12, 5);
  const io::MeshData domain = fuzz::square_domain(grid);
  TriangleMesh2 mesh = imp_testing::to_mesh(fuzz::kuhn_grid(grid));
  ImprovementOptions2 options;
  options.target_quality = 0.8;
  ASSERT_LT(worst_shape_quality(mesh), 0.8);
  std::uint64_t reports = 0;
  const auto stats = improve_quality_2(mesh, options, [&](const generators::Progress& p) {
    EXPECT_EQ(p.stage, "improvement");
    ++reports;
  });
  EXPECT_TRUE(stats.reached_target);
  EXPECT_GE(worst_shape_quality(mesh), 0.8);
  EXPECT_EQ(worst_shape_quality(mesh), stats.final_worst);
  EXPECT_GT(reports, 0u);
  EXPECT_LE(reports, 201u);
  EXPECT_TRUE(imp_testing::certify(mesh, &domain).valid);
}

TEST(imp_Algorithm35, SizeAwareQualityRegradesAndStaysValid) {
  // Size 0.45 on unit cells: insertions must refine; the result is valid and better.
  const auto grid = jittered_grid(6, 9);
  const io::MeshData domain = fuzz::square_domain(grid);
  TriangleMesh2 mesh = imp_testing::to_mesh(fuzz::kuhn_grid(grid));
  const std::size_t before = mesh.element_count();
  ImprovementOptions2 options;
  options.size.uniform_size = 0.45;
  const auto stats = improve_quality_2(mesh, options);
  EXPECT_GT(stats.successes[0], 0u);  // insert on edge
  EXPECT_GT(mesh.element_count(), before);
  EXPECT_GT(stats.final_worst, stats.initial_worst);
  EXPECT_GT(stats.final_mean, stats.initial_mean);
  const auto report = imp_testing::certify(mesh, &domain);
  EXPECT_TRUE(report.valid) << report.finding.message;
}

TEST(imp_Algorithm35, ClockwiseElementIsRefusedWithItsId) {
  TriangleMesh2 mesh;
  const auto a = mesh.add_vertex({0, 0}), b = mesh.add_vertex({1, 0}), c = mesh.add_vertex({0, 1});
  mesh.add_element({a, c, b});
  try {
    improve_quality_2(mesh, ImprovementOptions2{});
    FAIL() << "a clockwise element was accepted";
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("element 0"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace certimesh
