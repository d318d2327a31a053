// The kernel was built in the floating-point environment its proofs assume: round to
// nearest, binary64 evaluation, no FMA contraction (fp_environment.h). The companion CTest
// predicates.no_fma_in_kernel_object_code scans the kernel's object code for FMA.
#include <gtest/gtest.h>

#include <cfenv>

#if defined(__SSE2__) && (defined(__x86_64__) || defined(__i386__))
#include <xmmintrin.h>
#define CERTIMESH_TEST_HAS_MXCSR 1
#endif

#include "certimesh/predicates/fp_environment.h"
#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/insphere.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"

namespace certimesh::test {
namespace {

namespace pr = certimesh::predicates;

TEST(FpEnvironment, ProbeIsOk) {
  const pr::FpEnvironmentReport r = pr::probe_fp_environment();
  std::cout << "[fp environment] " << r.describe() << std::endl;
  EXPECT_TRUE(r.round_to_nearest);
  EXPECT_TRUE(r.subnormals_kept);
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

// Degenerate inputs: every filter is uncertain, so every call reaches its exact stage.
void call_every_exact_stage() {
  (void)pr::orient2d({0, 0}, {1, 1}, {2, 2});
  (void)pr::orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0});
  (void)pr::incircle({1, 0}, {0, 1}, {-1, 0}, {0, -1});
  (void)pr::insphere({1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {0, -1, 0});
}

// In round-to-nearest the exact stages answer (the degenerate signs are zero) ...
TEST(FpEnvironment, ExactStagesAnswerInRoundToNearest) {
  EXPECT_NO_THROW(call_every_exact_stage());
  EXPECT_EQ(pr::orient2d({0, 0}, {1, 1}, {2, 2}), pr::Sign::zero);
}

// ... and refuse every directed mode, whose rounding errors the proofs do not cover.
TEST(FpEnvironment, ExactStagesRefuseDirectedRounding) {
  for (const int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO}) {
    ASSERT_EQ(std::fesetround(mode), 0);
    EXPECT_THROW((void)pr::orient2d({0, 0}, {1, 1}, {2, 2}), pr::FpEnvironmentError);
    EXPECT_THROW((void)pr::orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}),
                 pr::FpEnvironmentError);
    EXPECT_THROW((void)pr::incircle({1, 0}, {0, 1}, {-1, 0}, {0, -1}), pr::FpEnvironmentError);
    EXPECT_THROW((void)pr::insphere({1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {0, -1, 0}),
                 pr::FpEnvironmentError);
    std::fesetround(FE_TONEAREST);
  }
  EXPECT_NO_THROW(call_every_exact_stage());
}

#if defined(CERTIMESH_TEST_HAS_MXCSR)
// Flush-to-zero and denormals-are-zero (what crtfastmath.o sets for a -ffast-math link)
// break the underflow terms of the bounds: refused, and reported by the probe.
TEST(FpEnvironment, ExactStagesRefuseFlushToZero) {
  const unsigned saved = _mm_getcsr();
  for (const unsigned bits : {0x8000u, 0x0040u}) {  // FTZ, DAZ
    _mm_setcsr(saved | bits);
    const pr::FpEnvironmentReport r = pr::probe_fp_environment();
    bool threw = false;
    try {
      call_every_exact_stage();
    } catch (const pr::FpEnvironmentError&) {
      threw = true;
    }
    _mm_setcsr(saved);
    EXPECT_TRUE(threw) << "MXCSR bit " << bits;
    EXPECT_FALSE(r.subnormals_kept);
    EXPECT_FALSE(r.ok());
  }
}

// Rounding set through MXCSR alone (as _MM_SET_ROUNDING_MODE does) is seen too.
TEST(FpEnvironment, ExactStagesSeeMxcsrRounding) {
  const unsigned saved = _mm_getcsr();
  _mm_setcsr((saved & ~0x6000u) | 0x2000u);  // round down, x87 control word untouched
  bool threw = false;
  try {
    (void)pr::orient2d({0, 0}, {1, 1}, {2, 2});
  } catch (const pr::FpEnvironmentError&) {
    threw = true;
  }
  _mm_setcsr(saved);
  EXPECT_TRUE(threw);
}
#endif

}  // namespace
}  // namespace certimesh::test
