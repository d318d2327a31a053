#include "certimesh/io/svg_cut_3.h"

#include <algorithm>
#include <array>
#include <limits>
#include <map>

#include "certimesh/io/format_error.h"
#include "certimesh/io/mesh_file.h"

namespace certimesh::io {

namespace {

constexpr int kFace[4][3] = {{1, 3, 2}, {0, 2, 3}, {0, 3, 1}, {0, 1, 2}};

struct Cut {
  MeshData picture;  // 2D: the cut polygons as triangles, the boundary trace as segments
  std::vector<double> values;
};

Index add_point(MeshData& m, const double* a, const double* b, double z) {
  // The point of segment ab at height z (a below, b above), in double: a picture.
  const double t = (z - a[2]) / (b[2] - a[2]);
  m.coordinates.push_back(a[0] + t * (b[0] - a[0]));
  m.coordinates.push_back(a[1] + t * (b[1] - a[1]));
  return static_cast<Index>(m.point_count() - 1);
}

// The cut of one tetrahedron: 3 points (one corner on one side) or a quadrilateral (two and
// two), in cyclic order, added as triangles.
void cut_tetrahedron(const MeshData& mesh, const Index* corner, double z, double value, Cut& cut) {
  const double* p[4];
  int below[4], above[4], nb = 0, na = 0;
  for (int k = 0; k < 4; ++k) {
    p[k] = &mesh.coordinates[3 * static_cast<std::size_t>(corner[k])];
    (p[k][2] < z ? below[nb++] : above[na++]) = k;
  }
  if (nb == 0 || na == 0) return;
  std::vector<Index> polygon;
  if (nb == 1 || na == 1) {
    const bool lone_below = nb == 1;
    const int lone = lone_below ? below[0] : above[0];
    for (int k = 0; k < 3; ++k) {
      const int other = lone_below ? above[k] : below[k];
      polygon.push_back(lone_below ? add_point(cut.picture, p[lone], p[other], z) : add_point(cut.picture, p[other], p[lone], z));
    }
  } else {
    const int a = below[0], b = below[1], c = above[0], d = above[1];
    for (const auto& [u, v] : {std::pair{a, c}, std::pair{a, d}, std::pair{b, d}, std::pair{b, c}})
      polygon.push_back(add_point(cut.picture, p[u], p[v], z));
  }
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    cut.picture.triangles.insert(cut.picture.triangles.end(), {polygon[0], polygon[k], polygon[k + 1]});
    cut.values.push_back(value);
  }
}

// The boundary's trace: the cut of every face held by one tetrahedron, a segment.
void cut_boundary(const MeshData& mesh, double z, Cut& cut) {
  std::map<std::array<Index, 3>, int> count;
  for (std::size_t t = 0; t < mesh.tetrahedron_count(); ++t)
    for (const auto& f : kFace) {
      std::array<Index, 3> key{mesh.tetrahedra[4 * t + f[0]], mesh.tetrahedra[4 * t + f[1]], mesh.tetrahedra[4 * t + f[2]]};
      std::sort(key.begin(), key.end());
      ++count[key];
    }
  for (const auto& [face, n] : count) {
    if (n != 1) continue;
    const double* q[3];
    for (int k = 0; k < 3; ++k) q[k] = &mesh.coordinates[3 * static_cast<std::size_t>(face[static_cast<std::size_t>(k)])];
    std::vector<Index> ends;
    for (int k = 0; k < 3; ++k) {
      const double *u = q[k], *v = q[(k + 1) % 3];
      if ((u[2] < z) != (v[2] < z)) ends.push_back(u[2] < z ? add_point(cut.picture, u, v, z) : add_point(cut.picture, v, u, z));
    }
    if (ends.size() == 2) cut.picture.segments.insert(cut.picture.segments.end(), {ends[0], ends[1]});
  }
}

}  // namespace

double middle_z(const MeshData& mesh) {
  double low = std::numeric_limits<double>::infinity(), high = -low;
  for (std::size_t i = 2; i < mesh.coordinates.size(); i += 3) {
    low = std::min(low, mesh.coordinates[i]);
    high = std::max(high, mesh.coordinates[i]);
  }
  return mesh.coordinates.empty() ? 0.0 : low / 2 + high / 2;
}

std::string svg_cut_picture(const MeshData& mesh, double z, const std::vector<double>& values, const SvgOptions& options) {
  if (mesh.dimension != 3) throw FormatError("svg", 0, "a cut picture needs a 3D mesh");
  if (values.size() != mesh.tetrahedron_count())
    throw FormatError("svg", 0, "a cut picture needs one value per tetrahedron");
  for (const Index v : mesh.tetrahedra)
    if (v >= mesh.point_count()) throw FormatError("svg", 0, "a tetrahedron names vertex " + std::to_string(v) + ", out of range");
  Cut cut;
  cut.picture.dimension = 2;
  for (std::size_t t = 0; t < mesh.tetrahedron_count(); ++t) cut_tetrahedron(mesh, &mesh.tetrahedra[4 * t], z, values[t], cut);
  cut_boundary(mesh, z, cut);
  SvgOptions o = options;
  o.fill_values = &cut.values;
  return svg_picture(cut.picture, o);
}

void write_svg_cut_picture(const MeshData& mesh, double z, const std::vector<double>& values,
                           const std::filesystem::path& path, const SvgOptions& options) {
  write_file_atomically(path, svg_cut_picture(mesh, z, values, options));
}

}  // namespace certimesh::io
