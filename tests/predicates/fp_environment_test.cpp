// The kernel was built in the floating-point environment its proofs assume: round to
// nearest, binary64 evaluation, no FMA contraction (fp_environment.h). The companion CTest
// predicates.no_fma_in_kernel_object_code scans the kernel's object code for FMA.
#include <gtest/gtest.h>

#include <cfenv>
#include <functional>
#include <iterator>
#include <thread>

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

// The exact stages check the mode once per thread, at its first exact stage, and the mode
// itself is per thread: each case runs in a thread of its own, which sets the mode, calls
// `query` and reports whether it threw FpEnvironmentError.
template <class SetMode, class Query>
bool refused_in_fresh_thread(SetMode set_mode, Query query) {
  bool refused = false;
  std::thread([&] {
    set_mode();
    try {
      query();
    } catch (const pr::FpEnvironmentError&) {
      refused = true;
    }
  }).join();
  return refused;
}

// In round-to-nearest the exact stages answer (the degenerate signs are zero) ...
TEST(FpEnvironment, ExactStagesAnswerInRoundToNearest) {
  EXPECT_FALSE(refused_in_fresh_thread([] {}, call_every_exact_stage));
  EXPECT_EQ(pr::orient2d({0, 0}, {1, 1}, {2, 2}), pr::Sign::zero);
}

// ... and each of them refuses every directed mode, whose rounding errors the proofs do
// not cover.
TEST(FpEnvironment, ExactStagesRefuseDirectedRounding) {
  const std::function<void()> stages[] = {
      [] { (void)pr::orient2d({0, 0}, {1, 1}, {2, 2}); },
      [] { (void)pr::orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}); },
      [] { (void)pr::incircle({1, 0}, {0, 1}, {-1, 0}, {0, -1}); },
      [] { (void)pr::insphere({1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, 0, 1}, {0, -1, 0}); }};
  for (const int mode : {FE_UPWARD, FE_DOWNWARD, FE_TOWARDZERO})
    for (std::size_t i = 0; i < std::size(stages); ++i)
      EXPECT_TRUE(refused_in_fresh_thread([mode] { std::fesetround(mode); }, stages[i]))
          << "mode " << mode << ", predicate " << i;
}

#if defined(CERTIMESH_TEST_HAS_MXCSR)
// Flush-to-zero and denormals-are-zero (what crtfastmath.o sets for a -ffast-math link)
// break the underflow terms of the bounds: refused, and reported by the probe.
TEST(FpEnvironment, ExactStagesRefuseFlushToZero) {
  for (const unsigned bits : {0x8000u, 0x0040u}) {  // FTZ, DAZ
    const auto set = [bits] { _mm_setcsr(_mm_getcsr() | bits); };
    EXPECT_TRUE(refused_in_fresh_thread(set, call_every_exact_stage)) << "MXCSR bit " << bits;
    bool kept = true;
    refused_in_fresh_thread(set, [&kept] { kept = pr::probe_fp_environment().subnormals_kept; });
    EXPECT_FALSE(kept) << "MXCSR bit " << bits;
  }
}

// Rounding set through MXCSR alone (as _MM_SET_ROUNDING_MODE does) is seen too.
TEST(FpEnvironment, ExactStagesSeeMxcsrRounding) {
  const auto round_down = [] { _mm_setcsr((_mm_getcsr() & ~0x6000u) | 0x2000u); };
  EXPECT_TRUE(refused_in_fresh_thread(round_down, call_every_exact_stage));
}
#endif

}  // namespace
}  // namespace certimesh::test
