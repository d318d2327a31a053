// bench_delaunay_2d: certimesh's ConstrainedDelaunay2 against CGAL's Delaunay_triangulation_2
// (Epick, its own spatial sort) on the same points in the same run: 10^6 uniform random
// points (seeded), the 1000 x 1000 integer grid and 10^5 points on a circle. Each time covers
// the whole construction from the point array (CGAL's includes copying into its points).
//
// The grid and circle runs are checked runs: after timing, the certimesh triangulation is
// verified outside the timed loop (triangle count, every triangle counterclockwise, every
// interior edge locally Delaunay under the exact incircle); a failure aborts the benchmark.
//
// Options (before Google Benchmark's own): --dt_small runs tiny sizes (the CTest smoke).
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <random>
#include <string>
#include <vector>

#include "bench_delaunay_2d_cgal.h"
#include "small_flag_main.h"
#include "certimesh/generators/delaunay/constrained_delaunay_2.h"
#include "certimesh/predicates/incircle.h"
#include "certimesh/predicates/orient2d.h"

namespace {

using certimesh::generators::ConstrainedDelaunay2;
using certimesh::predicates::Point2;
using certimesh::predicates::Sign;

struct Sizes {
  std::size_t uniform = 1000000;
  int grid_side = 1000;
  std::size_t circle = 100000;
};
Sizes sizes;

std::vector<Point2> uniform_points(std::size_t n) {
  std::mt19937_64 rng(20261130);  // fixed seed: the same points in every run
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point2> p(n);
  for (auto& q : p) q.x = u(rng), q.y = u(rng);
  return p;
}

std::vector<Point2> grid_points(int side) {
  std::vector<Point2> p;
  p.reserve(std::size_t(side) * std::size_t(side));
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j) p.push_back({double(i), double(j)});
  return p;
}

std::vector<Point2> circle_points(std::size_t n) {
  std::vector<Point2> p(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = 6.283185307179586 * double(i) / double(n);
    p[i] = {std::cos(a), std::sin(a)};
  }
  return p;
}

std::vector<std::pair<double, double>> as_pairs(const std::vector<Point2>& p) {
  std::vector<std::pair<double, double>> out;
  out.reserve(p.size());
  for (const auto& q : p) out.emplace_back(q.x, q.y);
  return out;
}

// The exact check of the checked runs; aborts the run with a message when it fails.
void check_delaunay(benchmark::State& state, const std::vector<Point2>& points, std::size_t expected_triangles) {
  const ConstrainedDelaunay2 dt(points);
  const auto tris = dt.triangles();
  if (expected_triangles && tris.size() != expected_triangles) {
    state.SkipWithError("wrong triangle count");
    return;
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> apex;
  for (const auto& t : tris) {
    if (certimesh::predicates::orient2d(points[t[0]], points[t[1]], points[t[2]]) != Sign::positive) {
      state.SkipWithError("a triangle is not counterclockwise");
      return;
    }
    for (int i = 0; i < 3; ++i) apex[{t[(i + 1) % 3], t[(i + 2) % 3]}] = t[i];
  }
  for (const auto& [e, a] : apex) {
    const auto twin = apex.find({e.second, e.first});
    if (twin == apex.end()) continue;
    if (certimesh::predicates::incircle(points[a], points[e.first], points[e.second], points[twin->second]) ==
        Sign::positive) {
      state.SkipWithError("an edge is not locally Delaunay");
      return;
    }
  }
  state.counters["checked"] = 1;
}

void run_certimesh(benchmark::State& state, const std::vector<Point2>& points) {
  std::size_t triangles = 0;
  for (auto _ : state) {
    const ConstrainedDelaunay2 dt(points);
    triangles = dt.triangle_slot_count();
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["points"] = double(points.size());
  state.counters["points/s"] = benchmark::Counter(double(points.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void run_cgal(benchmark::State& state, const std::vector<Point2>& points) {
  const auto pairs = as_pairs(points);
  std::size_t faces = 0;
  for (auto _ : state) {
    faces = certimesh::bench::cgal_delaunay_faces(pairs);
    benchmark::DoNotOptimize(faces);
  }
  state.counters["points"] = double(points.size());
  state.counters["faces"] = double(faces);
  state.counters["points/s"] = benchmark::Counter(double(points.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_delaunay2d_certimesh(benchmark::State& state) { run_certimesh(state, uniform_points(sizes.uniform)); }
void BM_delaunay2d_cgal(benchmark::State& state) { run_cgal(state, uniform_points(sizes.uniform)); }

void BM_delaunay2d_certimesh_grid(benchmark::State& state) {
  const auto points = grid_points(sizes.grid_side);
  run_certimesh(state, points);
  const auto side = std::size_t(sizes.grid_side);
  check_delaunay(state, points, 2 * (side - 1) * (side - 1));
}
void BM_delaunay2d_cgal_grid(benchmark::State& state) { run_cgal(state, grid_points(sizes.grid_side)); }

void BM_delaunay2d_certimesh_circle(benchmark::State& state) {
  const auto points = circle_points(sizes.circle);
  run_certimesh(state, points);
  check_delaunay(state, points, 0);
}
void BM_delaunay2d_cgal_circle(benchmark::State& state) { run_cgal(state, circle_points(sizes.circle)); }

}  // namespace

BENCHMARK(BM_delaunay2d_certimesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_delaunay2d_cgal)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_delaunay2d_certimesh_grid)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_delaunay2d_cgal_grid)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_delaunay2d_certimesh_circle)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_delaunay2d_cgal_circle)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  return certimesh::bench::run_benchmarks(argc, argv, "--dt_small", [] { sizes = Sizes{2000, 30, 2000}; });
}
