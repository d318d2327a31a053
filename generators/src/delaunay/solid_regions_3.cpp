// apply_holes_and_regions_3 (solid_regions_3.h): locate each point by exact orient3d, then fill
// its region across the faces that are not surface triangles.
#include "certimesh/generators/delaunay/solid_regions_3.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <string>
#include <unordered_map>
#include <unordered_set>
#include <vector>

#include "certimesh/generators/domain/surface_3.h"
#include "certimesh/predicates/orient3d.h"

namespace certimesh::generators {

namespace {

using predicates::Point3;
using Face = std::array<std::uint32_t, 3>;

struct FaceHash {
  std::size_t operator()(const Face& f) const noexcept {
    std::uint64_t h = 1469598103934665603ull;
    for (std::uint32_t v : f) h = (h ^ v) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

Face sorted(Face f) {
  std::sort(f.begin(), f.end());
  return f;
}

// Face i of a tetrahedron: the corners other than i.
Face face_of(const std::array<std::uint32_t, 4>& t, int i) {
  Face f;
  int k = 0;
  for (int j = 0; j < 4; ++j)
    if (j != i) f[static_cast<std::size_t>(k++)] = t[static_cast<std::size_t>(j)];
  return f;
}

class Regions {
 public:
  Regions(const Tetrahedralization3& solid, std::span<const Face> surface) : solid_(solid) {
    for (const Face& f : surface) surface_.insert(sorted(f));
    std::unordered_map<Face, std::uint32_t, FaceHash> open;
    neighbour_.assign(solid.tetrahedra.size(), {none, none, none, none});
    for (std::uint32_t t = 0; t < solid.tetrahedra.size(); ++t)
      for (int i = 0; i < 4; ++i) {
        const Face f = sorted(face_of(solid.tetrahedra[t], i));
        if (const auto it = open.find(f); it != open.end()) {
          const std::uint32_t u = it->second >> 2;
          neighbour_[t][static_cast<std::size_t>(i)] = u;
          neighbour_[u][it->second & 3] = t;
          open.erase(it);
        } else {
          open.emplace(f, t << 2 | static_cast<std::uint32_t>(i));
        }
      }
  }

  /// A tetrahedron whose closed set holds p, or none; throws when p lies on a closed surface
  /// triangle (on a surface vertex or edge too: every tetrahedron holding p is looked at, so
  /// the answer does not depend on which one is found first).
  std::uint32_t locate(const Point3& p, const std::string& what) const {
    std::uint32_t found = none;
    for (std::uint32_t t = 0; t < solid_.tetrahedra.size(); ++t) {
      if (!in_box(t, p)) continue;
      const auto& c = solid_.tetrahedra[t];
      bool inside = true, on_surface = false;
      for (int i = 0; i < 4 && inside; ++i) {
        const Face f = face_of(c, i);  // p must be on corner i's side of it, or on it
        const predicates::Sign to_corner = predicates::orient3d(point(f[0]), point(f[1]), point(f[2]), point(c[static_cast<std::size_t>(i)]));
        const predicates::Sign to_p = predicates::orient3d(point(f[0]), point(f[1]), point(f[2]), p);
        if (to_p == predicates::Sign::zero)
          on_surface = on_surface || surface_.count(sorted(f)) > 0;
        else if (to_p != to_corner)
          inside = false;
      }
      if (!inside) continue;
      if (on_surface)
        throw SolidRegionsError("error: " + what + " " + format_point(p) +
                                " lies on the surface (a triangle, edge or vertex of it): neither side is its region");
      if (found == none) found = t;
    }
    return found;
  }

  /// The tetrahedra of the region of t, in fill order.
  std::vector<std::uint32_t> region_of(std::uint32_t t) const {
    std::vector<char> seen(solid_.tetrahedra.size(), 0);
    std::vector<std::uint32_t> out{t};
    seen[t] = 1;
    for (std::size_t k = 0; k < out.size(); ++k) {
      const std::uint32_t u = out[k];
      for (int i = 0; i < 4; ++i) {
        const std::uint32_t n = neighbour_[u][static_cast<std::size_t>(i)];
        if (n == none || seen[n] || surface_.count(sorted(face_of(solid_.tetrahedra[u], i)))) continue;
        seen[n] = 1;
        out.push_back(n);
      }
    }
    return out;
  }

  static constexpr std::uint32_t none = UINT32_MAX;

 private:
  const Point3& point(std::uint32_t v) const { return solid_.points[v]; }
  bool in_box(std::uint32_t t, const Point3& p) const {
    const auto& c = solid_.tetrahedra[t];
    auto outside = [&](auto coordinate) {
      double lo = coordinate(point(c[0])), hi = lo;
      for (std::uint32_t v : c) lo = std::min(lo, coordinate(point(v))), hi = std::max(hi, coordinate(point(v)));
      return coordinate(p) < lo || coordinate(p) > hi;
    };
    return !outside([](const Point3& q) { return q.x; }) && !outside([](const Point3& q) { return q.y; }) &&
           !outside([](const Point3& q) { return q.z; });
  }

  const Tetrahedralization3& solid_;
  std::unordered_set<Face, FaceHash> surface_;
  std::vector<std::array<std::uint32_t, 4>> neighbour_;
};

}  // namespace

SolidRegionCounts apply_holes_and_regions_3(Tetrahedralization3& solid, std::span<const Face> surface,
                                            std::span<const Point3> holes, std::span<const Point3> region_points,
                                            std::span<const double> region_attributes) {
  SolidRegionCounts counts;
  if (holes.empty() && region_points.empty()) return counts;
  solid.labels.resize(solid.tetrahedra.size(), 0);
  std::vector<char> removed(solid.tetrahedra.size(), 0);
  {
    const Regions regions(solid, surface);
    for (std::size_t h = 0; h < holes.size(); ++h) {
      const std::string what = "hole point " + std::to_string(h);
      const std::uint32_t t = regions.locate(holes[h], what);
      if (t == Regions::none) throw SolidRegionsError("error: " + what + " " + format_point(holes[h]) + " is outside the solid: it makes no hole");
      if (removed[t]) continue;  // a second hole point in the same hole
      for (const std::uint32_t u : regions.region_of(t)) removed[u] = 1, ++counts.hole_tetrahedra;
    }
    for (std::size_t r = 0; r < region_points.size(); ++r) {
      const std::string what = "region point " + std::to_string(r);
      const double a = r < region_attributes.size() ? region_attributes[r] : 0.0;
      if (!(std::nearbyint(a) == a && std::fabs(a) <= 2147483647.0))
        throw SolidRegionsError("error: " + what + " has attribute " + std::to_string(a) + ", not an integer label");
      const std::uint32_t t = regions.locate(region_points[r], what);
      if (t == Regions::none || removed[t])
        throw SolidRegionsError("error: " + what + " " + format_point(region_points[r]) + " is outside the solid or in a hole");
      for (const std::uint32_t u : regions.region_of(t)) solid.labels[u] = static_cast<io::Label>(a), ++counts.labelled_tetrahedra;
    }
  }
  std::size_t kept = 0;
  for (std::size_t t = 0; t < solid.tetrahedra.size(); ++t)
    if (!removed[t]) solid.tetrahedra[kept] = solid.tetrahedra[t], solid.labels[kept] = solid.labels[t], ++kept;
  if (kept == 0) throw SolidRegionsError("error: the solid is empty: every region of it holds a hole point");
  solid.tetrahedra.resize(kept);
  solid.labels.resize(kept);
  return counts;
}

}  // namespace certimesh::generators
