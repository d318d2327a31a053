#include "certimesh/generators/delaunay/tetrahedral_refinement_3.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "refinement_mesh_3.h"

namespace certimesh::generators {

namespace {

using detail::RefinementMesh3;
using Insertion = RefinementMesh3::Insertion;

constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The insertion budget never exceeds this (about 0.8 billion tetrahedra, 27 GB).
constexpr std::uint64_t kBudgetCap = std::uint64_t{1} << 27;

Point3 minus(const Point3& a, const Point3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Point3 cross(const Point3& a, const Point3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
double dot3(const Point3& a, const Point3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
double length(const Point3& a) { return std::sqrt(dot3(a, a)); }

// What refinement needs of one tetrahedron, in double (sizes decide nothing exact).
struct Shape {
  double shortest = kInfinity, longest = 0.0;
  Point3 circumcentre{};
  double circumradius = kInfinity;  // infinite for a (numerically) flat tetrahedron
  Point3 centroid{};
};

Shape shape_of(const RefinementMesh3& mesh, std::uint32_t t) {
  const std::uint32_t* c = mesh.corners(t);
  const Point3* p[4] = {&mesh.point(c[0]), &mesh.point(c[1]), &mesh.point(c[2]), &mesh.point(c[3])};
  Shape s;
  double shortest = kInfinity, longest = 0.0;  // squared
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j) {
      const Point3 e = minus(*p[i], *p[j]);
      const double l = dot3(e, e);
      shortest = std::min(shortest, l);
      longest = std::max(longest, l);
    }
  s.shortest = std::sqrt(shortest);
  s.longest = std::sqrt(longest);
  s.centroid = {(p[0]->x + p[1]->x + p[2]->x + p[3]->x) / 4, (p[0]->y + p[1]->y + p[2]->y + p[3]->y) / 4,
                (p[0]->z + p[1]->z + p[2]->z + p[3]->z) / 4};
  const Point3 u = minus(*p[1], *p[0]), v = minus(*p[2], *p[0]), w = minus(*p[3], *p[0]);
  const Point3 vw = cross(v, w), wu = cross(w, u), uv = cross(u, v);
  const double den = 2.0 * dot3(u, vw);
  if (den != 0.0) {
    const double uu = dot3(u, u), vv = dot3(v, v), ww = dot3(w, w);
    const Point3 r{(uu * vw.x + vv * wu.x + ww * uv.x) / den, (uu * vw.y + vv * wu.y + ww * uv.y) / den,
                   (uu * vw.z + vv * wu.z + ww * uv.z) / den};
    const double radius = length(r);
    if (std::isfinite(radius)) {
      s.circumradius = radius;
      s.circumcentre = {p[0]->x + r.x, p[0]->y + r.y, p[0]->z + r.z};
    }
  }
  return s;
}

double volume(const RefinementMesh3& mesh, std::uint32_t t) {
  const std::uint32_t* c = mesh.corners(t);
  const Point3 u = minus(mesh.point(c[1]), mesh.point(c[0])), v = minus(mesh.point(c[2]), mesh.point(c[0])),
               w = minus(mesh.point(c[3]), mesh.point(c[0]));
  return std::abs(dot3(u, cross(v, w))) / 6.0;
}

class Refinement {
 public:
  Refinement(Tetrahedralization3& mesh, const TetrahedralRefinementOptions& options)
      : input_(mesh), options_(options), mesh_(mesh) {
    initial_sizes();
  }

  TetrahedralRefinementStats run(const ProgressCallback& progress) {
    stats_.insertion_bound = options_.max_insertions ? options_.max_insertions : budget();
    for (std::uint32_t t = 0; t < mesh_.slot_count(); ++t) queue_.push_back(t);
    for (std::size_t head = 0; head < queue_.size(); ++head) {
      const std::uint32_t t = queue_[head];
      if (!mesh_.is_live(t)) continue;
      if (stats_.inserted >= stats_.insertion_bound) {
        stats_.bound_reached = true;
        break;
      }
      refine(t);
      if ((stats_.inserted & 0x3fff) == 0 && stats_.inserted) report(progress, "refinement", stats_.inserted, 0);
    }
    count_skinny_left();
    mesh_.export_to(input_);
    return stats_;
  }

 private:
  bool sized() const { return options_.size_function || options_.uniform_size > 0.0 || has_boundary_sizes_; }

  // The size a tetrahedron is held to: the size function at its centroid, or else
  // min over its corners u of h_u + grading * |x - u| at the centroid x, capped by --size.
  // Where the boundary triangles are larger than that, the tetrahedra on them stay larger:
  // their faces are kept, and points in their diametral balls are refused.
  double size_of(const Point3& x, std::uint32_t t) const {
    if (options_.size_function) return options_.size_function(x);
    double h = options_.uniform_size > 0.0 ? options_.uniform_size : kInfinity;
    const std::uint32_t* c = mesh_.corners(t);
    for (int k = 0; k < 4; ++k) h = std::min(h, size_[c[k]] + options_.grading * length(minus(x, mesh_.point(c[k]))));
    return h;
  }

  // Input vertices: the mean length of their boundary edges (the faces of one tetrahedron).
  // Each edge of boundary face i of t, its length added to both ends (every boundary edge is
  // met twice, from its two faces: the mean is unchanged).
  void add_boundary_edges(std::uint32_t t, int i, std::vector<double>& sum, std::vector<std::uint32_t>& count) const {
    const std::uint32_t* c = mesh_.corners(t);
    std::uint32_t f[3];
    for (int k = 0, m = 0; k < 4; ++k)
      if (k != i) f[m++] = c[k];
    for (int a = 0; a < 3; ++a) {
      const std::uint32_t u = f[a], v = f[(a + 1) % 3];
      const double l = length(minus(mesh_.point(u), mesh_.point(v)));
      sum[u] += l, sum[v] += l;
      ++count[u], ++count[v];
    }
  }

  void initial_sizes() {
    const std::size_t n = mesh_.vertex_count();
    if (n == 0) return;
    low_ = high_ = mesh_.point(0);
    for (std::uint32_t v = 1; v < n; ++v) {
      const Point3& p = mesh_.point(v);
      low_ = {std::min(low_.x, p.x), std::min(low_.y, p.y), std::min(low_.z, p.z)};
      high_ = {std::max(high_.x, p.x), std::max(high_.y, p.y), std::max(high_.z, p.z)};
    }
    std::vector<double> sum(n, 0.0);
    std::vector<std::uint32_t> count(n, 0);
    for (std::uint32_t t = 0; t < mesh_.slot_count(); ++t) {
      const Shape s = shape_of(mesh_, t);
      shortest_input_edge_ = std::min(shortest_input_edge_, s.shortest);
      total_volume_ += volume(mesh_, t);
    }
    for (std::uint32_t t = 0; t < mesh_.slot_count(); ++t)
      for (int i = 0; i < 4; ++i)
        if (mesh_.is_boundary(t, i)) add_boundary_edges(t, i, sum, count);
    const double fallback = options_.uniform_size > 0.0 ? options_.uniform_size : kInfinity;
    size_.assign(n, fallback);
    for (std::size_t v = 0; v < n; ++v)
      if (count[v]) {
        size_[v] = std::min(fallback, sum[v] / count[v]);
        has_boundary_sizes_ = true;
        smallest_size_ = std::min(smallest_size_, size_[v]);
      }
    if (options_.uniform_size > 0.0) smallest_size_ = std::min(smallest_size_, options_.uniform_size);
  }

  // A packing bound: points at least `l` apart, each owning a ball of radius l/2 that
  // meets the solid in at least a fraction of it, number at most about V / l^3 (with a
  // generous constant), plus the vertices near the boundary.
  std::uint64_t budget() const {
    double l = shortest_input_edge_;
    if (sized() && std::isfinite(smallest_size_)) l = std::min(l, smallest_size_ / 8.0);
    if (!(l > 0.0) || !std::isfinite(l)) return 1000;
    const double points = 64.0 * total_volume_ / (l * l * l) + 16.0 * static_cast<double>(mesh_.vertex_count()) + 1000.0;
    return points >= static_cast<double>(kBudgetCap) ? kBudgetCap : static_cast<std::uint64_t>(points);
  }

  void refine(std::uint32_t t) {
    const Shape s = shape_of(mesh_, t);
    const double h = sized() ? size_of(s.centroid, t) : kInfinity;
    const bool big = s.longest > h;
    const bool skinny = options_.max_radius_edge > 0.0 && s.circumradius > options_.max_radius_edge * s.shortest;
    if (!big && !skinny) return;
    // No point goes into the diametral ball of a boundary face: it could only make a flat
    // tetrahedron on a face that is never split. So a boundary coarser than the size keeps
    // the tetrahedra next to it as large as its triangles, as `tetgen -Y` does.
    const double clearance = big ? 0.25 * h : s.shortest;
    if (s.circumradius < kInfinity && insert(s.circumcentre, t, clearance, 1.0)) {
      ++stats_.circumcentres;
      return;
    }
    if (big && insert(s.centroid, t, 0.125 * h, 1.0)) ++stats_.centroids;
  }

  bool insert(const Point3& p, std::uint32_t t, double clearance, double ball) {
    if (!(p.x >= low_.x && p.y >= low_.y && p.z >= low_.z && p.x <= high_.x && p.y <= high_.y && p.z <= high_.z)) {
      ++stats_.refused_outside;  // outside the input's box: outside the solid, no walk needed
      return false;
    }
    switch (mesh_.insert(p, t, clearance, ball)) {
      case Insertion::inserted: break;
      case Insertion::behind_constraint:
      case Insertion::walk_too_long: ++stats_.refused_outside; return false;
      case Insertion::too_close: ++stats_.refused_close; return false;
      default: ++stats_.refused_other; return false;
    }
    ++stats_.inserted;
    double h = options_.uniform_size > 0.0 ? options_.uniform_size : kInfinity;
    if (!options_.size_function)
      for (std::uint32_t u : mesh_.link()) h = std::min(h, size_[u] + options_.grading * length(minus(p, mesh_.point(u))));
    size_.push_back(h);
    for (std::uint32_t n : mesh_.created()) queue_.push_back(n);
    return true;
  }

  void count_skinny_left() {
    if (!(options_.max_radius_edge > 0.0)) return;
    for (std::uint32_t t = 0; t < mesh_.slot_count(); ++t) {
      if (!mesh_.is_live(t)) continue;
      const Shape s = shape_of(mesh_, t);
      if (s.circumradius > options_.max_radius_edge * s.shortest) ++stats_.skinny_left;
    }
  }

  Tetrahedralization3& input_;
  const TetrahedralRefinementOptions& options_;
  RefinementMesh3 mesh_;
  std::vector<double> size_;
  std::vector<std::uint32_t> queue_;
  TetrahedralRefinementStats stats_;
  bool has_boundary_sizes_ = false;
  double smallest_size_ = kInfinity;
  double shortest_input_edge_ = kInfinity;
  double total_volume_ = 0.0;
  Point3 low_{}, high_{};  // the input's bounding box
};

}  // namespace

TetrahedralRefinementStats refine_tetrahedra_3(Tetrahedralization3& mesh, const TetrahedralRefinementOptions& options,
                                               const ProgressCallback& progress) {
  Refinement refinement(mesh, options);
  return refinement.run(progress);
}

}  // namespace certimesh::generators
