#include <stdexcept>

#include "certimesh/fuzz/campaign/target.h"

namespace certimesh::fuzz::campaign {

void TargetRegistry::add(std::unique_ptr<Target> target) {
  if (!target) throw std::invalid_argument("TargetRegistry::add: null target");
  if (find(target->name())) throw std::invalid_argument("TargetRegistry::add: '" + std::string(target->name()) + "' is already registered");
  targets_.push_back(std::move(target));
}

const Target* TargetRegistry::find(std::string_view name) const {
  for (const auto& t : targets_)
    if (t->name() == name) return t.get();
  return nullptr;
}

std::vector<const Target*> TargetRegistry::all() const {
  std::vector<const Target*> out;
  for (const auto& t : targets_) out.push_back(t.get());
  return out;
}

}  // namespace certimesh::fuzz::campaign
