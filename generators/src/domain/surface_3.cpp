// Surface3 from io::MeshData (surface_3.h): the triangles as given, TetGen facets cut exactly.
#include "certimesh/generators/domain/surface_3.h"

#include <cmath>
#include <string>

#include "certimesh/generators/domain/surface_problem_3.h"
#include "certimesh/io/mesh_file.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"

namespace certimesh::generators {

namespace {

using predicates::Point2;
using predicates::Point3;
using predicates::Sign;

[[noreturn]] void refuse(SurfaceProblemKind kind, std::string message, std::vector<std::uint32_t> triangles = {},
                         std::vector<std::uint32_t> vertices = {}) {
  throw InvalidSurface({SurfaceProblem{kind, std::move(triangles), std::move(vertices), std::move(message)}});
}

Point2 drop(const Point3& p, int axis) {
  if (axis == 0) return {p.y, p.z};
  if (axis == 1) return {p.z, p.x};
  return {p.x, p.y};
}

// The axis whose dropping keeps a, b, c non-collinear, or -1 when they are collinear (exact:
// three points are collinear in space iff all three coordinate projections are).
int projection_axis(const Point3& a, const Point3& b, const Point3& c) {
  for (int axis = 0; axis < 3; ++axis)
    if (predicates::orient2d(drop(a, axis), drop(b, axis), drop(c, axis)) != Sign::zero) return axis;
  return -1;
}

int sign_of_difference(double from, double to) { return (to > from) - (to < from); }

// One polygonal facet, weakly convex and planar, cut into triangles on its own corners by
// clipping strict corners (orientation kept: each triangle is (prev, corner, next)). O(k^2).
class ConvexFacetCutter {
 public:
  ConvexFacetCutter(const std::vector<Point3>& points, std::vector<std::uint32_t> corners, std::size_t facet)
      : points_(points), corners_(std::move(corners)), facet_(facet) {}

  std::vector<std::array<std::uint32_t, 3>> cut() {
    check_planar();
    check_convex();
    return clip();
  }

 private:
  [[noreturn]] void bad(const std::string& why) const {
    refuse(SurfaceProblemKind::bad_facet, "facet " + std::to_string(facet_) + " " + why);
  }
  const Point3& at(std::size_t i) const { return points_[corners_[i]]; }
  Point2 flat(std::size_t i) const { return drop(at(i), axis_); }
  std::size_t k() const { return corners_.size(); }

  void check_planar() {
    std::size_t third = 2;
    for (; third < k(); ++third) {
      axis_ = projection_axis(at(0), at(1), at(third));
      if (axis_ >= 0) break;
    }
    if (axis_ < 0) bad("has all its corners on one line");
    for (std::size_t i = 2; i < k(); ++i)
      if (predicates::orient3d(at(0), at(1), at(third), at(i)) != Sign::zero)
        bad("is not planar: corner " + std::to_string(corners_[i]) + " " + format_point(at(i)) + " is off the plane of its corners " +
            std::to_string(corners_[0]) + ", " + std::to_string(corners_[1]) + ", " + std::to_string(corners_[third]));
  }

  // The turn at corner i of the current polygon (prev, i, next): +1/-1, 0 straight; 2 a U-turn.
  int turn(std::size_t p, std::size_t i, std::size_t n) const {
    const Sign s = predicates::orient2d(flat(p), flat(i), flat(n));
    if (s != Sign::zero) return static_cast<int>(s);
    const Point2 a = flat(p), b = flat(i), c = flat(n);
    const bool straight = sign_of_difference(a.x, b.x) == sign_of_difference(b.x, c.x) && sign_of_difference(a.y, b.y) == sign_of_difference(b.y, c.y);
    return straight ? 0 : 2;
  }

  // Weakly convex and simple: every turn the same sign or straight, and the edge directions go
  // round once (the sign of dy changes exactly twice around the polygon).
  void check_convex() {
    int changes = 0, first = 0, last = 0;
    for (std::size_t i = 0; i < k(); ++i) {
      const int t = turn((i + k() - 1) % k(), i, (i + 1) % k());
      if (t == 2) bad("turns back on itself at corner " + std::to_string(corners_[i]) + " " + format_point(at(i)));
      if (t != 0 && orientation_ == 0) orientation_ = t;
      if (t != 0 && t != orientation_)
        bad("is not convex at corner " + std::to_string(corners_[i]) + " " + format_point(at(i)) +
            " (non-convex polygonal facets are not supported yet: split it into convex facets or triangles)");
      const int dy = sign_of_difference(flat(i).y, flat((i + 1) % k()).y);
      if (dy == 0) continue;
      if (first == 0) first = dy;
      if (last != 0 && dy != last) ++changes;
      last = dy;
    }
    if (last != first) ++changes;
    if (changes != 2) bad("winds round more than once (its edges cross)");
  }

