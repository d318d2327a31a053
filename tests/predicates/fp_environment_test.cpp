// The kernel was built in the floating-point environment its proofs assume: round to
// nearest, binary64 evaluation, no FMA contraction (fp_environment.h). The companion CTest
// predicates.no_fma_in_kernel_object_code scans the kernel's object code for FMA.
#include <gtest/gtest.h>

#include <cfenv>

#include "certimesh/predicates/fp_environment.h"
#include "certimesh/predicates/orient2d.h"

namespace certimesh::test {
namespace {

namespace pr = certimesh::predicates;

TEST(FpEnvironment, ProbeIsOk) {
  const pr::FpEnvironmentReport r = pr::probe_fp_environment();
  std::cout << "[fp environment] " << r.describe() << std::endl;
  EXPECT_TRUE(r.round_to_nearest);
  EXPECT_TRUE(r.binary64_evaluation);
  EXPECT_TRUE(r.no_contraction);
  EXPECT_TRUE(r.ok());
}

// The probe is not vacuous: under a directed rounding mode it must report it.
TEST(FpEnvironment, ProbeDetectsDirectedRounding) {
  ASSERT_EQ(std::fesetround(FE_UPWARD), 0);
  const pr::FpEnvironmentReport r = pr::probe_fp_environment();
  std::fesetround(FE_TONEAREST);
  EXPECT_FALSE(r.round_to_nearest);
  EXPECT_FALSE(r.ok());
}

}  // namespace
}  // namespace certimesh::test
