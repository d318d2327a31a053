// The error the exact predicates raise for NaN or infinite coordinates.
//
// A sign of a NaN is meaningless; the kernel refuses it instead of answering. The filters
// never throw (NaN makes every comparison false, so they answer `uncertain`); the exact
// stage checks and throws.
#pragma once

#include <stdexcept>
#include <string>

namespace certimesh::predicates {

class NonFiniteInput : public std::domain_error {
 public:
  explicit NonFiniteInput(const std::string& predicate)
      : std::domain_error(predicate + ": non-finite coordinate (NaN or infinity)") {}
};

}  // namespace certimesh::predicates
