// The 3D pipeline's driver (mesh_solid_3.h): runs the stages in order and times them.
#include "certimesh/generators/mesh_solid_3.h"

#include <chrono>

#include "certimesh/generators/delaunay/delaunay_3.h"

namespace certimesh::generators {

namespace {

class StageClock {
 public:
  explicit StageClock(MeshStats3& stats) : stats_(stats) {}
  void stop(std::string_view stage) {
    const auto now = std::chrono::steady_clock::now();
    stats_.stages.push_back({stage, std::chrono::duration<double>(now - start_).count()});
    start_ = now;
  }

 private:
  MeshStats3& stats_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

std::vector<Point3> points_of(const io::MeshData& m) {
  std::vector<Point3> p(m.point_count());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = {m.coordinates[3 * i], m.coordinates[3 * i + 1], m.coordinates[3 * i + 2]};
  return p;
}

io::MeshData to_mesh_data(const Tetrahedralization3& solid, const std::vector<io::Label>& input_point_labels) {
  io::MeshData mesh;
  mesh.dimension = 3;
  mesh.coordinates.reserve(3 * solid.points.size());
  for (const Point3& p : solid.points) mesh.coordinates.insert(mesh.coordinates.end(), {p.x, p.y, p.z});
  if (!input_point_labels.empty()) {  // Steiner points carry label 0
    mesh.point_labels = input_point_labels;
    mesh.point_labels.resize(solid.points.size(), 0);
  }
  mesh.tetrahedra.reserve(4 * solid.tetrahedra.size());
  for (const auto& t : solid.tetrahedra) mesh.tetrahedra.insert(mesh.tetrahedra.end(), t.begin(), t.end());
  mesh.tetrahedron_labels = solid.labels;
  mesh.tetrahedron_labels.resize(solid.tetrahedra.size(), 0);
  return mesh;
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
  StageClock clock(result.stats);
  Tetrahedralization3 solid;
  solid.points = points_of(points);
  result.stats.input_vertices = solid.points.size();
  solid.tetrahedra = Delaunay3(solid.points, progress).tetrahedra();
  clock.stop("delaunay");
  if (options.refine) {
    result.stats.refinement = refine_tetrahedra_3(solid, refinement_options(options), progress);
    clock.stop("refinement");
  }
  result.stats.interior_steiner_points = solid.points.size() - result.stats.input_vertices;
  result.mesh = to_mesh_data(solid, points.point_labels);
  return result;
}

}  // namespace certimesh::generators
