// How a generator reports progress and diagnostics. The library never prints: a long stage
// calls this callback now and then (a few hundred times per run at most), and the caller --
// the CLI, a GUI, a test -- decides what a person sees. An empty callback costs one branch.
#pragma once

#include <cstdint>
#include <functional>
#include <string_view>

namespace certimesh::generators {

struct Progress {
  std::string_view stage;     // "delaunay", "advancing front", "completion", "improvement", ...
  std::uint64_t done = 0;     // work units finished in this stage
  std::uint64_t total = 0;    // an estimate of the stage's work units; 0 when unknown
};

using ProgressCallback = std::function<void(const Progress&)>;

/// Calls `callback` when it is set.
inline void report(const ProgressCallback& callback, std::string_view stage, std::uint64_t done,
                   std::uint64_t total) {
  if (callback) callback(Progress{stage, done, total});
}

}  // namespace certimesh::generators
