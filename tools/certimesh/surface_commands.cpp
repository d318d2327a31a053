// `certimesh check-surface SURFACE`: reads a closed triangulated surface and validates it
// exactly (generators/domain/surface_validation_3.h); prints its counts or every problem.
#include <cstdio>
#include <string>

#include "certimesh/generators/domain/surface_3.h"
#include "certimesh/generators/domain/surface_validation_3.h"
#include "certimesh/io/format_error.h"
#include "cli.h"

namespace certimesh::cli {

namespace gen = certimesh::generators;

namespace {

void print_problems(const std::string& path, const std::vector<gen::SurfaceProblem>& problems, std::size_t total_pairs) {
  for (const gen::SurfaceProblem& p : problems) std::fprintf(stderr, "error: %s: %s\n", path.c_str(), p.message.c_str());
  if (total_pairs > problems.size())
    std::fprintf(stderr, "error: %s: %zu intersecting pairs of triangles in all (the first %zu listed)\n", path.c_str(), total_pairs, problems.size());
}

}  // namespace

int run_check_surface(const std::string& path) {
  gen::Surface3 surface;
  try {
    surface = gen::read_surface_3(path);
  } catch (const io::FormatError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  } catch (const gen::InvalidSurface& e) {
    print_problems(path, e.problems(), 0);
    return 1;
  }
  const gen::SurfaceCheck check = gen::check_surface(surface, 10);
  if (!check.problems.empty()) {
    print_problems(path, check.problems, check.problems.front().kind == gen::SurfaceProblemKind::self_intersection ? check.intersecting_pairs : 0);
    return 1;
  }
  std::printf("%s: valid closed surface: %zu vertices, %zu triangles, %zu shells (%zu solids, %zu cavities, %zu interfaces)",
              path.c_str(), surface.points.size() - check.unused_vertices, surface.triangles.size(), check.shells.size(), check.solids,
              check.cavities, check.interfaces);
  if (check.unused_vertices > 0) std::printf(", %zu vertices in no triangle", check.unused_vertices);
  // TetGen's hole and region points are passed on to the mesher, which locates them.
  if (!surface.holes.empty()) std::printf(", %zu hole points", surface.holes.size());
  if (!surface.region_points.empty()) std::printf(", %zu region points", surface.region_points.size());
  std::printf("\n");
  return 0;
}

}  // namespace certimesh::cli
