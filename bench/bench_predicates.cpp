// bench_predicates: certimesh's predicates against naive double and CGAL Epick.
//
//   BM_<predicate>_<impl>[_neardegenerate]
//   predicate: orient2d, orient3d, incircle, insphere
//   impl:      naive      plain double determinant, the filter's formula, no bound
//              filtered   certimesh X(): inline filter + exact stage (user-facing)
//              filteronly certimesh X_filtered(): the filter alone (may be uncertain)
//              exact      certimesh detail::X_exact_stage(): exact stage, no filter
//              cgal       CGAL Epick orientation / side_of_oriented_circle / sphere
//              prototype_ozaki, prototype_fastexact  orient2d-only bench prototypes
//                         (prototype_filters.h); NOT certimesh's number
//              shewchuk   Shewchuk's adaptive predicates.c, an optional reference peer
//                         for the exact stages (only when built with
//                         CERTIMESH_BENCH_SHEWCHUK_SOURCE); NOT certimesh's number
//
// Each benchmark iteration is one pass over g_tuples precomputed tuples; items/s and
// ns_per_call count predicate calls. No CGAL header is included here (cgal_peer.cpp).
// At start-up every implementation's signs are checked against the exact stage on every
// data set; a mismatch aborts.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "datasets.h"
#include "impls.h"
#include "shewchuk.h"

namespace certimesh_bench {
namespace {

// Tuples per data set (--bench_tuples=N overrides). Not fewer: every iteration replays
// the same tuples, and with 4096 of them this machine's branch predictor learns the
// replayed sequence of signs, which hides the cost of branching on the sign (RESULTS.md).
std::size_t g_tuples = 65536;

const char* name(Predicate p) {
  switch (p) {
    case Predicate::orient2d: return "orient2d";
    case Predicate::orient3d: return "orient3d";
    case Predicate::incircle: return "incircle";
    case Predicate::insphere: return "insphere";
  }
  return "?";
}

const char* name(Impl i) {
  switch (i) {
    case Impl::naive: return "naive";
    case Impl::filtered: return "filtered";
    case Impl::filteronly: return "filteronly";
    case Impl::exact: return "exact";
    case Impl::prototype_ozaki: return "prototype_ozaki";
    case Impl::prototype_fastexact: return "prototype_fastexact";
    case Impl::shewchuk: return "shewchuk";
  }
  return "?";
}

bool orient2d_only(Impl i) {
  return i == Impl::prototype_ozaki || i == Impl::prototype_fastexact;
}

struct Prepared {
  DataSet data;
  CgalPoints cgal;
  double naive_wrong = 0;        // fraction of tuples where naive's sign is wrong
  double filter_uncertain = 0;   // fraction where X_filtered is uncertain
  Prepared(Predicate p, bool nd)
      : data(make_dataset(p, nd, g_tuples)), cgal(p, data.points(), g_tuples) {}
};

// Checks every implementation against the exact stage on the first kCheckTuples tuples
// (enough to catch a convention or logic error, and keeps start-up short); records the
// statistics over the same tuples.
constexpr std::size_t kCheckTuples = 16384;
void cross_check(Prepared& s) {
  const Predicate p = s.data.predicate;
  const std::size_t n = std::min(s.data.ntuples, kCheckTuples);
  std::vector<std::int8_t> exact(n), other(n);
  certimesh_signs(p, Impl::exact, s.data.points(), n, exact.data());
  auto fail = [&](const char* what, std::size_t i) {
    std::fprintf(stderr, "bench_predicates: %s %s%s disagrees with the exact stage at tuple %zu\n",
                 name(p), what, s.data.near_degenerate ? " (near-degenerate)" : "", i);
    std::exit(2);
  };
  for (Impl impl : {Impl::filtered, Impl::prototype_ozaki,
                    Impl::prototype_fastexact, Impl::shewchuk}) {
    if (impl == Impl::shewchuk && !CERTIMESH_BENCH_HAVE_SHEWCHUK) continue;
    if (orient2d_only(impl) && p != Predicate::orient2d) continue;
    certimesh_signs(p, impl, s.data.points(), n, other.data());
    for (std::size_t i = 0; i < n; ++i)
      if (other[i] != exact[i]) fail(name(impl), i);
  }
  s.cgal.signs(other.data(), n);
  for (std::size_t i = 0; i < n; ++i)
    if (other[i] != exact[i]) fail("cgal", i);
  certimesh_signs(p, Impl::filteronly, s.data.points(), n, other.data());
  std::size_t uncertain = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (other[i] == 0) ++uncertain;
    else if (other[i] != exact[i]) fail("filteronly", i);
  }
  s.filter_uncertain = static_cast<double>(uncertain) / static_cast<double>(n);
  certimesh_signs(p, Impl::naive, s.data.points(), n, other.data());
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < n; ++i) wrong += other[i] != exact[i];
  s.naive_wrong = static_cast<double>(wrong) / static_cast<double>(n);
}

