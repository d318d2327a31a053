// bench_certificate_worst: certificate::check_mesh on the shapes that attain its worst cases
// (fuzz/worst_case_meshes.h, issue 12): a star polygon whose boundary boxes all overlap near
// its centre, an edge in k tetrahedra (k boundary triangles around each of its ends), a grid
// with a hole point per hole, nested rings, a TetGen facet of many corners. Beside each, in the same run, the CGAL reference
// check (orientation + facet pairing only: it does less) as the peer. bench/RESULTS.md has
// the numbers: the target is under a second per 10^6 elements for every shape.
//
// Options (before Google Benchmark's own): --worst_small runs tiny shapes (the CTest smoke).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/fuzz/worst_case_meshes.h"
#include "cgal_mesh_check_peer.h"

namespace {

using certimesh::io::MeshData;

struct Shape {
  MeshData mesh;
  MeshData domain;  // empty: checked without one
  bool has_domain = false;
};

std::size_t elements_of(const MeshData& m) { return m.dimension == 2 ? m.triangle_count() : m.tetrahedron_count(); }

// The shape must be valid (or the timing means nothing): certimesh and the peer agree.
void require_valid(const std::string& name, const Shape& s) {
  const auto r = certimesh::certificate::check_mesh(s.mesh, s.has_domain ? &s.domain : nullptr);
  const certimesh_bench::PeerVerdict p = certimesh_bench::cgal_reference_check(s.mesh);
  if (!r.valid || !p.all_positive || !p.paired) {
    std::fprintf(stderr, "bench_certificate_worst: %s is not valid (%s)\n", name.c_str(), r.finding.message.c_str());
    std::exit(1);
  }
}

using Factory = Shape (*)(int);

// Each shape is built (and validated) only when a benchmark that uses it runs, so a filter
// that leaves out the quadratic 3D fan does not pay for building it.
struct Case {
  std::string name;
  Factory make;
  int size;
  const Shape& shape() {
    if (!built) {
      value = make(size);
      require_valid(name, value);
      built = true;
    }
    return value;
  }
  Shape value;
  bool built = false;
};

void set_counters(benchmark::State& state, const MeshData& m) {
  state.counters["elements"] = static_cast<double>(elements_of(m));
  state.counters["elements_per_s"] = benchmark::Counter(static_cast<double>(elements_of(m)), benchmark::Counter::kIsIterationInvariantRate);
}

void run_certimesh(benchmark::State& state, Case* c) {
  const Shape& s = c->shape();
  for (auto _ : state) {
    auto r = certimesh::certificate::check_mesh(s.mesh, s.has_domain ? &s.domain : nullptr);
    benchmark::DoNotOptimize(r);
  }
  set_counters(state, s.mesh);
}

void run_cgal(benchmark::State& state, Case* c) {
  const Shape& s = c->shape();
  for (auto _ : state) {
    auto v = certimesh_bench::cgal_reference_check(s.mesh);
    benchmark::DoNotOptimize(v);
  }
  set_counters(state, s.mesh);
}

Shape star(int k) { return {certimesh::fuzz::star_fan_2d(k), {}, false}; }
Shape book(int k) { return {certimesh::fuzz::book_3d(k), {}, false}; }
Shape pinwheel(int k) { return {certimesh::fuzz::pinwheel_2d(k), {}, false}; }
Shape open_book(int k) { return {certimesh::fuzz::open_book_3d(k), {}, false}; }
Shape rings(int k) { return {certimesh::fuzz::nested_rings_2d(k), {}, false}; }
Shape spiked(int k) {
  Shape s;
  s.mesh = certimesh::fuzz::spiked_star_2d(k, 16, s.domain);
  s.has_domain = true;
  return s;
}
Shape star_prism(int k) {
  Shape s;
  s.mesh = certimesh::fuzz::star_prism_3d(k, s.domain);
  s.has_domain = true;
  return s;
}
Shape holes(int n) {
  Shape s;
  s.mesh = certimesh::fuzz::holey_grid_2d(n | 1, s.domain);  // odd: the corner squares stay
  s.has_domain = true;
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  double scale = 1;  // --worst_scale=S multiplies every shape's size (the smoke test: 0.01)
  int kept = 1;
  for (int i = 1; i < argc; ++i) {
    if (std::string(argv[i]) == "--worst_small") scale = 0.01;
    else if (std::string(argv[i]).rfind("--worst_scale=", 0) == 0) scale = std::atof(argv[i] + 14);
    else argv[kept++] = argv[i];
  }
  argc = kept;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  auto sized = [&](double n) { return std::max(4, static_cast<int>(n * scale)); };
  // Full size: 200,000 triangles; 250,000 triangles and 61,250 hole points; 100,000
  // triangles in 12,500 nested rings; the 3D fan at 100,000 tetrahedra (its two fans of
  // 100,000 boundary triangles are decided by their cones: no longer quadratic);
  // 100,000 parts pinched at one vertex; 50,000 tetrahedra in every other wedge around one edge
  // (100,000 boundary triangles on it, decided by the cones at its ends); 400,000 triangles of a
  // spiked star with 375,000 Steiner points rounded off their segments; a prism over a star
  // polygon of 1,000 corners against its TetGen facets, 3,000 tetrahedra (quadratic: the
  // contact check of the facets' cut triangles, whose boxes overlap).
  static Case cases[] = {{"star_fan_2d", star, sized(100000), {}, false},
                         {"holey_grid_2d_with_domain", holes, std::max(9, static_cast<int>(495 * std::sqrt(scale))), {}, false},
                         {"nested_rings_2d", rings, sized(12500), {}, false},
                         {"book_3d", book, sized(100000), {}, false},
                         {"pinwheel_2d", pinwheel, sized(100000), {}, false},
                         {"open_book_3d", open_book, sized(50000), {}, false},
                         {"spiked_star_2d_with_domain", spiked, sized(12500), {}, false},
                         {"star_prism_3d_with_facets", star_prism, sized(500), {}, false}};
  for (Case& c : cases) {
    benchmark::RegisterBenchmark(("BM_worst_" + c.name + "_certimesh").c_str(), run_certimesh, &c)->Unit(benchmark::kMillisecond);
    benchmark::RegisterBenchmark(("BM_worst_" + c.name + "_cgal_reference").c_str(), run_cgal, &c)->Unit(benchmark::kMillisecond);
  }
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
