// bench_certificate: certificate::check_mesh on large valid meshes (jittered Kuhn grids:
// 3D >= 2 M tetrahedra, 2D >= 10^6 triangles), side by side with the CGAL reference check
// (cgal_mesh_check_peer.h), in the same run. Reports elements per second per benchmark and,
// at the end, the time ratio CGAL reference / certimesh. bench/RESULTS.md has the numbers.
//
// Options (before Google Benchmark's own): --cert_small runs tiny meshes (the CTest smoke).
#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/fuzz/valid_meshes.h"
#include "cgal_mesh_check_peer.h"

namespace {

using certimesh::io::MeshData;

// Mesh sizes: 70^3 cubes x 6 = 2,058,000 tetrahedra; 1000 x 500 squares x 2 = 10^6 triangles.
struct Sizes {
  int cubes_per_axis = 70;
  int squares_x = 1000;
  int squares_y = 500;
};

MeshData make_grid(int dimension, const Sizes& s) {
  certimesh::fuzz::GridSpec g;
  g.dimension = dimension;
  g.cells = dimension == 3 ? std::array<int, 3>{s.cubes_per_axis, s.cubes_per_axis, s.cubes_per_axis}
                           : std::array<int, 3>{s.squares_x, s.squares_y, 1};
  g.jitter_seed = 20261129;  // documented, fixed: the same mesh in every run
  return certimesh::fuzz::kuhn_grid(g);
}

std::size_t elements_of(const MeshData& m) { return m.dimension == 2 ? m.triangle_count() : m.tetrahedron_count(); }

// Both checks must accept the mesh and agree on the facet counts, or the timing means nothing.
void cross_check(const MeshData& m) {
  const certimesh::certificate::Report r = certimesh::certificate::check_mesh(m);
  const certimesh_bench::PeerVerdict p = certimesh_bench::cgal_reference_check(m);
  if (!r.valid || !p.all_positive || !p.paired || r.statistics.boundary_facets != p.boundary_facets ||
      r.statistics.interior_facets != p.interior_facets) {
    std::fprintf(stderr, "bench_certificate: checks disagree on the %dD mesh (certimesh: %s, %s; "
                 "boundary facets %zu vs CGAL %zu)\n", m.dimension, r.valid ? "valid" : "invalid",
                 r.finding.message.c_str(), r.statistics.boundary_facets, p.boundary_facets);
    std::exit(1);
  }
}

void set_counters(benchmark::State& state, const MeshData& m) {
  const auto n = static_cast<double>(elements_of(m));
  state.counters[m.dimension == 2 ? "tris_per_s" : "tets_per_s"] =
      benchmark::Counter(n, benchmark::Counter::kIsIterationInvariantRate);
  state.counters["elements"] = n;
}

void run_certimesh(benchmark::State& state, const MeshData* m) {
  for (auto _ : state) {
    certimesh::certificate::Report r = certimesh::certificate::check_mesh(*m);
    benchmark::DoNotOptimize(r);
  }
  set_counters(state, *m);
}

// The same check against the mesh's domain (square .poly / cube surface): adds condition 6.
struct MeshAndDomain {
  const MeshData* mesh;
  const MeshData* domain;
};

void run_certimesh_with_domain(benchmark::State& state, MeshAndDomain md) {
  for (auto _ : state) {
    certimesh::certificate::Report r = certimesh::certificate::check_mesh(*md.mesh, md.domain);
    benchmark::DoNotOptimize(r);
  }
  set_counters(state, *md.mesh);
}

void run_cgal(benchmark::State& state, const MeshData* m) {
  for (auto _ : state) {
    certimesh_bench::PeerVerdict v = certimesh_bench::cgal_reference_check(*m);
    benchmark::DoNotOptimize(v);
  }
  set_counters(state, *m);
}

// Keeps every run's CPU time by name, to print the ratios after the console report. CPU time,
// not real time: both checks are single-threaded, and on a shared machine real time also
// counts the time the process waited for a core.
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs)
      if (run.run_type == Run::RT_Iteration || run.aggregate_name == "mean")
        times_[run.run_name.function_name] = run.GetAdjustedCPUTime();
    ConsoleReporter::ReportRuns(runs);
  }
  void print_ratios() const {
    for (const char* d : {"2d", "3d"}) {
      const auto ours = times_.find(std::string("BM_check_mesh_") + d + "_certimesh");
      const auto peer = times_.find(std::string("BM_check_mesh_") + d + "_cgal_reference");
      if (ours != times_.end() && peer != times_.end() && ours->second > 0)
        std::printf("ratio %s: CGAL reference / certimesh CPU time = %.2f\n", d, peer->second / ours->second);
    }
  }

 private:
  std::map<std::string, double> times_;
};

}  // namespace

int main(int argc, char** argv) {
  Sizes sizes;
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--cert_small") {
      sizes = Sizes{6, 20, 10};
    } else {
      argv[kept++] = argv[i];
    }
  }
  argc = kept;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;

  static const MeshData mesh2d = make_grid(2, sizes);
  static const MeshData mesh3d = make_grid(3, sizes);
  static const MeshData domain2d = certimesh::fuzz::square_domain(
      certimesh::fuzz::GridSpec{2, {sizes.squares_x, sizes.squares_y, 1}, {}, 0});
  static const MeshData domain3d = certimesh::fuzz::cube_surface_domain(sizes.cubes_per_axis);
  cross_check(mesh2d);
  cross_check(mesh3d);
  for (const auto& [mesh, domain] : {std::pair{&mesh2d, &domain2d}, std::pair{&mesh3d, &domain3d}}) {
    const certimesh::certificate::Report r = certimesh::certificate::check_mesh(*mesh, domain);
    if (!r.valid) {
      std::fprintf(stderr, "bench_certificate: the %dD mesh is rejected against its domain: %s\n",
                   mesh->dimension, r.finding.message.c_str());
      return 1;
    }
  }
  benchmark::AddCustomContext("mesh_2d", std::to_string(elements_of(mesh2d)) + " triangles (jittered Kuhn grid)");
  benchmark::AddCustomContext("mesh_3d", std::to_string(elements_of(mesh3d)) + " tetrahedra (jittered Kuhn grid)");

  benchmark::RegisterBenchmark("BM_check_mesh_2d_certimesh", run_certimesh, &mesh2d)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_check_mesh_2d_certimesh_with_domain", run_certimesh_with_domain,
                               MeshAndDomain{&mesh2d, &domain2d})->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_check_mesh_2d_cgal_reference", run_cgal, &mesh2d)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_check_mesh_3d_certimesh", run_certimesh, &mesh3d)->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_check_mesh_3d_certimesh_with_domain", run_certimesh_with_domain,
                               MeshAndDomain{&mesh3d, &domain3d})->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("BM_check_mesh_3d_cgal_reference", run_cgal, &mesh3d)->Unit(benchmark::kMillisecond);

  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  reporter.print_ratios();
  benchmark::Shutdown();
  return 0;
}
