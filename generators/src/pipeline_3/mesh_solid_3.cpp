// The 3D pipeline's driver (mesh_solid_3.h): runs the stages in order and times them.
#include "certimesh/generators/mesh_solid_3.h"

#include <chrono>

#include "certimesh/generators/delaunay/boundary_recovery_3.h"
#include "certimesh/generators/delaunay/delaunay_3.h"
#include "certimesh/generators/delaunay/solid_regions_3.h"
#include "certimesh/generators/domain/surface_validation_3.h"

namespace certimesh::generators {

namespace {

class SolidStageClock {
 public:
  explicit SolidStageClock(MeshStats3& stats) : stats_(stats) {}
  void stop(std::string_view stage) {
    const auto now = std::chrono::steady_clock::now();
    stats_.stages.push_back({stage, std::chrono::duration<double>(now - start_).count()});
    start_ = now;
  }

 private:
  MeshStats3& stats_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

std::vector<Point3> points_of_mesh(const io::MeshData& m) {
  std::vector<Point3> p(m.point_count());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = {m.coordinates[3 * i], m.coordinates[3 * i + 1], m.coordinates[3 * i + 2]};
  return p;
}

// The mesh as io::MeshData, vertices in no tetrahedron left out (the others keep their order,
// so input vertices stay first and in their order); returns how many were left out.
std::size_t solid_to_mesh_data(const Tetrahedralization3& solid, const std::vector<io::Label>& input_point_labels,
                         io::MeshData& mesh) {
  std::vector<std::uint32_t> id(solid.points.size(), 0);
  for (const auto& t : solid.tetrahedra)
    for (std::uint32_t v : t) id[v] = 1;
  std::uint32_t next = 0;
  std::size_t left_out = 0;
  mesh = io::MeshData{};
  mesh.dimension = 3;
  mesh.coordinates.reserve(3 * solid.points.size());
  for (std::size_t v = 0; v < solid.points.size(); ++v) {
    if (!id[v]) {
      ++left_out;
      continue;
    }
    id[v] = next++;
    const Point3& p = solid.points[v];
    mesh.coordinates.insert(mesh.coordinates.end(), {p.x, p.y, p.z});
    if (!input_point_labels.empty()) mesh.point_labels.push_back(v < input_point_labels.size() ? input_point_labels[v] : 0);
  }
  mesh.tetrahedra.reserve(4 * solid.tetrahedra.size());
  for (const auto& t : solid.tetrahedra)
    for (std::uint32_t v : t) mesh.tetrahedra.push_back(id[v]);
  mesh.tetrahedron_labels = solid.labels;
  mesh.tetrahedron_labels.resize(solid.tetrahedra.size(), 0);
  return left_out;
}

TetrahedralRefinementOptions refinement_options(const MeshOptions3& options) {
  TetrahedralRefinementOptions r;
  r.uniform_size = options.size;
  r.grading = options.grading;
  r.max_radius_edge = options.max_radius_edge;
  r.max_insertions = options.max_insertions;
  return r;
}

}  // namespace

MeshResult3 mesh_convex_hull_3(const io::MeshData& points, const MeshOptions3& options,
                               const ProgressCallback& progress) {
  MeshResult3 result;
  SolidStageClock clock(result.stats);
  Tetrahedralization3 solid;
  solid.points = points_of_mesh(points);
  result.stats.input_vertices = solid.points.size();
  solid.tetrahedra = Delaunay3(solid.points, progress).tetrahedra();
  clock.stop("delaunay");
  if (options.refine) {
    result.stats.refinement = refine_tetrahedra_3(solid, refinement_options(options), progress);
    clock.stop("refinement");
  }
  if (options.refine && options.improve) {  // unrefined, the Delaunay tetrahedralization is the answer
    result.stats.improvement = improve_tetrahedra_3(solid, static_cast<std::uint32_t>(points.point_count()));
    clock.stop("improvement");
  }
  result.stats.interior_steiner_points = solid.points.size() - result.stats.input_vertices;
  solid_to_mesh_data(solid, points.point_labels, result.mesh);
  return result;
}

MeshResult3 mesh_surface_3(Surface3 surface, const MeshOptions3& options, const ProgressCallback& progress) {
  MeshResult3 result;
  SolidStageClock clock(result.stats);
  const SurfaceCheck check = validate_surface(surface);  // orients .poly/.smesh shells outward
  result.stats.surface_shells = check.shells.size();
  result.stats.cavities = check.cavities;
  clock.stop("validation");
  BoundaryRecoveryOptions recovery_options;
  recovery_options.keep_surface_steiner_points = options.refine_surface;
  SolidMesh3 recovered = tetrahedralize_solid_3(surface.points, surface.triangles, recovery_options, progress);
  clock.stop("recovery");
  const BoundaryRecoveryCounts& counts = recovered.counts;
  result.stats.boundary_steiner_points = counts.edge_steiner_points + counts.face_steiner_points - counts.moved_inside;
  Tetrahedralization3 solid;
  solid.points = std::move(recovered.points);
  solid.tetrahedra = std::move(recovered.tetrahedra);
  if (!surface.holes.empty() || !surface.region_points.empty()) {
    if (options.refine_surface)  // the surface triangles are then unions of faces, not faces
      throw SolidRegionsError("error: hole and region points with --refine-surface are not supported yet");
    const SolidRegionCounts regions = apply_holes_and_regions_3(solid, surface.triangles, surface.holes,
                                                                surface.region_points, surface.region_attributes);
    result.stats.hole_tetrahedra = regions.hole_tetrahedra;
    clock.stop("regions");
  }
  // Surface triangles inside the solid (an interface: solid on both sides) stay faces.
  solid.constrained_faces = surface.triangles;
  if (options.refine) {
    result.stats.refinement = refine_tetrahedra_3(solid, refinement_options(options), progress);
    clock.stop("refinement");
  }
  if (options.improve) {  // input vertices (the first surface.points.size()) never move
    result.stats.improvement = improve_tetrahedra_3(solid, static_cast<std::uint32_t>(surface.points.size()));
    clock.stop("improvement");
  }
  result.stats.unused_input_vertices = check.unused_vertices;
  result.stats.input_vertices = surface.points.size() - check.unused_vertices;
  solid_to_mesh_data(solid, {}, result.mesh);
  result.stats.interior_steiner_points =
      result.mesh.point_count() - result.stats.input_vertices - result.stats.boundary_steiner_points;
  return result;
}

}  // namespace certimesh::generators
