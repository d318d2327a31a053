// Run-time evidence that the kernel was built in the floating-point environment its
// proofs assume (proofs/README.md): round-to-nearest, subnormals kept, binary64 evaluation,
// no FMA contraction. The probes are compiled inside the kernel with its own flags.
//
// The rounding mode and flush-to-zero are properties of the running thread, not of the
// build: a caller's fesetround() or a library linked with -ffast-math (which sets FTZ/DAZ
// at start-up on x86) changes them for the kernel too. The exact stages check them once per
// thread, at its first exact stage, and throw FpEnvironmentError (checking every call
// measured +50% on the cheapest exact stage); the inline filters do not check. A mode set
// before a thread's first uncertain query is caught; one changed later is seen only by
// probe_fp_environment().
#pragma once

#include <stdexcept>
#include <string>

namespace certimesh::predicates {

/// Raised by the exact stages when the thread's rounding mode is not round-to-nearest or
/// subnormals are flushed to zero: the proofs of the filters and expansions then fail.
class FpEnvironmentError : public std::domain_error {
 public:
  explicit FpEnvironmentError(const std::string& predicate);
};

struct FpEnvironmentReport {
  bool round_to_nearest = false;     // fegetround() == FE_TONEAREST at the call
  bool subnormals_kept = false;      // no flush-to-zero / denormals-are-zero (x86 MXCSR)
  bool binary64_evaluation = false;  // FLT_EVAL_METHOD == 0 inside the kernel
  bool no_contraction = false;       // a*b - a*b evaluates to exactly 0 inside the kernel
  bool ok() const {
    return round_to_nearest && subnormals_kept && binary64_evaluation && no_contraction;
  }
  std::string describe() const;
};

/// Probes the environment as the kernel's code sees it.
FpEnvironmentReport probe_fp_environment();

namespace detail {
/// Throws FpEnvironmentError naming `predicate` unless the thread rounds to nearest and
/// keeps subnormals; checks once per thread (the first call that passes). Called at the
/// entry of every exact stage.
void require_proven_fp_mode(const char* predicate);
}  // namespace detail

}  // namespace certimesh::predicates
