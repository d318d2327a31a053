// The 3D local modifications (local_modifications_3.h): 2-3 flip, edge removal, node shift.
#include "certimesh/topology/local_modifications_3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "certimesh/predicates/volume_sign.h"
#include "certimesh/topology/star_walk.h"

namespace certimesh::topology {

namespace {

using Element = TetrahedralMesh3::Element;

bool positive(const Point3d& a, const Point3d& b, const Point3d& c, const Point3d& d) {
  const auto p = [](const Point3d& q) { return predicates::Point3{q[0], q[1], q[2]}; };
  return predicates::volume_sign(p(a), p(b), p(c), p(d)) == predicates::Sign::positive;
}

// The quality of the tetrahedron, or -1 when it is not strictly positive (exact).
double valid_quality(const TetrahedralMesh3& mesh, const Element& t) {
  const Point3d a = mesh.point(t[0]), b = mesh.point(t[1]), c = mesh.point(t[2]), d = mesh.point(t[3]);
  if (!positive(a, b, c, d)) return -1.0;
  return tetrahedron_quality(a, b, c, d);
}

int local_index(const Element& t, VertexId v) {
  for (int i = 0; i < 4; ++i)
    if (t[static_cast<std::size_t>(i)] == v) return i;
  return -1;
}

LocalChange3 replace(TetrahedralMesh3& mesh, const std::vector<ElementId>& old, const std::vector<Element>& fresh,
                     Label label) {
  LocalChange3 change;
  change.removed = old;
  for (const ElementId e : old) mesh.remove_element(e);
  for (const Element& t : fresh) change.added.push_back(mesh.add_element(t, label));
  return change;
}

}  // namespace

bool is_constrained_facet(const TetrahedralMesh3& mesh, ElementId e, int i) {
  const ElementId n = mesh.neighbour(e, i);
  return n == no_element || mesh.label(n) != mesh.label(e) || mesh.facet_label(mesh.facet(e, i)) != 0;
}

bool is_fixed_vertex(const TetrahedralMesh3& mesh, VertexId v, const std::vector<ElementId>& star,
                     const LocalModificationOptions3& options) {
  if (v.value < options.first_movable_vertex || star.empty()) return true;
  if (!options.fixed_vertices.empty()) return v.value >= options.fixed_vertices.size() || options.fixed_vertices[v.value];
  if (star.size() != mesh.incident_element_count(v)) return true;  // a pinched star
  for (const ElementId e : star) {
    const int own = local_index(mesh.vertices(e), v);
    for (int i = 0; i < 4; ++i)
      if (i != own && is_constrained_facet(mesh, e, i)) return true;
  }
  return false;
}

double worst_quality(const TetrahedralMesh3& mesh, const std::vector<ElementId>& elements) {
  double worst = std::numeric_limits<double>::infinity();
  for (const ElementId e : elements) worst = std::min(worst, element_quality(mesh, e));
  return worst;
}

std::optional<LocalChange3> try_flip_2_3(TetrahedralMesh3& mesh, ElementId element, int facet) {
  if (is_constrained_facet(mesh, element, facet)) return std::nullopt;
  const ElementId other = mesh.neighbour(element, facet);
  const Element t = mesh.vertices(element);
  const VertexId q = mesh.vertices(other)[static_cast<std::size_t>(mesh.mirror_facet(element, facet))];
  // Chains: t + other = the three tetrahedra of t with one corner of the shared facet replaced
  // by q (the cone identity), so if all three are positive they tile the same region.
  std::vector<Element> fresh;
  double q1 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 4; ++i) {
    if (i == facet) continue;
    Element s = t;
    s[static_cast<std::size_t>(i)] = q;
    const double quality = valid_quality(mesh, s);
    if (quality < 0) return std::nullopt;
    q1 = std::min(q1, quality);
    fresh.push_back(s);
  }
  const std::vector<ElementId> old{element, other};
  if (!(q1 > worst_quality(mesh, old))) return std::nullopt;
  return replace(mesh, old, fresh, mesh.label(element));
}

