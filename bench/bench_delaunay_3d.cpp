// bench_delaunay_3d: certimesh's Delaunay3 against CGAL's Delaunay_triangulation_3 (Epick,
// its own spatial sort) on the same points in the same run: 10^6 uniform random points in the
// unit cube (seeded) and the 40^3 integer grid (cospherical everywhere). Each time covers the
// whole construction from the point array (CGAL's includes copying into its points).
//
// The grid run is a checked run: after timing, the certimesh tetrahedralization is verified
// outside the timed loop (every tetrahedron positive by exact orient3d, the volumes summing
// exactly, in integers, to the cube's); a failure aborts the benchmark. The tetrahedra per
// point and bytes per tetrahedron (the slot arrays: 33 bytes a slot) are counters.
//
// Options (before Google Benchmark's own): --dt_small runs tiny sizes (the CTest smoke).
#include <benchmark/benchmark.h>

#include <array>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include "bench_delaunay_3d_cgal.h"
#include "small_flag_main.h"
#include "certimesh/generators/delaunay/delaunay_3.h"
#include "certimesh/predicates/volume_sign.h"

namespace {

using certimesh::generators::Delaunay3;
using certimesh::predicates::Point3;

struct Sizes {
  std::size_t uniform = 1000000;
  int grid_side = 40;
};
Sizes sizes;

std::vector<Point3> uniform_points(std::size_t n) {
  std::mt19937_64 rng(20261202);  // fixed seed: the same points in every run
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Point3> p(n);
  for (auto& q : p) q.x = u(rng), q.y = u(rng), q.z = u(rng);
  return p;
}

std::vector<Point3> grid_points(int side) {
  std::vector<Point3> p;
  for (int i = 0; i < side; ++i)
    for (int j = 0; j < side; ++j)
      for (int k = 0; k < side; ++k) p.push_back({double(i), double(j), double(k)});
  return p;
}

std::vector<std::array<double, 3>> as_arrays(const std::vector<Point3>& p) {
  std::vector<std::array<double, 3>> out;
  out.reserve(p.size());
  for (const auto& q : p) out.push_back({q.x, q.y, q.z});
  return out;
}

// The grid's check: positive tetrahedra filling the cube (6 V summed in integers: the
// coordinates are small integers, every product exact).
void check_grid(benchmark::State& state, const std::vector<Point3>& points, int side) {
  const Delaunay3 dt(points);
  std::int64_t six_volume = 0;
  for (const auto& t : dt.tetrahedra()) {
    const Point3 &a = points[t[0]], &b = points[t[1]], &c = points[t[2]], &d = points[t[3]];
    if (certimesh::predicates::volume_sign(a, b, c, d) != certimesh::predicates::Sign::positive) {
      state.SkipWithError("a tetrahedron is not positive");
      return;
    }
    const auto u = [&](const Point3& p, int axis) {
      return std::int64_t(axis == 0 ? p.x - a.x : (axis == 1 ? p.y - a.y : p.z - a.z));
    };
    six_volume += u(b, 0) * (u(c, 1) * u(d, 2) - u(c, 2) * u(d, 1)) - u(b, 1) * (u(c, 0) * u(d, 2) - u(c, 2) * u(d, 0)) +
                  u(b, 2) * (u(c, 0) * u(d, 1) - u(c, 1) * u(d, 0));
  }
  const std::int64_t edge = side - 1;
  if (six_volume != 6 * edge * edge * edge) {
    state.SkipWithError("the tetrahedra do not fill the cube");
    return;
  }
  state.counters["checked"] = 1;
}

void run_certimesh(benchmark::State& state, const std::vector<Point3>& points) {
  std::size_t tetrahedra = 0, slots = 0;
  for (auto _ : state) {
    const Delaunay3 dt(points);
    tetrahedra = dt.tetrahedron_count();
    slots = dt.tetrahedron_slot_count();
    benchmark::DoNotOptimize(tetrahedra);
  }
  state.counters["points"] = double(points.size());
  state.counters["tets/point"] = double(tetrahedra) / double(points.size());
  state.counters["bytes/tet"] = 33.0 * double(slots) / double(tetrahedra);
  state.counters["points/s"] = benchmark::Counter(double(points.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void run_cgal(benchmark::State& state, const std::vector<Point3>& points) {
  const auto arrays = as_arrays(points);
  std::size_t cells = 0;
  for (auto _ : state) {
    cells = certimesh::bench::cgal_delaunay_cells(arrays);
    benchmark::DoNotOptimize(cells);
  }
  state.counters["points"] = double(points.size());
  state.counters["tets/point"] = double(cells) / double(points.size());
  state.counters["points/s"] = benchmark::Counter(double(points.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_delaunay3d_certimesh(benchmark::State& state) { run_certimesh(state, uniform_points(sizes.uniform)); }
void BM_delaunay3d_cgal(benchmark::State& state) { run_cgal(state, uniform_points(sizes.uniform)); }

void BM_delaunay3d_certimesh_grid(benchmark::State& state) {
  const auto points = grid_points(sizes.grid_side);
  run_certimesh(state, points);
  check_grid(state, points, sizes.grid_side);
}
void BM_delaunay3d_cgal_grid(benchmark::State& state) { run_cgal(state, grid_points(sizes.grid_side)); }

}  // namespace

BENCHMARK(BM_delaunay3d_certimesh)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_delaunay3d_cgal)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_delaunay3d_certimesh_grid)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_delaunay3d_cgal_grid)->Unit(benchmark::kMillisecond);

int main(int argc, char** argv) {
  return certimesh::bench::run_benchmarks(argc, argv, "--dt_small", [] { sizes = Sizes{3000, 8}; });
}
