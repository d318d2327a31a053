#include "certimesh/predicates/fp_environment.h"

#include <cfenv>
#include <cfloat>

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

}  // namespace

std::string FpEnvironmentReport::describe() const {
  std::string s;
  s += round_to_nearest ? "round-to-nearest: yes\n" : "round-to-nearest: NO\n";
  s += binary64_evaluation ? "binary64 evaluation: yes\n" : "binary64 evaluation: NO\n";
  s += no_contraction ? "no FMA contraction: yes\n" : "no FMA contraction: NO\n";
  return s;
}

FpEnvironmentReport probe_fp_environment() {
  FpEnvironmentReport r;
  r.round_to_nearest = std::fegetround() == FE_TONEAREST;
  r.binary64_evaluation = FLT_EVAL_METHOD == 0;
  r.no_contraction = contraction_probe() == 0.0;
  return r;
}

}  // namespace certimesh::predicates
