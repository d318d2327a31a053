// bench_sos_2d: the perturbed signs of degenerate 2D input, the kernel's orient2d_sos /
// incircle_sos (the GMP-free path of predicates/src/sos_2d.cpp) against the generic monomial
// search over GMP minors it replaced (detail::perturbed_sign, kept as the oracle), on the
// same tuples.
//
//   BM_<predicate>_sos_<impl>/<set>
//   predicate: orient2d (collinear triples), incircle (cocircular or collinear quadruples)
//   impl:      kernel    orient2d_sos / incircle_sos: exact sign (zero), then the fast path
//              generic   detail::perturbed_sign alone (the old cost on top of the exact sign)
//   set:       0 = every degenerate tuple of the 6x6 integer grid, in every order;
//              1 = collinear only (incircle: four points on one grid line or diagonal)
//
// At start-up both answers are compared on every tuple; a mismatch aborts.
#include <benchmark/benchmark.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <vector>

#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/symbolic_perturbation.h"

namespace {

namespace pr = certimesh::predicates;
using pr::Point2;

template <std::size_t N>
using Tuple = std::array<Point2, N>;

std::vector<Point2> grid() {
  std::vector<Point2> g;
  for (int x = 0; x < 6; ++x)
    for (int y = 0; y < 6; ++y) g.push_back({static_cast<double>(x), static_cast<double>(y)});
  return g;
}

bool collinear(std::span<const Point2> p) {
  for (std::size_t i = 2; i < p.size(); ++i)
    if (pr::orient2d(p[0], p[1], p[i]) != pr::Sign::zero) return false;
  return true;
}

pr::Sign exact_sign(const Tuple<3>& t) { return pr::orient2d(t[0], t[1], t[2]); }
pr::Sign exact_sign(const Tuple<4>& t) { return pr::incircle(t[0], t[1], t[2], t[3]); }
pr::Sign kernel_sos(const Tuple<3>& t) { return pr::orient2d_sos(t[0], t[1], t[2]); }
pr::Sign kernel_sos(const Tuple<4>& t) { return pr::incircle_sos(t[0], t[1], t[2], t[3]); }

template <std::size_t N>
pr::Sign generic_sos(const Tuple<N>& t) {
  std::array<double, 2 * N> raw{};
  for (std::size_t i = 0; i < N; ++i) {
    raw[2 * i] = t[i].x;
    raw[2 * i + 1] = t[i].y;
  }
  return pr::detail::perturbed_sign(raw, 2, N == 4);
}

// The degenerate ordered N-tuples of distinct grid points (collinear only when asked).
template <std::size_t N>
std::vector<Tuple<N>> degenerate_tuples(bool collinear_only) {
  const std::vector<Point2> g = grid();
  std::vector<Tuple<N>> out;
  std::array<std::size_t, N> idx{};
  const auto visit = [&](auto&& self, std::size_t depth) -> void {
    if (depth == N) {
      Tuple<N> t;
      for (std::size_t i = 0; i < N; ++i) t[i] = g[idx[i]];
      if (exact_sign(t) == pr::Sign::zero && (!collinear_only || collinear(t))) out.push_back(t);
      return;
    }
    for (std::size_t v = 0; v < g.size(); ++v) {
      bool fresh = true;
      for (std::size_t i = 0; i < depth; ++i) fresh = fresh && idx[i] != v;
      if (!fresh) continue;
      idx[depth] = v;
      self(self, depth + 1);
    }
  };
  visit(visit, 0);
  for (const auto& t : out)
    if (kernel_sos(t) != generic_sos(t)) {
      std::fprintf(stderr, "bench_sos_2d: the fast and generic SoS disagree\n");
      std::abort();
    }
  return out;
}

template <std::size_t N>
const std::vector<Tuple<N>>& tuples(bool collinear_only) {
  static const std::array<std::vector<Tuple<N>>, 2> sets{degenerate_tuples<N>(false),
                                                         degenerate_tuples<N>(true)};
  return sets[collinear_only ? 1 : 0];
}

template <std::size_t N, bool Generic>
void run(benchmark::State& state) {
  const auto& set = tuples<N>(state.range(0) != 0);
  for (auto _ : state)
    for (const auto& t : set) benchmark::DoNotOptimize(Generic ? generic_sos(t) : kernel_sos(t));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(set.size()));
  state.counters["ns_per_call"] = benchmark::Counter(
      static_cast<double>(state.iterations()) * static_cast<double>(set.size()),
      benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_orient2d_sos_kernel(benchmark::State& s) { run<3, false>(s); }
void BM_orient2d_sos_generic(benchmark::State& s) { run<3, true>(s); }
void BM_incircle_sos_kernel(benchmark::State& s) { run<4, false>(s); }
void BM_incircle_sos_generic(benchmark::State& s) { run<4, true>(s); }
BENCHMARK(BM_orient2d_sos_kernel)->Arg(0);
BENCHMARK(BM_orient2d_sos_generic)->Arg(0);
BENCHMARK(BM_incircle_sos_kernel)->Arg(0)->Arg(1);
BENCHMARK(BM_incircle_sos_generic)->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
