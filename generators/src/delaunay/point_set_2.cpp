// A point set's Delaunay triangulation as a mesh (point_set_2.h).
#include "certimesh/generators/delaunay/point_set_2.h"

#include <vector>

#include "certimesh/generators/delaunay/constrained_delaunay_2.h"

namespace certimesh::generators {

io::MeshData delaunay_of_points(const io::MeshData& points) {
  std::vector<Point2> p(points.point_count());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = {points.coordinates[2 * i], points.coordinates[2 * i + 1]};
  const ConstrainedDelaunay2 dt(p);
  io::MeshData mesh;
  mesh.dimension = 2;
  mesh.coordinates = points.coordinates;
  mesh.point_labels = points.point_labels;
  for (const auto& t : dt.triangles())
    for (auto v : t) mesh.triangles.push_back(v);
  if (mesh.triangles.empty())
    throw DelaunayError(p.size() < 3 ? "fewer than three points: no triangle"
                                     : "all " + std::to_string(p.size()) + " points lie on one line: their convex hull has no area");
  mesh.triangle_labels.assign(mesh.triangle_count(), 0);
  return mesh;
}

}  // namespace certimesh::generators
