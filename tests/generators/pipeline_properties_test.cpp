// The 2D pipeline over generated domains (fuzz/generators/.../planar_domains.h: star
// polygons, combs, nested holes, near-collinear chains, cocircular lattice points, internal
// cuts at tiny angles, cracks; 3 to 10^4 boundary vertices; scales 2^-35 to 2^45): every valid
// domain is meshed by both algorithms and the independent certificate accepts the mesh
// against the domain; every invalid domain is refused with the kind and the segment ids the
// mutation planted. Seeds are explicit, so a failure names its case and reproduces.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/fuzz/planar_domains.h"
#include "certimesh/generators/domain/domain_problem.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/generators/mesh_domain_2.h"

namespace {

using namespace certimesh::generators;
using certimesh::fuzz::DomainFamily;
using certimesh::fuzz::DomainMutation;
using certimesh::fuzz::PlanarDomainCase;

#if defined(__SANITIZE_ADDRESS__)
constexpr std::uint64_t kSeedsPerFamily = 6;  // the sanitizer build is ~10x slower
constexpr std::size_t kLargest = 2000;
#else
constexpr std::uint64_t kSeedsPerFamily = 14;
constexpr std::size_t kLargest = 10000;
#endif

// The boundary vertex count of seed `seed`: mostly small, some up to kMaxRandom.
std::size_t vertices_for(std::uint64_t seed) {
  constexpr std::size_t sizes[] = {3, 4, 7, 12, 20, 40, 80, 150, 300};
  return sizes[seed % std::size(sizes)];
}

int exponent_for(std::uint64_t seed) {
  constexpr int exponents[] = {0, -30, 40, -35, 45, 7, -3};
  return exponents[(seed / 3) % std::size(exponents)];
}

// Meshes with `algorithm` and certifies; a uniform size of 1/20 of the bounding box on odd
// seeds, automatic sizing from the boundary (growth 1.3: with 1.0 a hole of lattice points of
// radius 1105 inside a circle of radius 32045 asks for 10^6 triangles) on even ones.
void mesh_and_certify(const PlanarDomainCase& c, MeshAlgorithm2 algorithm, std::uint64_t seed) {
  MeshDomainOptions2 options;
  options.algorithm = algorithm;
  options.size.growth = 1.3;
  if (seed % 2 == 1) {
    double lo_x = INFINITY, lo_y = INFINITY, hi_x = -INFINITY, hi_y = -INFINITY;
    for (const Point2& p : c.domain.points) {
      lo_x = std::min(lo_x, p.x), hi_x = std::max(hi_x, p.x);
      lo_y = std::min(lo_y, p.y), hi_y = std::max(hi_y, p.y);
    }
    options.size.uniform_size = std::max(hi_x - lo_x, hi_y - lo_y) / 20.0;
  }
  MeshDomainResult2 result;
  try {
    result = mesh_domain_2(c.domain, options);
  } catch (const std::exception& e) {
    FAIL() << c.description << ": refused a valid domain: " << e.what();
  }
  const certimesh::io::MeshData domain = to_mesh_data(c.domain);
  const auto report = certimesh::certificate::check_mesh(result.mesh, &domain);
  ASSERT_TRUE(report.valid) << c.description << (algorithm == MeshAlgorithm2::delaunay ? " delaunay" : " front")
                            << ": " << report.finding.message;
}

class ValidFamilies : public ::testing::TestWithParam<int> {};

TEST_P(ValidFamilies, EveryDomainMeshedAndCertifiedByBothAlgorithms) {
  const auto family = static_cast<DomainFamily>(GetParam());
  for (std::uint64_t seed = 1; seed <= kSeedsPerFamily; ++seed) {
    const PlanarDomainCase c =
        certimesh::fuzz::make_valid_domain(family, seed, vertices_for(seed), exponent_for(seed));
    ASSERT_TRUE(validate_domain(c.domain).empty()) << c.description;
    mesh_and_certify(c, MeshAlgorithm2::advancing_front, seed);
    mesh_and_certify(c, MeshAlgorithm2::delaunay, seed);
  }
}

TEST_P(ValidFamilies, LargeBoundariesMeshedAndCertified) {
  const auto family = static_cast<DomainFamily>(GetParam());
  if (family == DomainFamily::tiny_angles) GTEST_SKIP() << "its size is bounded by construction";
  // The front at 10^4 boundary vertices; Delaunay refinement (slower on these, see the issue
  // notes) at a fifth of that.
  const PlanarDomainCase c = certimesh::fuzz::make_valid_domain(family, 7, kLargest, 0);
  mesh_and_certify(c, MeshAlgorithm2::advancing_front, 2);  // automatic sizing
  mesh_and_certify(certimesh::fuzz::make_valid_domain(family, 7, kLargest / 5, 0), MeshAlgorithm2::delaunay, 2);
}

INSTANTIATE_TEST_SUITE_P(Pipeline, ValidFamilies, ::testing::Range(0, certimesh::fuzz::kDomainFamilies),
                         [](const ::testing::TestParamInfo<int>& param_info) {
                           return std::string(
                               certimesh::fuzz::family_name(static_cast<DomainFamily>(param_info.param)));
                         });

class InvalidMutations : public ::testing::TestWithParam<int> {};

TEST_P(InvalidMutations, EveryDomainRefusedWithItsReason) {
  const auto mutation = static_cast<DomainMutation>(GetParam());
  for (std::uint64_t seed = 1; seed <= kSeedsPerFamily; ++seed) {
    const PlanarDomainCase c =
        certimesh::fuzz::make_invalid_domain(mutation, seed, vertices_for(seed), exponent_for(seed));
    if (mutation == DomainMutation::isolated_vertex) {
      // Valid since issue 12 (design decision 8): a vertex on no segment outside the domain is
      // dropped, as Triangle's -j drops it; the mesh does not contain it.
      const MeshDomainResult2 r = mesh_domain_2(c.domain, MeshDomainOptions2{});
      EXPECT_EQ(r.stats.dropped_vertices, 1u) << c.description;
      const Point2 far = c.domain.points[c.vertices.front()];
      for (std::size_t v = 0; v < r.mesh.point_count(); ++v)
        EXPECT_FALSE(r.mesh.coordinates[2 * v] == far.x && r.mesh.coordinates[2 * v + 1] == far.y) << c.description;
      continue;
    }
    try {
      mesh_domain_2(c.domain, MeshDomainOptions2{});
      ADD_FAILURE() << c.description << ": accepted";
    } catch (const InvalidDomain& e) {
      const auto& problems = e.problems();
      const auto match = std::find_if(problems.begin(), problems.end(), [&](const DomainProblem& p) {
        return p.kind == c.expected &&
               std::all_of(c.segments.begin(), c.segments.end(), [&](std::uint32_t s) {
                 return std::find(p.segments.begin(), p.segments.end(), s) != p.segments.end();
               });
      });
      EXPECT_NE(match, problems.end()) << c.description << ": expected " << to_string(c.expected) << ", got "
                                       << (problems.empty() ? "nothing" : problems.front().message);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Pipeline, InvalidMutations, ::testing::Range(0, certimesh::fuzz::kDomainMutations),
                         [](const ::testing::TestParamInfo<int>& param_info) {
                           return std::string(
                               certimesh::fuzz::mutation_name(static_cast<DomainMutation>(param_info.param)));
                         });

}  // namespace
