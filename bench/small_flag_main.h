// The main() of a benchmark with a "small sizes" flag (its CTest smoke run): the flag is taken
// out of the arguments before Google Benchmark reads them.
#pragma once

#include <benchmark/benchmark.h>

#include <functional>
#include <string_view>

namespace certimesh::bench {

/// Removes `flag` from argv (calling `use_small` if it was there), then runs the registered
/// benchmarks; returns main's exit code.
inline int run_benchmarks(int argc, char** argv, std::string_view flag, const std::function<void()>& use_small) {
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (argv[i] == flag) use_small();
    else argv[kept++] = argv[i];
  }
  argc = kept;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}

}  // namespace certimesh::bench
