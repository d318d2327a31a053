// The part every campaign target shares: its name, its one-line description and the kernel
// it calls (a struct of function pointers: a test builds a mutant as the same target over a
// broken kernel, under another name). Targets derive from KernelTarget and write only
// run_case and replay.
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

template <class Kernel>
class KernelTarget : public NamedTarget {
 public:
  KernelTarget(const Kernel& kernel, std::string name, std::string description)
      : NamedTarget(std::move(name), std::move(description)), kernel_(kernel) {}

 protected:
  Kernel kernel_;
};

}  // namespace certimesh::fuzz::campaign
