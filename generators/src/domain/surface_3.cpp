// Surface3 from io::MeshData (surface_3.h): the triangles as given, TetGen facets cut exactly.
#include "certimesh/generators/domain/surface_3.h"

#include <cmath>
#include <string>
#include <tuple>

#include "certimesh/generators/domain/surface_problem_3.h"
#include "certimesh/io/mesh_file.h"
#include "certimesh/predicates/intersection/segment_segment_2d.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"

namespace certimesh::generators {

namespace {

using predicates::Point2;
using predicates::Point3;
using predicates::Sign;

[[noreturn]] void refuse_surface(SurfaceProblemKind kind, std::string message, std::vector<std::uint32_t> triangles = {},
                         std::vector<std::uint32_t> vertices = {}) {
  throw InvalidSurface({SurfaceProblem{kind, std::move(triangles), std::move(vertices), std::move(message)}});
}

Point2 drop_coordinate(const Point3& p, int axis) {
  if (axis == 0) return {p.y, p.z};
  if (axis == 1) return {p.z, p.x};
  return {p.x, p.y};
}

// The axis whose dropping keeps a, b, c non-collinear, or -1 when they are collinear (exact:
// three points are collinear in space iff all three coordinate projections are).
int projection_axis(const Point3& a, const Point3& b, const Point3& c) {
  for (int axis = 0; axis < 3; ++axis)
    if (predicates::orient2d(drop_coordinate(a, axis), drop_coordinate(b, axis), drop_coordinate(c, axis)) != Sign::zero) return axis;
  return -1;
}

// One polygonal facet, planar and simple (collinear corners allowed), cut into triangles on its
// own corners by ear clipping: a corner is an ear when it turns as the polygon does and no other
// corner lies in the closed triangle of it and its neighbours. Each triangle is (prev, ear,
// next): the polygon's orientation is kept. O(k^2): the simplicity test (every pair of edges,
// exact) and the ears (each clipping re-tests its two neighbours against every corner).
class PolygonFacetCutter {
 public:
  PolygonFacetCutter(const std::vector<Point3>& points, std::vector<std::uint32_t> corners, std::size_t facet)
      : points_(points), corners_(std::move(corners)), facet_(facet) {}

  std::vector<std::array<std::uint32_t, 3>> cut() {
    check_planar();
    for (std::size_t i = 0; i < k(); ++i) flat_.push_back(drop_coordinate(at(i), axis_));
    check_simple();
    return clip();
  }

 private:
  [[noreturn]] void bad(const std::string& why) const {
    refuse_surface(SurfaceProblemKind::bad_facet, "facet " + std::to_string(facet_) + " " + why);
  }
  const Point3& at(std::size_t i) const { return points_[corners_[i]]; }
  std::size_t k() const { return corners_.size(); }
  std::string corner_text(std::size_t i) const { return std::to_string(corners_[i]) + " " + format_point(at(i)); }
  int orient(std::size_t a, std::size_t b, std::size_t c) const { return static_cast<int>(predicates::orient2d(flat_[a], flat_[b], flat_[c])); }

  void check_planar() {
    std::size_t third = 2;
    for (; third < k(); ++third) {
      axis_ = projection_axis(at(0), at(1), at(third));
      if (axis_ >= 0) break;
    }
    if (axis_ < 0) bad("has all its corners on one line");
    for (std::size_t i = 2; i < k(); ++i)
      if (predicates::orient3d(at(0), at(1), at(third), at(i)) != Sign::zero)
        bad("is not planar: corner " + corner_text(i) + " is off the plane of its corners " + std::to_string(corners_[0]) + ", " +
            std::to_string(corners_[1]) + ", " + std::to_string(corners_[third]));
  }

  // No two edges meet beyond the corner they share (exact; in the projection, which is
  // one-to-one on the facet's plane); then the turn at the lowest corner is the orientation.
  void check_simple() {
    auto edge = [&](std::size_t i) {
      const std::size_t j = (i + 1) % k();
      return std::array<predicates::Vertex2, 2>{predicates::Vertex2{flat_[i], corners_[i]}, predicates::Vertex2{flat_[j], corners_[j]}};
    };
    for (std::size_t i = 0; i < k(); ++i)
      for (std::size_t j = i + 1; j < k(); ++j)
        if (predicates::segment_segment_2d(edge(i), edge(j), predicates::IntersectionMode::exact) == predicates::Overlap::intersect)
          bad("is not a simple polygon: its edges from corners " + corner_text(i) + " and " + corner_text(j) + " meet");
    std::size_t lowest = 0;
    for (std::size_t i = 1; i < k(); ++i)
      if (std::tie(flat_[i].x, flat_[i].y) < std::tie(flat_[lowest].x, flat_[lowest].y)) lowest = i;
    orientation_ = orient((lowest + k() - 1) % k(), lowest, (lowest + 1) % k());
    if (orientation_ == 0) bad("cannot be oriented");  // impossible for a simple polygon
  }

  bool is_ear(std::size_t v) const {
    const std::size_t p = prev_[v], n = next_[v];
    if (orient(p, v, n) != orientation_) return false;
    for (std::size_t x = next_[n]; x != p; x = next_[x])
      if (orient(p, v, x) * orientation_ >= 0 && orient(v, n, x) * orientation_ >= 0 && orient(n, p, x) * orientation_ >= 0) return false;
    return true;
  }