  std::vector<std::array<std::uint32_t, 3>> clip() {
    std::vector<std::size_t> prev(k()), next(k());
    std::vector<char> strict(k());
    for (std::size_t i = 0; i < k(); ++i) prev[i] = (i + k() - 1) % k(), next[i] = (i + 1) % k();
    std::size_t strict_count = 0;
    for (std::size_t i = 0; i < k(); ++i) strict_count += strict[i] = turn(prev[i], i, next[i]) != 0;
    std::vector<std::array<std::uint32_t, 3>> out;
    std::size_t remaining = k(), v = 0;
    while (remaining > 3) {
      std::size_t tried = 0;
      for (;; v = next[v], ++tried) {
        if (tried > remaining) bad("cannot be cut into triangles");
        if (!strict[v]) continue;
        const std::size_t p = prev[v], n = next[v];
        const bool p_strict = turn(prev[p], p, n) != 0, n_strict = turn(p, n, next[n]) != 0;
        const std::size_t after = strict_count - 1 - strict[p] - strict[n] + p_strict + n_strict;
        if (after < 3) continue;  // the rest would be a flat chain: clip elsewhere
        out.push_back({corners_[p], corners_[v], corners_[n]});
        next[p] = n, prev[n] = p;
        strict[p] = p_strict, strict[n] = n_strict, strict_count = after;
        --remaining;
        v = n;
        break;
      }
    }
    out.push_back({corners_[prev[v]], corners_[v], corners_[next[v]]});
    return out;
  }

  const std::vector<Point3>& points_;
  std::vector<std::uint32_t> corners_;
  std::size_t facet_;
  int axis_ = -1;
  int orientation_ = 0;
};

void add_facets(const io::MeshData& data, Surface3& s) {
  const io::FacetList& f = data.facets;
  s.from_facets = true;
  for (std::size_t i = 0; i < f.facet_count(); ++i) {
    const std::uint64_t p = f.polygon_begin(i);
    const std::string name = "facet " + std::to_string(i);
    if (f.hole_end[i] != f.hole_begin(i)) refuse(SurfaceProblemKind::bad_facet, name + " has facet holes (not supported yet)");
    if (f.facet_end[i] != p + 1)
      refuse(SurfaceProblemKind::bad_facet, name + " has " + std::to_string(f.facet_end[i] - p) + " polygons (only one-polygon facets are supported yet)");
    std::vector<std::uint32_t> corners(f.corners.begin() + static_cast<std::ptrdiff_t>(f.corner_begin(p)), f.corners.begin() + static_cast<std::ptrdiff_t>(f.polygon_end[p]));
    for (const std::uint32_t c : corners)
      if (c >= s.points.size()) refuse(SurfaceProblemKind::vertex_index_out_of_range, name + " names vertex " + std::to_string(c) + ", which does not exist");
    if (corners.size() < 3) refuse(SurfaceProblemKind::bad_facet, name + " has " + std::to_string(corners.size()) + " corners (a facet needs 3 at least)");
    std::vector<std::array<std::uint32_t, 3>> cut;
    if (corners.size() == 3) {
      cut.push_back({corners[0], corners[1], corners[2]});  // a degenerate one is the validation's to name
    } else {
      cut = ConvexFacetCutter(s.points, std::move(corners), i).cut();
    }
    for (const auto& t : cut) {
      s.triangles.push_back(t);
      s.labels.push_back(f.labels.empty() ? 0 : f.labels[i]);
      s.facet_of.push_back(static_cast<std::uint32_t>(i));
    }
  }
}

std::vector<Point3> points_of(const std::vector<double>& xyz) {
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
  if (data.dimension != 3) refuse(SurfaceProblemKind::wrong_dimension, "the file is " + std::to_string(data.dimension) + "D: a surface has 3D points");
  Surface3 s;
  s.oriented = oriented;
  s.points = points_of(data.coordinates);
  for (const Point3& p : s.points)
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) refuse(SurfaceProblemKind::non_finite_coordinate, "a point is not finite");
  if (!data.facets.empty()) add_facets(data, s);
  for (std::size_t t = 0; t < data.triangle_count(); ++t) {
    std::array<std::uint32_t, 3> tri{data.triangles[3 * t], data.triangles[3 * t + 1], data.triangles[3 * t + 2]};
    for (const std::uint32_t v : tri)
      if (v >= s.points.size()) refuse(SurfaceProblemKind::vertex_index_out_of_range, "triangle " + std::to_string(t) + " names vertex " + std::to_string(v) + ", which does not exist");
    s.facet_of.push_back(static_cast<std::uint32_t>(s.triangles.size()));
    s.triangles.push_back(tri);
    s.labels.push_back(data.triangle_labels.empty() ? 0 : data.triangle_labels[t]);
  }
  if (s.triangles.empty()) refuse(SurfaceProblemKind::no_triangles, "the file has no triangles or facets: nothing bounds a solid");
  s.holes = points_of(data.holes);
  s.region_points = points_of(data.region_points);
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
