// The part every campaign target shares: its name and its one-line description (a test
// builds a mutant as the same target under another name). Targets derive from it and write
// only run_case and replay.
#pragma once

#include <string>
#include <string_view>
#include <utility>

#include "certimesh/fuzz/campaign/target.h"

namespace certimesh::fuzz::campaign {

class NamedTarget : public Target {
 public:
  NamedTarget(std::string name, std::string description) : name_(std::move(name)), description_(std::move(description)) {}
  std::string_view name() const final { return name_; }
  std::string_view description() const final { return description_; }

 private:
  std::string name_, description_;
};

}  // namespace certimesh::fuzz::campaign