std::optional<LocalChange3> try_edge_removal(TetrahedralMesh3& mesh, ElementId element, int a, int b,
                                             const LocalModificationOptions3& options) {
  const Element t0 = mesh.vertices(element);
  const VertexId x = t0[static_cast<std::size_t>(a)], y = t0[static_cast<std::size_t>(b)];
  std::array<VertexId, 2> other{};
  int k = 0;
  for (int i = 0; i < 4; ++i)
    if (i != a && i != b) other[static_cast<std::size_t>(k++)] = t0[static_cast<std::size_t>(i)];
  if (!positive(mesh.point(x), mesh.point(y), mesh.point(other[0]), mesh.point(other[1])))
    std::swap(other[0], other[1]);
  // The ring: (x, y, ring[i], ring[i + 1]) positive; the next tetrahedron is across the facet
  // (x, y, ring[i + 1]), opposite ring[i].
  std::vector<VertexId> ring{other[0], other[1]};
  std::vector<ElementId> old{element};
  ElementId current = element;
  for (;;) {
    const Element t = mesh.vertices(current);
    const int opposite = local_index(t, ring[ring.size() - 2]);
    if (is_constrained_facet(mesh, current, opposite)) return std::nullopt;
    const ElementId next = mesh.neighbour(current, opposite);
    if (next == element) break;
    if (old.size() >= options.max_ring) return std::nullopt;
    VertexId far = no_vertex;
    for (const VertexId v : mesh.vertices(next))
      if (v != x && v != y && v != ring.back()) far = v;
    ring.push_back(far);
    old.push_back(next);
    current = next;
  }
  ring.pop_back();  // the walk closed: the last vertex is ring[0] again
  const std::size_t n = ring.size();
  if (n != old.size() || n < 3) return std::nullopt;

  // Triangle (i, j, k), i < j < k: tetrahedra (r_i, r_j, r_k, y) and (r_j, r_i, r_k, x).
  const auto index = [n](std::size_t i, std::size_t j, std::size_t c) { return (i * n + j) * n + c; };
  std::vector<double> triangle(n * n * n, -2.0);  // -2: not computed yet
  const auto triangle_quality = [&](std::size_t i, std::size_t j, std::size_t c) {
    double& q = triangle[index(i, j, c)];
    if (q == -2.0) {
      const double up = valid_quality(mesh, {ring[i], ring[j], ring[c], y});
      const double down = up < 0 ? -1.0 : valid_quality(mesh, {ring[j], ring[i], ring[c], x});
      q = up < 0 || down < 0 ? -1.0 : std::min(up, down);
    }
    return q;
  };
  // best[i][k]: the best worst quality over triangulations of the sub-polygon r_i .. r_k.
  constexpr double infinity = std::numeric_limits<double>::infinity();
  std::vector<double> best(n * n, infinity);
  std::vector<std::size_t> split(n * n, 0);
  for (std::size_t length = 2; length < n; ++length)
    for (std::size_t i = 0; i + length < n; ++i) {
      const std::size_t kk = i + length;
      double value = -1.0;
      for (std::size_t j = i + 1; j < kk; ++j) {
        const double left = best[i * n + j], right = best[j * n + kk];
        if (left < 0 || right < 0 || std::min(left, right) <= value) continue;
        const double here = std::min({left, right, triangle_quality(i, j, kk)});
        if (here > value) {
          value = here;
          split[i * n + kk] = j;
        }
      }
      best[i * n + kk] = value;
    }
  if (!(best[n - 1] > worst_quality(mesh, old))) return std::nullopt;
  std::vector<Element> fresh;
  std::vector<std::pair<std::size_t, std::size_t>> pending{{0, n - 1}};
  while (!pending.empty()) {
    const auto [i, kk] = pending.back();
    pending.pop_back();
    if (kk < i + 2) continue;
    const std::size_t j = split[i * n + kk];
    fresh.push_back({ring[i], ring[j], ring[kk], y});
    fresh.push_back({ring[j], ring[i], ring[kk], x});
    pending.emplace_back(i, j);
    pending.emplace_back(j, kk);
  }
  return replace(mesh, old, fresh, mesh.label(element));
}

