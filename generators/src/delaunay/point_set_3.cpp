// A point set's Delaunay tetrahedralization as a mesh (point_set_3.h).
#include "certimesh/generators/delaunay/point_set_3.h"

#include <vector>

#include "certimesh/generators/delaunay/delaunay_3.h"

namespace certimesh::generators {

io::MeshData delaunay_of_points_3(const io::MeshData& points, const ProgressCallback& progress) {
  std::vector<Point3> p(points.point_count());
  for (std::size_t i = 0; i < p.size(); ++i)
    p[i] = {points.coordinates[3 * i], points.coordinates[3 * i + 1], points.coordinates[3 * i + 2]};
  const Delaunay3 dt(p, progress);
  io::MeshData mesh;
  mesh.dimension = 3;
  mesh.coordinates = points.coordinates;
  mesh.point_labels = points.point_labels;
  mesh.tetrahedra.reserve(4 * dt.tetrahedron_count());
  for (const auto& t : dt.tetrahedra())
    for (auto v : t) mesh.tetrahedra.push_back(v);
  mesh.tetrahedron_labels.assign(mesh.tetrahedron_count(), 0);
  return mesh;
}

}  // namespace certimesh::generators
