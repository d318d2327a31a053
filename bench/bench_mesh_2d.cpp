// bench_mesh_2d: the monograph's Table 3.1 experiment (unit square, quasi-uniform size h)
// with certimesh's 2D pipeline, side by side with `gmsh -2 -algo front2d` (Gmsh's
// frontal-Delaunay) in the same run, on the same domain and sizes. Not Google Benchmark: the
// peer is an external program, timed by its own "Done meshing 2D" CPU figure (I/O excluded),
// and certimesh by the pipeline's own stage clock (also without I/O). Every certimesh mesh is
// certified (untimed) against the domain; a refused mesh stops the run with exit 1.
//
//   bench_mesh_2d [--sizes 0.01,0.005,0.0025,0.00125] [--repetitions 3] [--gmsh gmsh|none]
//                 [--algorithm front|delaunay]
//
// Output: a Markdown table (the columns of Table 3.1, worst and mean quality, ratios).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <unistd.h>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/generators/mesh_domain_2.h"
#include "certimesh/io/mesh_file.h"
#include "certimesh/topology/quality.h"

namespace {

using certimesh::generators::PlanarDomain;

struct Row {
  double h = 0;
  std::size_t triangles = 0;
  double seconds = 0;        // median over the repetitions (pipeline total, or gmsh's 2D CPU)
  double front_seconds = 0;  // certimesh: the advancing-front stage alone
  double worst = 0, mean = 0;
};

struct Options {
  std::vector<double> sizes{0.01, 0.005, 0.0025, 0.00125};
  int repetitions = 3;
  std::string gmsh = "gmsh";
  bool delaunay = false;
};

PlanarDomain unit_square() {
  PlanarDomain d;
  d.points = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  d.segments = {{0, 1, 1}, {1, 2, 1}, {2, 3, 1}, {3, 0, 1}};
  return d;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

void quality_of(const certimesh::io::MeshData& m, double& worst, double& mean) {
  worst = 1.0;
  double sum = 0.0;
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    certimesh::topology::Point2d p[3];
    for (int i = 0; i < 3; ++i) {
      const auto v = m.triangles[3 * t + static_cast<std::size_t>(i)];
      p[i] = {m.coordinates[static_cast<std::size_t>(m.dimension) * v],
              m.coordinates[static_cast<std::size_t>(m.dimension) * v + 1]};
    }
    const double q = certimesh::topology::triangle_quality(p[0], p[1], p[2]);
    worst = std::min(worst, q);
    sum += q;
  }
  mean = m.triangle_count() ? sum / static_cast<double>(m.triangle_count()) : 0.0;
}

Row run_certimesh(double h, const Options& o) {
  const PlanarDomain domain = unit_square();
  const certimesh::io::MeshData domain_data = certimesh::generators::to_mesh_data(domain);
  certimesh::generators::MeshDomainOptions2 options;
  options.size.uniform_size = h;
  options.algorithm = o.delaunay ? certimesh::generators::MeshAlgorithm2::delaunay
                                 : certimesh::generators::MeshAlgorithm2::advancing_front;
  Row row{h, 0, 0, 0, 0, 0};
  std::vector<double> totals, fronts;
  for (int r = 0; r < o.repetitions; ++r) {
    const auto result = certimesh::generators::mesh_domain_2(domain, options);
    double total = 0.0, front = 0.0;
    for (const auto& t : result.stats.timings) {
      total += t.seconds;
      if (t.stage == "advancing front" || t.stage == "delaunay refinement") front += t.seconds;
    }
    totals.push_back(total);
    fronts.push_back(front);
    if (r == 0) {
      const auto report = certimesh::certificate::check_mesh(result.mesh, &domain_data);
      if (!report.valid) {
        std::fprintf(stderr, "error: the certimesh mesh at h=%g fails its certificate: %s\n", h,
                     report.finding.message.c_str());
        std::exit(1);
      }
      row.triangles = result.mesh.triangle_count();
      quality_of(result.mesh, row.worst, row.mean);
    }
  }
  row.seconds = median(totals);
  row.front_seconds = median(fronts);
  return row;
}

// gmsh's own CPU time for the 2D stage, from "Done meshing 2D (Wall Xs, CPU Ys)".
double gmsh_cpu_seconds(const std::filesystem::path& log) {
  std::ifstream in(log);
  std::string line;
  while (std::getline(in, line)) {
    const auto at = line.find("Done meshing 2D");
    if (at == std::string::npos) continue;
    const auto cpu = line.find("CPU ", at);
    if (cpu != std::string::npos) return std::atof(line.c_str() + cpu + 4);
  }
  return -1.0;
}

bool run_gmsh(double h, const Options& o, const std::filesystem::path& dir, Row& row) {
  const auto geo = dir / "square.geo";
  std::ofstream(geo) << "SetFactory(\"OpenCASCADE\");\nRectangle(1) = {0,0,0,1,1};\n";
  const auto out = dir / "square.msh";
  const auto log = dir / "gmsh.log";
  std::vector<double> times;
  for (int r = 0; r < o.repetitions; ++r) {
    std::ostringstream cmd;
    cmd << o.gmsh << " '" << geo.string() << "' -2 -algo front2d -nt 1 -clmax " << h << " -format msh41 -o '"
        << out.string() << "' > '" << log.string() << "' 2>&1";
    if (std::system(cmd.str().c_str()) != 0) return false;
    const double t = gmsh_cpu_seconds(log);
    if (t < 0) return false;
    times.push_back(t);
  }
  const auto mesh = certimesh::io::read_mesh(out);
  row = Row{h, mesh.triangle_count(), median(times), 0, 0, 0};
  quality_of(mesh, row.worst, row.mean);
  return true;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--sizes" && i + 1 < argc) {
      o.sizes.clear();
      std::stringstream s(argv[++i]);
      for (std::string item; std::getline(s, item, ',');) o.sizes.push_back(std::atof(item.c_str()));
    } else if (a == "--repetitions" && i + 1 < argc) {
      o.repetitions = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--gmsh" && i + 1 < argc) {
      o.gmsh = argv[++i];
    } else if (a == "--algorithm" && i + 1 < argc) {
      o.delaunay = std::string(argv[++i]) == "delaunay";
    } else {
      std::fprintf(stderr, "error: unknown argument '%s'\n", argv[i]);
      std::exit(2);
    }
  }
  return o;
}

