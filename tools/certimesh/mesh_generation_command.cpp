// `certimesh mesh`: a domain in, a certified mesh out. The library meshes and reports
// progress through a callback; this file decides what a person sees, certifies the mesh with
// the independent checker and writes nothing unless the certificate holds.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/generators/delaunay/constrained_delaunay_2.h"
#include "certimesh/generators/delaunay/point_set_2.h"
#include "certimesh/generators/domain/convex_hull_2.h"
#include "certimesh/generators/domain/default_domains.h"
#include "certimesh/generators/domain/domain_problem.h"
#include "certimesh/generators/domain/domain_validation.h"
#include "certimesh/generators/mesh_domain_2.h"
#include "certimesh/io/format_error.h"
#include "certimesh/io/mesh_file.h"
#include "certimesh/io/svg_picture.h"
#include "certimesh/predicates/orient2d.h"
#include "cli.h"
#include "mesh_output.h"

#ifndef CERTIMESH_VERSION
#define CERTIMESH_VERSION "unknown"
#endif

namespace certimesh::cli {

namespace {

using generators::PlanarDomain;

constexpr const char* kBuiltinPrefix = "builtin:";

// The domain named on the command line: a .poly file, or one of the built-in domains.
PlanarDomain load_domain(const std::string& name) {
  if (name.rfind(kBuiltinPrefix, 0) == 0) {
    const std::string which = name.substr(std::string(kBuiltinPrefix).size());
    if (which == "plate") return generators::plate_with_holes_and_crack();
    if (which == "square") return generators::unit_square();
    if (which == "two-holes") return generators::square_with_two_holes();
    throw std::invalid_argument("unknown built-in domain '" + which + "' (plate, square, two-holes)");
  }
  return generators::planar_domain_from_mesh_data(io::read_mesh(name));
}

void print_summary(const generators::MeshDomainStats2& s, const certificate::Report& report) {
  std::printf("mesh: %llu vertices (%llu on the boundary), %llu triangles",
              static_cast<unsigned long long>(s.vertices), static_cast<unsigned long long>(s.boundary_vertices),
              static_cast<unsigned long long>(s.triangles));
  if (s.completed_by_delaunay > 0) {
    std::printf(", %llu of them by the Delaunay completion", static_cast<unsigned long long>(s.completed_by_delaunay));
  }
  std::printf("\nquality 12*sqrt(3)*area/perimeter^2: worst %.4f, mean %.4f\n", s.worst_quality, s.mean_quality);
  if (s.isolated_vertices + s.dropped_vertices + s.eaten_segments > 0) {
    std::printf("input: %llu vertices on no segment kept as mesh vertices, %llu vertices outside the domain dropped, "
                "%llu segments with the domain on neither side eaten\n",
                static_cast<unsigned long long>(s.isolated_vertices), static_cast<unsigned long long>(s.dropped_vertices),
                static_cast<unsigned long long>(s.eaten_segments));
  }
  if (s.area_bisections > 0) {
    std::printf("maximum areas: %llu bisections\n", static_cast<unsigned long long>(s.area_bisections));
  }
  if (s.improved_region > 0) {
    std::printf("improvement: %llu triangles around the worst ones, %llu iterations, %llu local modifications\n",
                static_cast<unsigned long long>(s.improved_region),
                static_cast<unsigned long long>(s.improvement_iterations),
                static_cast<unsigned long long>(s.improvement_operations));
  }
  if (s.quality_refined) {
    const generators::QualityRefinementStats& q = s.quality;
    std::printf("min-angle refinement: %llu Steiner points (%llu on segments); smallest angle %.2f degrees",
                static_cast<unsigned long long>(q.inserted), static_cast<unsigned long long>(q.segment_splits),
                q.smallest_angle);
    if (q.exempt > 0)
      std::printf(", %llu triangles exempt (small input angle, down to %.2f degrees)",
                  static_cast<unsigned long long>(q.exempt), q.smallest_exempt_angle);
    std::printf("\n");
  }
  double total = 0.0;
  for (const auto& t : s.timings) total += t.seconds;
  std::printf("time: %.3f s (", total);
  for (std::size_t i = 0; i < s.timings.size(); ++i) {
    std::printf("%s%s %.3f", i ? ", " : "", s.timings[i].stage.c_str(), s.timings[i].seconds);
  }
  std::printf(")\ncertificate: %s\n", report.valid ? "valid, the triangles tile the domain exactly once" : "INVALID");
}

int refuse_domain(const std::string& name, const generators::InvalidDomain& e) {
  for (const auto& p : e.problems()) std::fprintf(stderr, "error: %s: %s\n", name.c_str(), p.message.c_str());
  if (e.problems().empty()) std::fprintf(stderr, "error: %s: %s\n", name.c_str(), e.what());
  return 1;
}

// The convex hull of a point set as a domain, for the certificate: Andrew's monotone chain with
// exact orient2d, points on a hull edge kept as domain vertices (they are mesh vertices). It
// shares no code with the triangulation it certifies.
io::MeshData convex_hull_domain(const io::MeshData& points) {
  std::vector<io::Index> order(points.point_count());
  for (io::Index i = 0; i < order.size(); ++i) order[i] = i;
  auto at = [&](io::Index v) { return predicates::Point2{points.coordinates[2 * v], points.coordinates[2 * v + 1]}; };
  std::sort(order.begin(), order.end(), [&](io::Index a, io::Index b) { return at(a).x != at(b).x ? at(a).x < at(b).x : at(a).y < at(b).y; });
  std::vector<io::Index> hull;
  for (int pass = 0; pass < 2; ++pass, std::reverse(order.begin(), order.end())) {  // lower, then upper chain
    const std::size_t base = hull.size();
    for (io::Index v : order) {
      while (hull.size() >= base + 2 && predicates::orient2d(at(hull[hull.size() - 2]), at(hull.back()), at(v)) == predicates::Sign::negative)
        hull.pop_back();
      hull.push_back(v);
    }
    hull.pop_back();  // the chain's last point starts the other chain
  }
  io::MeshData domain;
  domain.dimension = 2;
  domain.coordinates = points.coordinates;
  for (std::size_t i = 0; i < hull.size(); ++i) {
    domain.segments.push_back(hull[i]);
    domain.segments.push_back(hull[(i + 1) % hull.size()]);
  }
  domain.segment_labels.assign(domain.segment_count(), 0);
  return domain;
}

// A point set (a .node file: points, no segments): its Delaunay triangulation, the convex hull
// meshed as Triangle does for a .node, certified against the hull before anything is written.
// A 3D one goes to the 3D pipeline (mesh_command_3.cpp).
int mesh_point_set(const MeshOptions& options, const io::MeshData& points) {
  if (points.dimension == 3) return mesh_solid_3(options, points);
  if (points.dimension != 2) {
    std::fprintf(stderr, "error: %s: a %d-dimensional point set: only 2D and 3D point sets are meshed\n",
                 options.domain.c_str(), points.dimension);
    return 2;
  }
  const io::MeshData mesh = generators::delaunay_of_points(points);
  const io::MeshData hull = convex_hull_domain(points);
  const certificate::Report report = certificate::check_mesh(mesh, &hull);
  std::printf("mesh: %zu vertices (%zu on the convex hull), %zu triangles: the Delaunay triangulation of the points\n",
              mesh.point_count(), hull.segment_count(), mesh.triangle_count());
  std::printf("quality 12*sqrt(3)*area/perimeter^2: worst %.4f\ncertificate: %s\n", report.statistics.worst_quality,
              report.valid ? "valid, the triangles tile the convex hull exactly once" : "INVALID");
  if (!report.valid) {
    std::fprintf(stderr, "error: internal: the triangulation fails its certificate: %s (nothing written)\n", report.finding.message.c_str());
    return 3;
  }
  write_outputs(options, mesh, hull, report);
  return 0;
}

}  // namespace

bool is_point_set(const io::MeshData& m) {
  return m.segments.empty() && m.triangles.empty() && m.tetrahedra.empty() && m.facets.empty() && m.point_count() > 0;
}

// Progress on standard error, only for a person at a terminal, at most every 0.2 s.
generators::ProgressCallback terminal_progress(bool quiet) {
  if (quiet || !isatty(STDERR_FILENO)) return {};
  auto last = std::make_shared<std::chrono::steady_clock::time_point>();
  return [last](const generators::Progress& p) {
    const auto now = std::chrono::steady_clock::now();
    if (now - *last < std::chrono::milliseconds(200) && p.done != p.total) return;
    *last = now;
    if (p.total > 0) {
      std::fprintf(stderr, "\r%-24.*s %3.0f%%", static_cast<int>(p.stage.size()), p.stage.data(),
                   100.0 * static_cast<double>(p.done) / static_cast<double>(p.total));
    } else {
      std::fprintf(stderr, "\r%-24.*s %llu", static_cast<int>(p.stage.size()), p.stage.data(),
                   static_cast<unsigned long long>(p.done));
    }
    std::fflush(stderr);
  };
}

// Writes the mesh and, when asked, its certificate and picture; each file atomically.
void write_outputs(const MeshOptions& options, const io::MeshData& mesh, const io::MeshData& domain,
                   const certificate::Report& report) {
  io::write_mesh(mesh, options.output);
  if (!options.certificate.empty()) {
    io::write_file_atomically(options.certificate, certificate::certificate_json(report, CERTIMESH_VERSION));
  }
  if (!options.svg.empty()) io::write_svg_picture(mesh, options.svg);
  if (!options.save_domain.empty()) io::write_mesh(domain, options.save_domain);
}

int run_mesh(const MeshOptions& options) {
  if (!output_extension_supported(options.output, kMeshOutputExtensions)) return 2;
  generators::MeshDomainOptions2 mesh_options;
  mesh_options.algorithm = options.delaunay ? generators::MeshAlgorithm2::delaunay
                                            : generators::MeshAlgorithm2::advancing_front;
  mesh_options.size.uniform_size = options.size;
  mesh_options.size.growth = options.gamma;
  mesh_options.size.grading = options.grading;
  mesh_options.improve = options.improve;
  mesh_options.min_angle = options.min_angle;
  mesh_options.max_steiner = options.max_steiner;
  try {
    if (options.domain.rfind(kBuiltinPrefix, 0) != 0) {
      const io::MeshData input = io::read_mesh(options.domain);
      if (input.dimension == 3) return mesh_solid_3(options, input);  // a surface or a point set
      if (is_point_set(input)) {
        if (options.min_angle > 0.0) {  // not silently ignored: the point set's triangulation is fixed
          std::fprintf(stderr, "error: %s: --min-angle needs a domain with segments (.poly); a point set is meshed as its Delaunay triangulation only\n",
                       options.domain.c_str());
          return 2;
        }
        return mesh_point_set(options, input);
      }
    }
    PlanarDomain domain = load_domain(options.domain);
    if (options.convex_hull) {
      std::size_t added = 0;
      domain = generators::with_convex_hull(domain, &added);
      if (!options.quiet) std::printf("convex hull: %zu segments added\n", added);
    }
    const io::MeshData domain_data = generators::to_mesh_data(domain);
    const generators::MeshDomainResult2 result =
        generators::mesh_domain_2(domain, mesh_options, terminal_progress(options.quiet));
    if (!options.quiet && isatty(STDERR_FILENO)) std::fputs("\r\033[K", stderr);
    const certificate::Report report = certificate::check_mesh(result.mesh, &domain_data);
    print_summary(result.stats, report);
    if (!report.valid) {  // never write a mesh the certificate refuses
      std::fprintf(stderr, "error: internal: the generated mesh fails its certificate: %s: %s (nothing written)\n",
                   std::string(certificate::defect_name(report.finding.defect)).c_str(),
                   report.finding.message.c_str());
      return 3;
    }
    write_outputs(options, result.mesh, domain_data, report);
    if (result.stats.quality_refined && result.stats.quality.below_min_angle > 0) {
      std::fprintf(stderr,
                   "warning: --min-angle %g not met: %llu triangles below it, not exempt (%s; %llu segment splits "
                   "refused); the mesh was written\n",
                   options.min_angle, static_cast<unsigned long long>(result.stats.quality.below_min_angle),
                   result.stats.quality.cap_reached ? "the Steiner cap --max-steiner was reached"
                                                    : "no admissible Steiner point was left for them",
                   static_cast<unsigned long long>(result.stats.quality.refused_splits));
      return 4;
    }
    return 0;
  } catch (const generators::InvalidDomain& e) {
    return refuse_domain(options.domain, e);
  } catch (const generators::DelaunayError& e) {
    std::fprintf(stderr, "error: %s: %s\n", options.domain.c_str(), e.what());
  } catch (const io::FormatError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "error: out of memory\n");
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "error: %s: %s\n", options.domain.c_str(), e.what());
  }
  return 2;
}

}  // namespace certimesh::cli
