// Run-time evidence that the kernel was built in the floating-point environment its
// proofs assume (proofs/README.md): round-to-nearest, binary64 evaluation, no FMA
// contraction. The probes are compiled inside the kernel with its own flags.
#pragma once

#include <string>

namespace certimesh::predicates {

struct FpEnvironmentReport {
  bool round_to_nearest = false;     // fegetround() == FE_TONEAREST at the call
  bool binary64_evaluation = false;  // FLT_EVAL_METHOD == 0 inside the kernel
  bool no_contraction = false;       // a*b - a*b evaluates to exactly 0 inside the kernel
  bool ok() const { return round_to_nearest && binary64_evaluation && no_contraction; }
  std::string describe() const;
};

/// Probes the environment as the kernel's code sees it.
FpEnvironmentReport probe_fp_environment();

}  // namespace certimesh::predicates