void print_row(const char* who, const Row& r) {
  const double n = static_cast<double>(r.triangles);
  std::printf("| %s | %g | %zu | %.3f | %.0f | %.3f | %.4f | %.4f |\n", who, r.h, r.triangles, r.seconds,
              n / r.seconds, 1e6 * r.seconds / (n * std::log(n)), r.worst, r.mean);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  const auto dir = std::filesystem::temp_directory_path() / ("certimesh_bench_mesh_2d_" + std::to_string(getpid()));
  std::filesystem::create_directories(dir);
  std::printf("| mesher | h | N_f | t, s | N_f/t, 1/s | t/(N_f ln N_f), us | Q worst | Q mean |\n");
  std::printf("|---|---|---|---|---|---|---|---|\n");
  std::vector<std::pair<Row, Row>> pairs;
  for (const double h : o.sizes) {
    const Row ours = run_certimesh(h, o);
    print_row(o.delaunay ? "certimesh delaunay" : "certimesh front", ours);
    std::printf("| (%s stage alone) | %g | %zu | %.3f | %.0f | | | |\n",
                o.delaunay ? "delaunay refinement" : "advancing-front", h, ours.triangles, ours.front_seconds,
                static_cast<double>(ours.triangles) / ours.front_seconds);
    Row peer;
    if (o.gmsh != "none" && run_gmsh(h, o, dir, peer)) {
      print_row("gmsh -2 front2d", peer);
      pairs.emplace_back(ours, peer);
    }
    std::fflush(stdout);
  }
  if (!pairs.empty()) {
    std::printf("\n| h | throughput certimesh / gmsh (tris/s) | Q worst certimesh - gmsh |\n|---|---|---|\n");
    for (const auto& [ours, peer] : pairs) {
      const double rate = (static_cast<double>(ours.triangles) / ours.seconds) /
                          (static_cast<double>(peer.triangles) / peer.seconds);
      std::printf("| %g | %.1fx | %+.4f |\n", ours.h, rate, ours.worst - peer.worst);
    }
  }
  std::filesystem::remove_all(dir);
  return 0;
}
