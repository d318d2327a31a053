// `certimesh mesh` in 3D: the pipeline of mesh_solid_3.h, the certificate, the summary a
// person reads (counts, quality, smallest dihedral angle, Steiner points, time per stage).
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "certimesh/generators/delaunay/boundary_recovery_3.h"
#include "certimesh/generators/domain/surface_problem_3.h"
#include "certimesh/generators/delaunay/solid_regions_3.h"
#include "certimesh/generators/mesh_solid_3.h"
#include "certimesh/io/svg_cut_3.h"
#include "certimesh/topology/quality.h"
#include "mesh_output.h"

namespace certimesh::cli {

namespace {

// Per tetrahedron, its quality and smallest dihedral angle: one pass, for the summary and the
// picture.
struct Quality3 {
  std::vector<double> quality;
  double worst = 1.0, mean = 0.0, smallest_dihedral = 180.0;
};

Quality3 quality_of(const io::MeshData& m) {
  Quality3 q;
  q.quality.resize(m.tetrahedron_count());
  const auto p = [&](io::Index v) {
    return topology::Point3d{m.coordinates[3 * v], m.coordinates[3 * v + 1], m.coordinates[3 * v + 2]};
  };
  for (std::size_t t = 0; t < m.tetrahedron_count(); ++t) {
    const io::Index* c = &m.tetrahedra[4 * t];
    q.quality[t] = topology::tetrahedron_quality(p(c[0]), p(c[1]), p(c[2]), p(c[3]));
    q.worst = std::min(q.worst, q.quality[t]);
    q.mean += q.quality[t];
    q.smallest_dihedral =
        std::min(q.smallest_dihedral, topology::tetrahedron_min_dihedral_angle(p(c[0]), p(c[1]), p(c[2]), p(c[3])));
  }
  if (m.tetrahedron_count() > 0) q.mean /= static_cast<double>(m.tetrahedron_count());
  return q;
}

void print_summary_3(const generators::MeshResult3& r, const Quality3& q, const certificate::Report& report,
                     const char* what) {
  std::printf("mesh: %zu vertices (%zu input, %zu Steiner inside, %zu on the boundary), %zu tetrahedra (%zu boundary triangles): %s\n",
              r.mesh.point_count(), r.stats.input_vertices, r.stats.interior_steiner_points,
              r.stats.boundary_steiner_points, r.mesh.tetrahedron_count(), report.statistics.boundary_facets, what);
  std::printf("quality 6^4*sqrt(2)*volume/perimeter^3: worst %.4f, mean %.4f; smallest dihedral angle %.2f degrees\n",
              q.worst, q.mean, q.smallest_dihedral);
  const generators::TetrahedralRefinementStats& s = r.stats.refinement;
  if (s.inserted + s.refused_outside + s.refused_close + s.refused_other > 0) {
    std::printf("refinement: %llu points (%llu circumcentres, %llu centroids); %llu tetrahedra above the radius-edge bound left%s\n",
                static_cast<unsigned long long>(s.inserted), static_cast<unsigned long long>(s.circumcentres),
                static_cast<unsigned long long>(s.centroids), static_cast<unsigned long long>(s.skinny_left),
                s.bound_reached ? " (the insertion budget was reached)" : "");
  }
  const generators::ImprovementStats3& im = r.stats.improvement;
  if (im.ran)
    std::printf("improvement: worst %.4f -> %.4f; %llu edge removals, %llu 2-3 flips, %llu node shifts in %llu attempts, %u passes\n",
                im.worst_before, im.worst_after, static_cast<unsigned long long>(im.edge_removals),
                static_cast<unsigned long long>(im.flips_2_3), static_cast<unsigned long long>(im.node_shifts),
                static_cast<unsigned long long>(im.attempts), im.passes);
  double total = 0.0;
  for (const auto& t : r.stats.stages) total += t.seconds;
  std::printf("time: %.3f s (", total);
  for (std::size_t i = 0; i < r.stats.stages.size(); ++i)
    std::printf("%s%.*s %.3f", i ? ", " : "", static_cast<int>(r.stats.stages[i].stage.size()),
                r.stats.stages[i].stage.data(), r.stats.stages[i].seconds);
  std::printf(")\ncertificate: %s\n", report.valid ? "valid, a conforming mesh of positive tetrahedra" : "INVALID");
}

int refuse_surface(const std::string& path, const generators::InvalidSurface& e) {
  for (const auto& p : e.problems()) std::fprintf(stderr, "error: %s: %s\n", path.c_str(), p.message.c_str());
  if (e.problems().empty()) std::fprintf(stderr, "error: %s: %s\n", path.c_str(), e.what());
  return 1;
}

}  // namespace

int mesh_solid_3(const MeshOptions& options, const io::MeshData& input) {
  generators::MeshOptions3 o;
  o.size = options.size;
  if (options.radius_edge > 0.0) o.max_radius_edge = options.radius_edge;  // else the default, 2
  o.refine_surface = options.refine_surface;
  o.improve = options.improve;
  o.max_insertions = options.max_steiner;  // the refinement stops there and says so (exit 4)
  const bool points_only = is_point_set(input);
  if (!points_only && !input.tetrahedra.empty()) {
    std::fprintf(stderr, "error: %s: a tetrahedral mesh, not a surface or a point set: `certimesh check` certifies it\n",
                 options.domain.c_str());
    return 2;
  }
  // A point set is refined only when asked, as `tetgen` refines only with -q or -a; a
  // surface always (radius-edge 2, sizes from its own edges, unless told otherwise).
  o.refine = !points_only || options.size > 0.0 || options.radius_edge > 0.0;
  generators::MeshResult3 result;
  try {
    result = points_only ? generators::mesh_convex_hull_3(input, o, terminal_progress(options.quiet))
                         : generators::mesh_surface_3(generators::read_surface_3(options.domain), o,
                                                      terminal_progress(options.quiet));
  } catch (const generators::InvalidSurface& e) {
    return refuse_surface(options.domain, e);
  } catch (const generators::SolidRegionsError& e) {
    std::string why = e.what();
    if (why.rfind("error: ", 0) == 0) why.erase(0, 7);
    std::fprintf(stderr, "error: %s: %s (nothing written)\n", options.domain.c_str(), why.c_str());
    return 2;
  } catch (const generators::BoundaryRecoveryError& e) {
    std::string why = e.what();
    if (why.rfind("error: ", 0) == 0) why.erase(0, 7);  // the message is the library's sentence
    std::fprintf(stderr, "error: %s: the boundary could not be recovered: %s (nothing written)\n", options.domain.c_str(),
                 why.c_str());
    return 3;
  }
  if (!options.quiet && isatty(STDERR_FILENO)) std::fputs("\r\033[K", stderr);
  // A surface's mesh is certified against the surface as the file gives it; a point set's as
  // a valid mesh (its domain, the hull, is what the tetrahedra make).
  const certificate::Report report = certificate::check_mesh(result.mesh, points_only ? nullptr : &input);
  const Quality3 quality = quality_of(result.mesh);
  print_summary_3(result, quality, report,
                  !points_only ? "the solid the surface bounds"
                  : o.refine   ? "the convex hull of the points, refined"
                               : "the Delaunay tetrahedralization of the points");
  if (!report.valid) {
    std::fprintf(stderr, "error: internal: the tetrahedralization fails its certificate: %s: %s (nothing written)\n",
                 std::string(certificate::defect_name(report.finding.defect)).c_str(), report.finding.message.c_str());
    return 3;
  }
  MeshOptions without_svg = options;  // the 2D picture is not for a 3D mesh: the cut is
  without_svg.svg.clear();
  write_outputs(without_svg, result.mesh, input, report);
  if (!options.svg.empty()) io::write_svg_cut_picture(result.mesh, io::middle_z(result.mesh), quality.quality, options.svg);
  if (result.stats.refinement.bound_reached) {
    std::fprintf(stderr, "warning: the refinement stopped at --max-steiner %llu points, short of --size; the mesh was written\n",
                 static_cast<unsigned long long>(options.max_steiner));
    return 4;
  }
  return 0;
}

}  // namespace certimesh::cli
