// The §5.2 regrading experiment (digest D §6.1): the square with two round holes, a
// quasi-uniform start mesh of about 1,800 triangles (the 2D pipeline without improvement),
// regraded by Algorithm 35 with the size-aware quality (6.1.5) towards a size proportional to
// the distance to the nearer hole centre, scaled so that the target count equals the start
// count, with the monograph's three operation sets. Prints, per set: iterations, successes per
// operation, worst and mean quality, triangle count and time, beside the monograph's numbers;
// every result is checked by the certificate against the domain.
//
// The boundary trace, by default, is kept as the monograph keeps it (digest D §2.1: boundary
// nodes "may move only along boundary edges", boundary edges are split and collapsed): kept
// geometrically, on the input segments. Steiner vertices slide along their input segment,
// may be collapsed into a neighbour on it, and boundary edges are split on it; every such
// vertex is the rounding of an exact point of its segment (design decision 2), so the
// certificate still finds it on the domain. The domain's own vertices (the square's corners,
// the holes' polygon vertices) never move: unlike the monograph's round holes, ours are
// polygons (--hole-segments, 16 by default), and their vertices are fixed points of the input.
// --trace-vertex-for-vertex keeps the old run (no boundary vertex moves or goes; boundary
// edges split onto the segment nearest the midpoint).
//
//   experiment_regrade_2d [--h 0.033] [--max-operations N] [--target Q0] [--basket-size N2]
//                         [--baskets N3] [--hole-segments N] [--min-shift-gain G] [--trace-vertex-for-vertex]
//                         [--coarsen-straight-boundary]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/generators/domain/default_domains.h"
#include "certimesh/generators/improvement/input_segments_2.h"
#include "certimesh/generators/improvement/quality_improvement_2.h"
#include "certimesh/generators/mesh_domain_2.h"
#include "certimesh/topology/local_modifications_2.h"
#include "certimesh/topology/mesh_data_conversion.h"
#include "certimesh/topology/quality.h"
#include "point_on_segment.h"

namespace {

namespace gen = certimesh::generators;
namespace topo = certimesh::topology;
using certimesh::predicates::Point2;

struct Arguments {
  double h = 0.033;  // near the monograph's 1,827 triangles (1,838 at dd5e996; 1,908 after 845023e's front)
  std::uint64_t max_operations = 0;  // 0: 100 x the start count; stagnation (N3) stops earlier
  double target = 0.9;
  std::uint32_t basket_size = 0;  // N2; 0: the default (7 %)
  std::uint32_t baskets = 0;      // N3; 0: the default (N2 * N3 just above the count)
  bool coarsen_straight_boundary = false;
  bool trace_vertex_for_vertex = false;
  std::size_t hole_segments = 16;
  double minimum_shift_gain = 1e-3;  // ImprovementOptions2's default
};

Arguments parse(int argc, char** argv) {
  Arguments a;
  for (int i = 1; i < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--coarsen-straight-boundary" || key == "--trace-vertex-for-vertex") {
      (key == "--coarsen-straight-boundary" ? a.coarsen_straight_boundary : a.trace_vertex_for_vertex) = true;
      --i;
      continue;
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "error: option %s needs a value\n", key.c_str());
      std::exit(2);
    }
    if (key == "--h") a.h = std::atof(argv[i + 1]);
    else if (key == "--max-operations") a.max_operations = std::strtoull(argv[i + 1], nullptr, 10);
    else if (key == "--target") a.target = std::atof(argv[i + 1]);
    else if (key == "--basket-size") a.basket_size = static_cast<std::uint32_t>(std::atoi(argv[i + 1]));
    else if (key == "--baskets") a.baskets = static_cast<std::uint32_t>(std::atoi(argv[i + 1]));
    else if (key == "--min-shift-gain") a.minimum_shift_gain = std::atof(argv[i + 1]);
    else if (key == "--hole-segments") a.hole_segments = std::strtoull(argv[i + 1], nullptr, 10);
    else {
      std::fprintf(stderr, "error: unknown option %s\n", key.c_str());
      std::exit(2);
    }
  }
  return a;
}

const std::vector<Point2> hole_centres{{0.3, 0.5}, {0.7, 0.5}};

double distance_to_holes(const Point2& p) {
  double d = std::numeric_limits<double>::infinity();
  for (const Point2& c : hole_centres) d = std::min(d, std::hypot(p.x - c.x, p.y - c.y));
  return d;
}