  std::vector<std::array<std::uint32_t, 3>> clip() {
    prev_.resize(k()), next_.resize(k());
    for (std::size_t i = 0; i < k(); ++i) prev_[i] = (i + k() - 1) % k(), next_[i] = (i + 1) % k();
    std::vector<char> ear(k());
    for (std::size_t i = 0; i < k(); ++i) ear[i] = is_ear(i);
    std::vector<std::array<std::uint32_t, 3>> out;
    std::size_t v = 0;
    for (std::size_t remaining = k(); remaining > 3; --remaining) {
      std::size_t tried = 0;
      while (!ear[v]) {
        v = next_[v];
        if (++tried > remaining) bad("cannot be cut into triangles on its corners");
      }
      const std::size_t p = prev_[v], n = next_[v];
      out.push_back({corners_[p], corners_[v], corners_[n]});
      next_[p] = n, prev_[n] = p;
      ear[p] = is_ear(p), ear[n] = is_ear(n);
      v = n;
    }
    out.push_back({corners_[prev_[v]], corners_[v], corners_[next_[v]]});
    return out;
  }

  const std::vector<Point3>& points_;
  std::vector<std::uint32_t> corners_;
  std::size_t facet_;
  int axis_ = -1;
  int orientation_ = 0;
  std::vector<Point2> flat_;
  std::vector<std::size_t> prev_, next_;
};

void add_facets(const io::MeshData& data, Surface3& s) {
  const io::FacetList& f = data.facets;
  s.from_facets = true;
  for (std::size_t i = 0; i < f.facet_count(); ++i) {
    const std::uint64_t p = f.polygon_begin(i);
    const std::string name = "facet " + std::to_string(i);
    if (f.hole_end[i] != f.hole_begin(i)) refuse_surface(SurfaceProblemKind::bad_facet, name + " has facet holes (not supported yet)");
    if (f.facet_end[i] != p + 1)
      refuse_surface(SurfaceProblemKind::bad_facet, name + " has " + std::to_string(f.facet_end[i] - p) + " polygons (only one-polygon facets are supported yet)");
    std::vector<std::uint32_t> corners(f.corners.begin() + static_cast<std::ptrdiff_t>(f.corner_begin(p)), f.corners.begin() + static_cast<std::ptrdiff_t>(f.polygon_end[p]));
    for (const std::uint32_t c : corners)
      if (c >= s.points.size()) refuse_surface(SurfaceProblemKind::vertex_index_out_of_range, name + " names vertex " + std::to_string(c) + ", which does not exist");
    if (corners.size() < 3) refuse_surface(SurfaceProblemKind::bad_facet, name + " has " + std::to_string(corners.size()) + " corners (a facet needs 3 at least)");
    std::vector<std::array<std::uint32_t, 3>> cut;
    if (corners.size() == 3) {
      cut.push_back({corners[0], corners[1], corners[2]});  // a degenerate one is the validation's to name
    } else {
      cut = PolygonFacetCutter(s.points, std::move(corners), i).cut();
    }
    for (const auto& t : cut) {
      s.triangles.push_back(t);
      s.labels.push_back(f.labels.empty() ? 0 : f.labels[i]);
      s.facet_of.push_back(static_cast<std::uint32_t>(i));
    }
  }
}

std::vector<Point3> points_of_xyz(const std::vector<double>& xyz) {
  std::vector<Point3> out(xyz.size() / 3);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
  return out;
}

}  // namespace

std::string format_point(const Point3& p) {
  std::string out = "(";
  io::append_double(out, p.x);
  out += ' ';
  io::append_double(out, p.y);
  out += ' ';
  io::append_double(out, p.z);
  return out + ")";
}

std::string describe_triangle(const Surface3& s, std::uint32_t t) {
  std::string out = "triangle " + std::to_string(t);
  if (s.from_facets && t < s.facet_of.size()) out += " of facet " + std::to_string(s.facet_of[t]);
  out += ' ';
  const auto& tri = s.triangles[t];
  for (int k = 0; k < 3; ++k) {
    if (k > 0) out += '-';
    out += tri[std::size_t(k)] < s.points.size() ? format_point(s.points[tri[std::size_t(k)]]) : "(?)";
  }
  return out;
}

Surface3 surface_from_mesh_data(const io::MeshData& data, bool oriented) {
  if (data.dimension != 3) refuse_surface(SurfaceProblemKind::wrong_dimension, "the file is " + std::to_string(data.dimension) + "D: a surface has 3D points");
  Surface3 s;
  s.oriented = oriented;
  s.points = points_of_xyz(data.coordinates);
  for (const Point3& p : s.points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) refuse_surface(SurfaceProblemKind::non_finite_coordinate, "a point is not finite");
  if (!data.facets.empty()) add_facets(data, s);
  for (std::size_t t = 0; t < data.triangle_count(); ++t) {
    std::array<std::uint32_t, 3> tri{data.triangles[3 * t], data.triangles[3 * t + 1], data.triangles[3 * t + 2]};
    for (const std::uint32_t v : tri)
      if (v >= s.points.size()) refuse_surface(SurfaceProblemKind::vertex_index_out_of_range, "triangle " + std::to_string(t) + " names vertex " + std::to_string(v) + ", which does not exist");
    s.facet_of.push_back(static_cast<std::uint32_t>(s.triangles.size()));
    s.triangles.push_back(tri);
    s.labels.push_back(data.triangle_labels.empty() ? 0 : data.triangle_labels[t]);
  }
  if (s.triangles.empty()) refuse_surface(SurfaceProblemKind::no_triangles, "the file has no triangles or facets: nothing bounds a solid");
  s.holes = points_of_xyz(data.holes);
  s.region_points = points_of_xyz(data.region_points);
  s.region_attributes = data.region_attributes;
  s.region_max_volumes = data.region_max_measures;
  return s;
}

Surface3 read_surface_3(const std::filesystem::path& path) {
  const io::MeshData data = io::read_mesh(path);
  const std::string ext = path.extension().string();
  return surface_from_mesh_data(data, !(ext == ".poly" || ext == ".smesh"));
}

}  // namespace certimesh::generators
