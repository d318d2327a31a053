#include "certimesh/predicates/fp_environment.h"

#include <cfenv>
#include <cfloat>

#if defined(__SSE2__) && (defined(__x86_64__) || defined(__i386__))
#include <xmmintrin.h>
#define CERTIMESH_HAS_MXCSR 1
#else
#define CERTIMESH_HAS_MXCSR 0
#endif

namespace certimesh::predicates {

namespace {

// With contraction, x*y - x*y becomes fma(x, y, -(x*y)): the rounding error of x*y, not 0.
// volatile keeps the compiler from folding the expression at compile time.
double contraction_probe() {
  volatile double vx = 1.0 + 0x1p-30;
  volatile double vy = 1.0 - 0x1p-30;
  const double x = vx, y = vy;
  return x * y - x * y;
}

// On x86 the kernel's doubles live in SSE registers, whose mode is MXCSR (fegetround reads
// only the x87 control word in glibc, and _mm_setcsr changes MXCSR alone): read it directly.
#if CERTIMESH_HAS_MXCSR
constexpr unsigned mxcsr_rounding = 0x6000, mxcsr_ftz = 0x8000, mxcsr_daz = 0x0040;
#endif

bool rounds_to_nearest() noexcept {
#if CERTIMESH_HAS_MXCSR
  return (_mm_getcsr() & mxcsr_rounding) == 0 && std::fegetround() == FE_TONEAREST;
#else
  return std::fegetround() == FE_TONEAREST;
#endif
}

bool keeps_subnormals() noexcept {
#if CERTIMESH_HAS_MXCSR
  return (_mm_getcsr() & (mxcsr_ftz | mxcsr_daz)) == 0;
#else
  return true;  // not probed on this target: documented in proofs/README.md section 1
#endif
}

}  // namespace

FpEnvironmentError::FpEnvironmentError(const std::string& predicate)
    : std::domain_error(predicate +
                        ": the floating-point mode is not round-to-nearest with subnormals "
                        "(fesetround, or flush-to-zero set e.g. by code linked with "
                        "-ffast-math): the filters' proofs do not hold") {}

// Once per thread, at its first exact stage: reading MXCSR on every call measured 20 -> 31 ns
// on a degenerate orient2d (the cheapest exact stage), a cost the grid-like inputs that live
// in the exact stages would pay throughout. A mode changed later in the same thread is
// caught by probe_fp_environment() only (proofs/README.md section 1).
void detail::require_proven_fp_mode(const char* predicate) {
  thread_local bool checked = false;
  if (checked) return;
#if CERTIMESH_HAS_MXCSR
  const bool ok = (_mm_getcsr() & (mxcsr_rounding | mxcsr_ftz | mxcsr_daz)) == 0;
#else
  const bool ok = rounds_to_nearest();
#endif
  if (!ok) throw FpEnvironmentError(predicate);
  checked = true;
}

std::string FpEnvironmentReport::describe() const {
  std::string s;
  s += round_to_nearest ? "round-to-nearest: yes\n" : "round-to-nearest: NO\n";
  s += subnormals_kept ? "subnormals kept: yes\n" : "subnormals kept: NO (flush-to-zero)\n";
  s += binary64_evaluation ? "binary64 evaluation: yes\n" : "binary64 evaluation: NO\n";
  s += no_contraction ? "no FMA contraction: yes\n" : "no FMA contraction: NO\n";
  return s;
}

FpEnvironmentReport probe_fp_environment() {
  FpEnvironmentReport r;
  r.round_to_nearest = rounds_to_nearest();
  r.subnormals_kept = keeps_subnormals();
  r.binary64_evaluation = FLT_EVAL_METHOD == 0;
  r.no_contraction = contraction_probe() == 0.0;
  return r;
}

}  // namespace certimesh::predicates