std::optional<LocalChange3> try_node_shift(TetrahedralMesh3& mesh, VertexId v, const LocalModificationOptions3& options) {
  if (!options.fixed_vertices.empty() && (v.value >= options.fixed_vertices.size() || options.fixed_vertices[v.value]))
    return std::nullopt;  // before the star walk: most corners of boundary slivers are fixed
  const std::vector<ElementId> star = walk_star(mesh, v);
  if (is_fixed_vertex(mesh, v, star, options)) return std::nullopt;
  const Point3d origin = mesh.point(v);
  // Per tetrahedron the ideal apex over its facet opposite v (the regular tetrahedron's, on
  // v's side); targets: their mean, and the worst tetrahedron's own.
  Point3d mean{0, 0, 0}, worst_apex = origin;
  double q0 = std::numeric_limits<double>::infinity();
  for (const ElementId e : star) {
    const Element t = mesh.vertices(e);
    const int own = local_index(t, v);
    std::array<Point3d, 3> f;
    int k = 0;
    for (int i = 0; i < 4; ++i)
      if (i != own) f[static_cast<std::size_t>(k++)] = mesh.point(t[static_cast<std::size_t>(i)]);
    Point3d c, u, w, normal;
    for (int d = 0; d < 3; ++d) {
      c[d] = (f[0][d] + f[1][d] + f[2][d]) / 3.0;
      u[d] = f[1][d] - f[0][d];
      w[d] = f[2][d] - f[0][d];
    }
    normal = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]};
    const double length = std::sqrt(normal[0] * normal[0] + normal[1] * normal[1] + normal[2] * normal[2]);
    const double side = normal[0] * (origin[0] - c[0]) + normal[1] * (origin[1] - c[1]) + normal[2] * (origin[2] - c[2]);
    double edges = 0;
    for (int i = 0; i < 3; ++i) {
      const Point3d& p = f[static_cast<std::size_t>(i)];
      const Point3d& q = f[static_cast<std::size_t>((i + 1) % 3)];
      edges += std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
    }
    const double height = std::sqrt(2.0 / 3.0) * edges / 3.0 * (side < 0 ? -1.0 : 1.0) / (length > 0 ? length : 1.0);
    Point3d apex;
    for (int d = 0; d < 3; ++d) {
      apex[d] = c[d] + height * normal[d];
      mean[d] += apex[d] / static_cast<double>(star.size());
    }
    const double q = element_quality(mesh, e);
    if (q < q0) {
      q0 = q;
      worst_apex = apex;
    }
  }
  const auto star_quality = [&](const Point3d& p) {
    double worst = std::numeric_limits<double>::infinity();
    for (const ElementId e : star) {
      std::array<Point3d, 4> c;
      const Element t = mesh.vertices(e);
      for (std::size_t i = 0; i < 4; ++i) c[i] = t[i] == v ? p : mesh.point(t[i]);
      if (!positive(c[0], c[1], c[2], c[3])) return -1.0;
      worst = std::min(worst, tetrahedron_quality(c[0], c[1], c[2], c[3]));
      if (worst <= q0) return worst;  // cannot win any more
    }
    return worst;
  };
  const double wanted = q0 + std::min(options.minimum_shift_gain, q0);
  double best = q0;
  Point3d best_point = origin;
  for (const Point3d& target : {mean, worst_apex})
    for (const double step : {1.0, 0.5, 0.25, 0.1, 0.03, 0.01, 0.003, 0.001}) {  // small: a vertex next to a face
      Point3d p;
      for (int d = 0; d < 3; ++d) p[d] = origin[d] + step * (target[d] - origin[d]);
      if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) continue;
      const double q = star_quality(p);
      if (q > best) {
        best = q;
        best_point = p;
      }
    }
  if (!(best > wanted)) return std::nullopt;
  mesh.move_vertex(v, best_point);
  return LocalChange3{star, star};
}

}  // namespace certimesh::topology