bool in_domain(const Point2& p) { return distance_to_holes(p) > 0.1; }

// Size h(x) = c·d(x): the count of equilateral triangles of side h covering the domain is
// ∫ 1/(√3/4 h²) dA; c makes it `count` (midpoint rule on a 1000 x 1000 grid).
double size_scale_for_count(double count) {
  constexpr int n = 1000;
  double integral = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Point2 p{(i + 0.5) / n, (j + 0.5) / n};
      if (in_domain(p)) integral += 1.0 / (distance_to_holes(p) * distance_to_holes(p)) / (n * n);
    }
  return std::sqrt(integral / (std::sqrt(3.0) / 4.0 * count));
}

// The domain segment an edge (a, b) of the mesh boundary lies on: the one nearest both ends.
double distance_to_segment(const Point2& p, const Point2& a, const Point2& b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  return std::hypot(p.x - a.x - t * dx, p.y - a.y - t * dy);
}

topo::BoundaryProjection2 projection_onto(const gen::PlanarDomain& domain, const topo::TriangleMesh2& mesh) {
  return [&domain, &mesh](topo::VertexId a, topo::VertexId b, const topo::Point2d& m) {
    const auto pa = mesh.point(a), pb = mesh.point(b);
    const Point2 A{pa[0], pa[1]}, B{pb[0], pb[1]};
    const gen::DomainSegment* best = nullptr;
    double best_distance = std::numeric_limits<double>::infinity();
    for (const auto& s : domain.segments) {
      const double d = std::max(distance_to_segment(A, domain.points[s.a], domain.points[s.b]),
                                distance_to_segment(B, domain.points[s.a], domain.points[s.b]));
      if (d < best_distance) best_distance = d, best = &s;
    }
    const Point2 s0 = domain.points[best->a], s1 = domain.points[best->b];
    const double dx = s1.x - s0.x, dy = s1.y - s0.y;
    const double f = std::clamp(((m[0] - s0.x) * dx + (m[1] - s0.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    const Point2 q = gen::detail::point_on_segment(s0, s1, f);
    return topo::Point2d{q.x, q.y};
  };
}

// Where the worst element is, and whether its vertices are on the trace: what caps the result.
void print_worst(const topo::TriangleMesh2& mesh, const gen::ImprovementOptions2& options,
                 const gen::PlanarDomain& domain) {
  const auto is_domain_vertex = [&domain](const topo::Point2d& p) {
    return std::any_of(domain.points.begin(), domain.points.end(),
                       [&p](const Point2& q) { return q.x == p[0] && q.y == p[1]; });
  };
  double worst = 2.0;
  topo::ElementId at{};
  for (std::uint32_t s = 0; s < mesh.element_slot_count(); ++s) {
    const topo::ElementId e{s};
    if (!mesh.is_live(e)) continue;
    const auto v = mesh.vertices(e);
    const auto a = mesh.point(v[0]), b = mesh.point(v[1]), c = mesh.point(v[2]);
    const Point2 centroid{(a[0] + b[0] + c[0]) / 3, (a[1] + b[1] + c[1]) / 3};
    const double q = certimesh::topology::size_aware_triangle_quality(a, b, c, options.size.at(centroid));
    if (q < worst) worst = q, at = e;
  }
  const auto v = mesh.vertices(at);
  std::printf("  worst element:");
  for (const auto x : v)
    std::printf(" (%.4f, %.4f)%s", mesh.point(x)[0], mesh.point(x)[1],
                is_domain_vertex(mesh.point(x)) ? "D" : topo::is_trace_vertex(mesh, x) ? "T" : "");
  std::printf("  (D: a domain vertex, fixed; T: another vertex on the boundary trace)\n");
}

struct OperationSet {
  const char* name;
  std::uint8_t operations;
  const char* monograph;
};

}  // namespace

int main(int argc, char** argv) {
  const Arguments args = parse(argc, argv);
  if (args.hole_segments < 3) {
    std::fprintf(stderr, "error: --hole-segments needs at least 3\n");
    return 2;
  }
  const gen::PlanarDomain domain = gen::square_with_two_holes(args.hole_segments);
  gen::MeshDomainOptions2 mesh_options;
  mesh_options.improve = false;
  mesh_options.size.uniform_size = args.h;
  mesh_options.size.grading = 0.0;  // the uniform start mesh of §5.2, not the boundary-adapted size
  const auto start = gen::mesh_domain_2(domain, mesh_options);
  const double count = static_cast<double>(start.stats.triangles);
  const double scale = size_scale_for_count(count);
  std::printf("start: %llu triangles (quasi-uniform, h = %g; monograph: 1827); size h(x) = %.4f * d(x); "
              "holes: %zu-gons; boundary trace kept %s\n",
              static_cast<unsigned long long>(start.stats.triangles), args.h, scale, args.hole_segments,
              args.trace_vertex_for_vertex ? "vertex for vertex" : "on the input segments (vertices slide)");

  // The domain as the certificate reads it.
  certimesh::io::MeshData domain_data;
  domain_data.dimension = 2;
  for (const Point2& p : domain.points) domain_data.coordinates.insert(domain_data.coordinates.end(), {p.x, p.y});
  for (const auto& s : domain.segments) {
    domain_data.segments.insert(domain_data.segments.end(), {s.a, s.b});
    domain_data.segment_labels.push_back(s.label);
  }
  for (const Point2& h : domain.holes) domain_data.holes.insert(domain_data.holes.end(), {h.x, h.y});

  using Op = gen::LocalOperation2;
  const auto bit = [](Op op) { return static_cast<std::uint8_t>(op); };
  const OperationSet sets[] = {
      {"shift", bit(Op::node_shift), "13000 iterations, mesh virtually unchanged"},
      {"insert+shift+collapse+delete",
       static_cast<std::uint8_t>(bit(Op::insert_on_edge) | bit(Op::node_shift) | bit(Op::edge_collapse) |
                                 bit(Op::node_deletion)),
       "47287 iterations (97% shifts), Q 0.73, avg 0.88"},
      {"all five", gen::all_local_operations_2, "22682 iterations, Q 0.78, avg 0.89"},
  };
  std::printf("%-30s %9s %8s %8s %9s %7s %7s %7s %7s %7s %6s %8s  %s\n", "operations", "iter", "worst", "mean",
              "triangles", "insert", "flip", "shift", "collap", "delete", "cert", "seconds", "monograph");
  bool all_valid = true;
  for (const OperationSet& set : sets) {
    auto converted = topo::from_mesh_data<topo::TriangleMesh2>(start.mesh);
    if (!converted.ok()) {
      std::fprintf(stderr, "error: %s\n", converted.error->message.c_str());
      return 1;
    }
    topo::TriangleMesh2 mesh = std::move(*converted.mesh);
    gen::ImprovementOptions2 options;
    options.target_quality = args.target;
    options.operations = set.operations;
    options.schedule = gen::ImprovementSchedule2::baskets;  // the monograph's listing, as §5.2 runs it
    options.basket_size = args.basket_size;
    options.max_baskets = args.baskets;
    options.coarsen_straight_boundary = args.coarsen_straight_boundary;
    options.minimum_shift_gain = args.minimum_shift_gain;
    options.max_operations = args.max_operations > 0 ? args.max_operations : 100 * start.stats.triangles;
    options.size.size_function = [scale](const Point2& p) { return scale * distance_to_holes(p); };
    if (args.trace_vertex_for_vertex) options.boundary_projection = projection_onto(domain, mesh);
    else options.input_segments = gen::input_segments_of(domain);
    const auto t0 = std::chrono::steady_clock::now();
    const auto stats = gen::improve_quality_2(mesh, options);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const auto report = certimesh::certificate::check_mesh(topo::to_mesh_data(mesh), &domain_data);
    all_valid = all_valid && report.valid;
    std::printf("%-30s %9llu %8.4f %8.4f %9zu %7llu %7llu %7llu %7llu %7llu %6s %8.2f  %s\n", set.name,
                static_cast<unsigned long long>(stats.iterations), stats.final_worst, stats.final_mean,
                mesh.element_count(), static_cast<unsigned long long>(stats.successes[0]),
                static_cast<unsigned long long>(stats.successes[1]),
                static_cast<unsigned long long>(stats.successes[2]),
                static_cast<unsigned long long>(stats.successes[3]),
                static_cast<unsigned long long>(stats.successes[4]), report.valid ? "valid" : "FAIL", seconds,
                set.monograph);
    if (&set == &sets[0])
      std::printf("%-30s %9s %8.4f %8.4f %9zu  (the start mesh, graded size-aware quality)\n", "start", "-",
                  stats.initial_worst, stats.initial_mean, start.stats.triangles);
    print_worst(mesh, options, domain);
    if (!report.valid) std::printf("  certificate: %s\n", report.finding.message.c_str());
  }
  return all_valid ? 0 : 1;
}
