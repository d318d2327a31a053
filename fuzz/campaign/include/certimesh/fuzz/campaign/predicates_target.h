// The `predicates` target: orient2d, orient3d, incircle and insphere, every mode, against
// exact oracles that share no code with the kernel.
//
// A case draws one predicate and its points from the recipes (fuzz/generators, recipes.h:
// 40 % exactly degenerate, 40 % near-degenerate, 20 % generic, at every scale) through a
// SplitMix64 draw source, and 1 case in 32 gets one NaN, infinite or raw bit-pattern
// coordinate. Then, with o the exact sign (scaled_integer_oracle.h; every disagreement is
// re-decided by the GMP rational oracle before it is reported):
//   - the filter (both copies: inline and kernel-compiled) is uncertain or equal to o;
//   - the exact predicate and the bare exact stage equal o;
//   - SoS equals o when o != 0, and is non-zero for pairwise distinct points;
//   - swapping two points (one pair per case, from the coordinates' bits) negates the
//     filter's certain answers, the exact sign and SoS;
//   - non-finite input: the filters are uncertain, exact and SoS throw NonFiniteInput.
// The payload is "PREDICATE x y [z] ..." in %a hex floats.
#pragma once

#include <memory>
#include <string>

#include "certimesh/fuzz/campaign/target.h"
#include "certimesh/predicates/point.h"
#include "certimesh/predicates/sign.h"

namespace certimesh::fuzz::campaign {

/// The kernel functions the target calls, so that a test can substitute a broken one (a
/// mutant) without it ever reaching the shipped library or CLI.
struct PredicateKernel {
  using P2 = predicates::Point2;
  using P3 = predicates::Point3;
  using Sign = predicates::Sign;
  using FilteredSign = predicates::FilteredSign;
  FilteredSign (*orient2d_filtered)(const P2&, const P2&, const P2&);
  FilteredSign (*orient2d_filtered_copy)(const P2&, const P2&, const P2&);
  Sign (*orient2d)(const P2&, const P2&, const P2&);
  Sign (*orient2d_exact_stage)(const P2&, const P2&, const P2&);
  Sign (*orient2d_sos)(const P2&, const P2&, const P2&);
  FilteredSign (*orient3d_filtered)(const P3&, const P3&, const P3&, const P3&);
  FilteredSign (*orient3d_filtered_copy)(const P3&, const P3&, const P3&, const P3&);
  Sign (*orient3d)(const P3&, const P3&, const P3&, const P3&);
  Sign (*orient3d_exact_stage)(const P3&, const P3&, const P3&, const P3&);
  Sign (*orient3d_sos)(const P3&, const P3&, const P3&, const P3&);
  FilteredSign (*incircle_filtered)(const P2&, const P2&, const P2&, const P2&);
  FilteredSign (*incircle_filtered_copy)(const P2&, const P2&, const P2&, const P2&);
  Sign (*incircle)(const P2&, const P2&, const P2&, const P2&);
  Sign (*incircle_exact_stage)(const P2&, const P2&, const P2&, const P2&);
  Sign (*incircle_sos)(const P2&, const P2&, const P2&, const P2&);
  FilteredSign (*insphere_filtered)(const P3&, const P3&, const P3&, const P3&, const P3&);
  FilteredSign (*insphere_filtered_copy)(const P3&, const P3&, const P3&, const P3&, const P3&);
  Sign (*insphere)(const P3&, const P3&, const P3&, const P3&, const P3&);
  Sign (*insphere_exact_stage)(const P3&, const P3&, const P3&, const P3&, const P3&);
  Sign (*insphere_sos)(const P3&, const P3&, const P3&, const P3&, const P3&);
};

/// certimesh's own kernel (certimesh::predicates).
PredicateKernel certimesh_predicate_kernel();

/// The predicates target over `kernel`, named `name`.
std::unique_ptr<Target> make_predicates_target(const PredicateKernel& kernel, std::string name,
                                               std::string description);

/// The shipped target: make_predicates_target(certimesh_predicate_kernel(), "predicates", ...).
std::unique_ptr<Target> make_predicates_target();

}  // namespace certimesh::fuzz::campaign