void set_counters(benchmark::State& state, std::size_t n) {
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) *
                          static_cast<std::int64_t>(n));
  state.counters["time_per_call"] = benchmark::Counter(
      static_cast<double>(n),
      benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

void register_all(std::vector<Prepared*>& sets) {
  for (Prepared* s : sets) {
    const Predicate p = s->data.predicate;
    const std::string suffix = s->data.near_degenerate ? "_neardegenerate" : "";
    for (Impl impl : {Impl::naive, Impl::filtered, Impl::filteronly, Impl::exact}) {
      const std::string bm = std::string("BM_") + name(p) + "_" + name(impl) + suffix;
      benchmark::RegisterBenchmark(bm.c_str(), [s, p, impl](benchmark::State& state) {
        const void* pts = s->data.points();
        const std::size_t n = s->data.ntuples;
        for (auto _ : state) {
          long long sum = certimesh_sum(p, impl, pts, n);
          benchmark::DoNotOptimize(sum);
        }
        set_counters(state, n);
        if (impl == Impl::naive) state.counters["wrong_sign_frac"] = s->naive_wrong;
        if (impl == Impl::filtered || impl == Impl::filteronly)
          state.counters["uncertain_frac"] = s->filter_uncertain;
      });
    }
    const std::string cg = std::string("BM_") + name(p) + "_cgal" + suffix;
    benchmark::RegisterBenchmark(cg.c_str(), [s](benchmark::State& state) {
      for (auto _ : state) {
        long long sum = s->cgal.sum();
        benchmark::DoNotOptimize(sum);
      }
      set_counters(state, s->data.ntuples);
    });
    for (Impl impl : {Impl::prototype_ozaki, Impl::prototype_fastexact,
                      Impl::shewchuk}) {
      if (impl == Impl::shewchuk && !CERTIMESH_BENCH_HAVE_SHEWCHUK) continue;
      if (orient2d_only(impl) && p != Predicate::orient2d) continue;
      const std::string bm = std::string("BM_") + name(p) + "_" + name(impl) + suffix;
      benchmark::RegisterBenchmark(bm.c_str(), [s, p, impl](benchmark::State& state) {
        const void* pts = s->data.points();
        const std::size_t n = s->data.ntuples;
        for (auto _ : state) {
          long long sum = certimesh_sum(p, impl, pts, n);
          benchmark::DoNotOptimize(sum);
        }
        set_counters(state, n);
        state.SetLabel(impl == Impl::shewchuk ? "reference peer, not certimesh"
                                              : "bench-only prototype, not certimesh");
      });
    }
  }
}

}  // namespace
}  // namespace certimesh_bench

int main(int argc, char** argv) {
  using namespace certimesh_bench;
  // Our own flag, removed before Google Benchmark parses the rest.
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg.rfind("--bench_tuples=", 0) == 0) {
      g_tuples = std::stoul(arg.substr(15));
      if (g_tuples == 0) g_tuples = 1;
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  benchmark::Initialize(&argc, argv);
  benchmark::AddCustomContext("bench_tuples", std::to_string(g_tuples));
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
#if CERTIMESH_BENCH_HAVE_SHEWCHUK
  shewchuk::exactinit();
#endif
  std::vector<Prepared*> sets;  // live until exit
  for (bool nd : {false, true})
    for (Predicate p : {Predicate::orient2d, Predicate::orient3d, Predicate::incircle,
                        Predicate::insphere}) {
      auto* s = new Prepared(p, nd);
      cross_check(*s);
      sets.push_back(s);
    }
  register_all(sets);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  for (Prepared* s : sets) delete s;
  return 0;
}
