// Exact validation of a closed triangulated surface (surface_validation_3.h).
#include "certimesh/generators/domain/surface_validation_3.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <queue>
#include <string>
#include <tuple>
#include <utility>

#include "certimesh/predicates/intersection/triangle_triangle_3d.h"
#include "certimesh/predicates/orient2d.h"
#include "certimesh/predicates/orient3d.h"

namespace certimesh::generators {

namespace {

using predicates::Point2;
using predicates::Point3;
using predicates::Sign;
using Triangle = std::array<std::uint32_t, 3>;

int sgn(Sign s) { return static_cast<int>(s); }

// The projection that drops coordinate `axis` (0: (y, z), 1: (z, x), 2: (x, y)); orient2d of a
// triangle's projection is then the sign of that component of its normal (b - a) x (c - a).
Point2 without_coordinate(const Point3& p, int axis) {
  if (axis == 0) return {p.y, p.z};
  if (axis == 1) return {p.z, p.x};
  return {p.x, p.y};
}

int normal_sign(const Point3& a, const Point3& b, const Point3& c, int axis) {
  return sgn(predicates::orient2d(without_coordinate(a, axis), without_coordinate(b, axis), without_coordinate(c, axis)));
}

bool collinear_by_projection(const Point3& a, const Point3& b, const Point3& c) {
  for (int axis = 0; axis < 3; ++axis)
    if (normal_sign(a, b, c, axis) != 0) return false;
  return true;
}

bool lexicographically_less(const Point3& a, const Point3& b) {
  return std::tie(a.x, a.y, a.z) < std::tie(b.x, b.y, b.z);
}

bool same_point(const Point3& a, const Point3& b) { return a.x == b.x && a.y == b.y && a.z == b.z; }

std::string edge_text(const Surface3& s, std::uint32_t u, std::uint32_t v) {
  return "edge " + std::to_string(u) + "-" + std::to_string(v) + " " + format_point(s.points[u]) + "-" + format_point(s.points[v]);
}

// One directed use of an edge by a triangle: edge k of `triangle` runs corner k -> k+1.
struct HalfEdge {
  std::uint32_t lo, hi, triangle;
  std::uint8_t k;
  bool forward;  // the triangle runs lo -> hi
  friend bool operator<(const HalfEdge& a, const HalfEdge& b) {
    return std::tie(a.lo, a.hi, a.triangle, a.k) < std::tie(b.lo, b.hi, b.triangle, b.k);
  }
};

class Validator {
 public:
  Validator(Surface3& s, std::size_t cap, SurfaceCheck& out) : s_(s), cap_(cap), out_(out) {}

  void run() {
    stage_vertices_and_triangles();
    if (!out_.problems.empty()) return;
    stage_edges();
    if (!out_.problems.empty()) return;
    stage_intersections();
    if (!out_.problems.empty()) return;
    stage_shells();
    if (!out_.problems.empty()) return;
    stage_windings();
    count_unused_vertices();
  }

 private:
  const Point3& corner(std::uint32_t t, int k) const { return s_.points[s_.triangles[t][std::size_t(k)]]; }

  // Problems of one stage, smallest triangle indices first, capped.
  void publish(std::vector<SurfaceProblem>& found) {
    std::stable_sort(found.begin(), found.end(), [](const SurfaceProblem& a, const SurfaceProblem& b) {
      return std::tie(a.triangles, a.vertices) < std::tie(b.triangles, b.vertices);
    });
    for (SurfaceProblem& p : found) {
      if (out_.problems.size() >= cap_) break;
      out_.problems.push_back(std::move(p));
    }
  }

  void stage_vertices_and_triangles() {
    std::vector<SurfaceProblem> found;
    // Duplicate vertices: equal coordinates sort next to each other.
    std::vector<std::uint32_t> order(s_.points.size());
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return lexicographically_less(s_.points[a], s_.points[b]); });
    for (std::size_t i = 1, first = 0; i < order.size(); ++i) {
      if (!same_point(s_.points[order[first]], s_.points[order[i]])) {
        first = i;
        continue;
      }
      const std::uint32_t a = std::min(order[first], order[i]), b = std::max(order[first], order[i]);
      found.push_back({SurfaceProblemKind::duplicate_vertices, {}, {a, b},
                       "vertices " + std::to_string(a) + " and " + std::to_string(b) + " are the same point " + format_point(s_.points[a])});
    }
    // Degenerate triangles.
    for (std::uint32_t t = 0; t < s_.triangles.size(); ++t) {
      const Triangle& v = s_.triangles[t];
      const bool repeated = v[0] == v[1] || v[1] == v[2] || v[0] == v[2];
      if (repeated || collinear_by_projection(corner(t, 0), corner(t, 1), corner(t, 2)))
        found.push_back({SurfaceProblemKind::degenerate_triangle, {t}, {v[0], v[1], v[2]},
                         describe_triangle(s_, t) + (repeated ? " repeats a corner" : " has zero area (its corners are collinear)")});
    }
    // Duplicate triangles: the same sorted vertex triple.
    std::vector<std::pair<Triangle, std::uint32_t>> keyed;
    keyed.reserve(s_.triangles.size());
    for (std::uint32_t t = 0; t < s_.triangles.size(); ++t) {
      Triangle k = s_.triangles[t];
      std::sort(k.begin(), k.end());
      keyed.push_back({k, t});
    }
    std::sort(keyed.begin(), keyed.end());
    for (std::size_t i = 1, first = 0; i < keyed.size(); ++i) {
      if (keyed[i].first != keyed[first].first) {
        first = i;
        continue;
      }
      const std::uint32_t a = keyed[first].second, b = keyed[i].second;
      found.push_back({SurfaceProblemKind::duplicate_triangles, {a, b}, {},
                       "triangles " + std::to_string(a) + " and " + std::to_string(b) + " have the same three vertices: " + describe_triangle(s_, a) +
                           " and " + describe_triangle(s_, b)});
    }
    publish(found);
  }

  // The triangles of an edge of 2k >= 4 triangles in their order around lo -> hi
  // (counterclockwise seen from hi), exactly: a half-plane index, then orient3d.
  void sort_around_edge(std::vector<HalfEdge>& around) const {
    const Point3& a = s_.points[around[0].lo];
    const Point3& b = s_.points[around[0].hi];
    auto third = [&](const HalfEdge& h) -> const Point3& { return corner(h.triangle, (h.k + 2) % 3); };
    const Point3& c0 = third(around[0]);
    int axis = 0;
    while (axis < 2 && normal_sign(a, b, c0, axis) == 0) ++axis;
    const int o0 = normal_sign(a, b, c0, axis);
    auto half = [&](const HalfEdge& h) {
      const int s = sgn(predicates::orient3d(a, b, c0, third(h)));
      if (s < 0) return 1;  // det[b - a, c0 - a, c - a] > 0: turning counterclockwise from c0
      if (s > 0) return 3;
      return normal_sign(a, b, third(h), axis) == o0 ? 0 : 2;
    };
    std::vector<std::pair<int, HalfEdge>> keyed;
    for (const HalfEdge& h : around) keyed.push_back({half(h), h});
    std::sort(keyed.begin(), keyed.end(), [&](const auto& x, const auto& y) {
      if (x.first != y.first) return x.first < y.first;
      if (x.first == 1 || x.first == 3) {
        const int s = sgn(predicates::orient3d(a, b, third(x.second), third(y.second)));
        if (s != 0) return s < 0;
      }
      return x.second.triangle < y.second.triangle;
    });
    for (std::size_t i = 0; i < around.size(); ++i) around[i] = keyed[i].second;
  }

  void join(const HalfEdge& x, const HalfEdge& y) {
    neighbour_[3 * std::size_t(x.triangle) + x.k] = y.triangle;
    neighbour_[3 * std::size_t(y.triangle) + y.k] = x.triangle;
  }

  std::string triangle_list(const std::vector<HalfEdge>& group) const {
    std::string out;
    for (std::size_t i = 0; i < group.size() && i < 8; ++i) out += (i ? ", " : "") + std::to_string(group[i].triangle);
    return group.size() > 8 ? out + ", ..." : out;
  }

  void stage_edges() {
    std::vector<HalfEdge> half;
    half.reserve(3 * s_.triangles.size());
    for (std::uint32_t t = 0; t < s_.triangles.size(); ++t)
      for (std::uint8_t k = 0; k < 3; ++k) {
        const std::uint32_t u = s_.triangles[t][k], v = s_.triangles[t][(k + 1) % 3];
        half.push_back({std::min(u, v), std::max(u, v), t, k, u < v});
      }
    std::sort(half.begin(), half.end());
    neighbour_.assign(half.size(), kNone);
    std::vector<SurfaceProblem> found;
    std::vector<HalfEdge> group;  // reused: one allocation for all edges
    for (std::size_t i = 0, j = 0; i < half.size(); i = j) {
      while (j < half.size() && half[j].lo == half[i].lo && half[j].hi == half[i].hi) ++j;
      group.assign(half.begin() + std::ptrdiff_t(i), half.begin() + std::ptrdiff_t(j));
      edge_group(group, found);
    }
    publish(found);
  }

  void edge_group(std::vector<HalfEdge>& g, std::vector<SurfaceProblem>& found) {
    // The texts are built only for a problem: most edges have none.
    auto edge = [&] { return edge_text(s_, g[0].lo, g[0].hi); };
    auto tris = [&] {
      std::vector<std::uint32_t> t;
      for (const HalfEdge& h : g) t.push_back(h.triangle);
      return t;
    };
    if (g.size() == 1) {
      found.push_back({SurfaceProblemKind::open_edge, tris(), {g[0].lo, g[0].hi}, edge() + " is open: it is an edge of " + describe_triangle(s_, g[0].triangle) + " only"});
      return;
    }
    if (g.size() == 2) {
      if (s_.oriented && g[0].forward == g[1].forward) {
        found.push_back({SurfaceProblemKind::inconsistent_orientation, tris(), {g[0].lo, g[0].hi},
                         describe_triangle(s_, g[0].triangle) + " and " + describe_triangle(s_, g[1].triangle) + " run along their common " + edge() +
                             " in the same direction (one of them is the wrong way round)"});
      }
      join(g[0], g[1]);
      return;
    }
    const std::string lead = edge() + " is in " + std::to_string(g.size()) + " triangles (" + triangle_list(g) + ")";
    if (!s_.oriented || g.size() % 2 == 1) {
      found.push_back({SurfaceProblemKind::non_manifold_edge, tris(), {g[0].lo, g[0].hi},
                       lead + (s_.oriented ? ": an odd number cannot close up"
                                           : ": in a .poly/.smesh an edge joins 2 facets (interfaces between regions are not supported yet)")});
      return;
    }
    sort_around_edge(g);
    for (std::size_t i = 0; i < g.size(); ++i) {
      if (g[i].forward == g[(i + 1) % g.size()].forward) {
        found.push_back({SurfaceProblemKind::non_manifold_edge, tris(), {g[0].lo, g[0].hi},
                         lead + " that do not alternate in direction around it: shells may touch along an edge only from outside each other"});
        return;
      }
    }
    // Join each triangle running lo -> hi with the next counterclockwise: the sector between
    // them is in front of both (outside).
    for (std::size_t i = 0; i < g.size(); ++i)
      if (g[i].forward) join(g[i], g[(i + 1) % g.size()]);
  }

  struct Box {
    std::array<double, 3> lo, hi;
  };

  Box box_of(std::uint32_t t) const {
    Box b{};
    for (int a = 0; a < 3; ++a) {
      const double x[3] = {coordinate(corner(t, 0), a), coordinate(corner(t, 1), a), coordinate(corner(t, 2), a)};
      b.lo[std::size_t(a)] = std::min({x[0], x[1], x[2]});
      b.hi[std::size_t(a)] = std::max({x[0], x[1], x[2]});
    }
    return b;
  }
  static double coordinate(const Point3& p, int axis) { return axis == 0 ? p.x : axis == 1 ? p.y : p.z; }

  bool intersect(std::uint32_t t, std::uint32_t u) const {
    auto vertices = [&](std::uint32_t i) {
      std::array<predicates::Vertex3, 3> v{};
      for (int k = 0; k < 3; ++k) v[std::size_t(k)] = {corner(i, k), s_.triangles[i][std::size_t(k)]};
      return v;
    };
    const auto a = vertices(t), b = vertices(u);
    // The filter may only err towards "intersect" (decision 3): its "disjoint" is final.
    if (predicates::triangle_triangle_3d(a, b, predicates::IntersectionMode::conservative) == predicates::Overlap::disjoint) return false;
    return predicates::triangle_triangle_3d(a, b, predicates::IntersectionMode::exact) == predicates::Overlap::intersect;
  }

  // Columns of a grid over the two axes other than the sweep axis: a triangle is listed in
  // every column its box meets, so two triangles whose boxes overlap share a column; the pair
  // is tested only in the column of the low corner of their boxes' overlap (it is in both
  // lists: the column index is a monotone function of the coordinate). The column width starts
  // at twice the median box size and doubles until the lists hold at most 8N + 64 entries, so
  // memory stays O(N) whatever the shapes.
  struct Columns {
    std::size_t u = 0, w = 0;  // the two axes of the grid
    double lo_u = 0, lo_w = 0, width = 1;
    std::uint64_t count_u = 1, count_w = 1;
    std::uint64_t of(double x, double lo, std::uint64_t count) const {
      const double c = std::floor((x - lo) / width);
      return c <= 0 ? 0 : c >= double(count - 1) ? count - 1 : static_cast<std::uint64_t>(c);
    }
    std::uint64_t cu(double x) const { return of(x, lo_u, count_u); }
    std::uint64_t cw(double x) const { return of(x, lo_w, count_w); }
  };

  Columns columns_for(const std::vector<Box>& boxes, const Box& all, std::size_t axis) const {
    Columns c;
    c.u = (axis + 1) % 3, c.w = (axis + 2) % 3;
    c.lo_u = all.lo[c.u], c.lo_w = all.lo[c.w];
    const double span = std::max(all.hi[c.u] - all.lo[c.u], all.hi[c.w] - all.lo[c.w]);
    std::vector<double> sizes;
    sizes.reserve(boxes.size());
    for (const Box& b : boxes) sizes.push_back(std::max(b.hi[c.u] - b.lo[c.u], b.hi[c.w] - b.lo[c.w]));
    std::nth_element(sizes.begin(), sizes.begin() + std::ptrdiff_t(sizes.size() / 2), sizes.end());
    c.width = 2 * sizes[sizes.size() / 2];
    if (!(c.width > 0) || !std::isfinite(span) || !(span > 0) || !std::isfinite(c.width)) c.width = std::isfinite(span) && span > 0 ? span : 1;
    c.width = std::max(c.width, span / double(1 << 20));  // at most 2^20 columns per axis
    for (;;) {
      c.count_u = static_cast<std::uint64_t>(std::floor((all.hi[c.u] - all.lo[c.u]) / c.width)) + 1;
      c.count_w = static_cast<std::uint64_t>(std::floor((all.hi[c.w] - all.lo[c.w]) / c.width)) + 1;
      std::uint64_t entries = 0;
      for (const Box& b : boxes) entries += (c.cu(b.hi[c.u]) - c.cu(b.lo[c.u]) + 1) * (c.cw(b.hi[c.w]) - c.cw(b.lo[c.w]) + 1);
      if (entries <= 8 * boxes.size() + 64 || (c.count_u == 1 && c.count_w == 1)) return c;
      c.width *= 2;
    }
  }

  void stage_intersections() {
    const std::size_t n = s_.triangles.size();
    std::vector<Box> boxes(n);
    constexpr double inf = std::numeric_limits<double>::infinity();
    Box all{{inf, inf, inf}, {-inf, -inf, -inf}};
    for (std::uint32_t t = 0; t < n; ++t) {
      boxes[t] = box_of(t);
      for (std::size_t a = 0; a < 3; ++a) all.lo[a] = std::min(all.lo[a], boxes[t].lo[a]), all.hi[a] = std::max(all.hi[a], boxes[t].hi[a]);
    }
    std::size_t axis = 0;
    for (std::size_t a = 1; a < 3; ++a)
      if (all.hi[a] - all.lo[a] > all.hi[axis] - all.lo[axis]) axis = a;
    const Columns grid = columns_for(boxes, all, axis);
    // (column, triangle) entries, by column and then by the box's start along the sweep axis.
    std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
    for (std::uint32_t t = 0; t < n; ++t)
      for (std::uint64_t i = grid.cu(boxes[t].lo[grid.u]); i <= grid.cu(boxes[t].hi[grid.u]); ++i)
        for (std::uint64_t j = grid.cw(boxes[t].lo[grid.w]); j <= grid.cw(boxes[t].hi[grid.w]); ++j) entries.push_back({i * grid.count_w + j, t});
    std::sort(entries.begin(), entries.end(), [&](const auto& a, const auto& b) {
      return std::tie(a.first, boxes[a.second].lo[axis], a.second) < std::tie(b.first, boxes[b.second].lo[axis], b.second);
    });
    std::priority_queue<std::pair<std::uint32_t, std::uint32_t>> first;  // the cap_ smallest pairs
    std::vector<std::uint32_t> active;
    for (std::size_t e = 0; e < entries.size(); ++e) {
      if (e == 0 || entries[e].first != entries[e - 1].first) active.clear();  // a new column
      const std::uint64_t column = entries[e].first;
      const std::uint32_t t = entries[e].second;
      std::size_t kept = 0;
      for (const std::uint32_t u : active) {
        if (boxes[u].hi[axis] < boxes[t].lo[axis]) continue;  // ends before t begins: retire it
        active[kept++] = u;
        bool overlap = true;
        for (std::size_t a = 0; a < 3; ++a) overlap = overlap && boxes[u].lo[a] <= boxes[t].hi[a] && boxes[t].lo[a] <= boxes[u].hi[a];
        if (!overlap) continue;
        const std::uint64_t home = grid.cu(std::max(boxes[t].lo[grid.u], boxes[u].lo[grid.u])) * grid.count_w +
                                   grid.cw(std::max(boxes[t].lo[grid.w], boxes[u].lo[grid.w]));
        if (home != column || !intersect(t, u)) continue;  // tested in its home column only
        ++out_.intersecting_pairs;
        first.push({std::min(t, u), std::max(t, u)});
        if (first.size() > cap_) first.pop();
      }
      active.resize(kept);
      active.push_back(t);
    }
    std::vector<SurfaceProblem> found;
    for (; !first.empty(); first.pop()) {
      const auto [a, b] = first.top();
      found.push_back({SurfaceProblemKind::self_intersection, {a, b}, {},
                       describe_triangle(s_, a) + " and " + describe_triangle(s_, b) + " intersect (they meet beyond their shared vertices)"});
    }
    publish(found);
  }

  // Turns triangle t over (corners 1 and 2 swapped), keeping neighbour_ per edge.
  void flip(std::uint32_t t) {
    std::swap(s_.triangles[t][1], s_.triangles[t][2]);
    std::swap(neighbour_[3 * std::size_t(t)], neighbour_[3 * std::size_t(t) + 2]);
  }

  // Whether u runs the edge from p to q.
  bool runs(std::uint32_t u, std::uint32_t p, std::uint32_t q) const {
    for (int k = 0; k < 3; ++k)
      if (s_.triangles[u][std::size_t(k)] == p && s_.triangles[u][std::size_t((k + 1) % 3)] == q) return true;
    return false;
  }

  void stage_shells() {
    const std::size_t n = s_.triangles.size();
    out_.shell_of.assign(n, kNone);
    std::vector<SurfaceProblem> found;
    for (std::uint32_t start = 0; start < n; ++start) {
      if (out_.shell_of[start] != kNone) continue;
      const auto shell = static_cast<std::uint32_t>(out_.shells.size());
      out_.shells.push_back({start, 0, 1, 0, 0});
      members_.emplace_back();
      std::queue<std::uint32_t> queue;
      out_.shell_of[start] = shell;
      queue.push(start);
      while (!queue.empty()) {
        const std::uint32_t t = queue.front();
        queue.pop();
        members_[shell].push_back(t);
        for (int k = 0; k < 3; ++k) {
          const std::uint32_t u = neighbour_[3 * std::size_t(t) + std::size_t(k)];
          const std::uint32_t p = s_.triangles[t][std::size_t(k)], q = s_.triangles[t][std::size_t((k + 1) % 3)];
          const bool coherent = runs(u, q, p);
          if (out_.shell_of[u] == kNone) {
            if (!coherent) flip(u);  // only an unoriented surface gets here (stage 2)
            out_.shell_of[u] = shell;
            queue.push(u);
          } else if (!coherent) {
            found.push_back({SurfaceProblemKind::non_orientable, {std::min(t, u), std::max(t, u)}, {},
                             "the shell of " + describe_triangle(s_, start) + " cannot be oriented (" + describe_triangle(s_, t) + " and " +
                                 describe_triangle(s_, u) + " disagree whichever way it is turned)"});
          }
        }
      }
      out_.shells[shell].triangle_count = static_cast<std::uint32_t>(members_[shell].size());
    }
    publish(found);
  }

  // Sign of orient2d, in the (y, z) projection, of (q, r) against the symbolic point
  // p' = a + e1 (b - a) + e2 (c - a) + (0, d, d^2), 1 >> e1 >> e2 >> d > 0.
  static int perturbed_orient_yz(const Point3& q, const Point3& r, const Point3& a, const Point3& b, const Point3& c) {
    const Point2 Q = without_coordinate(q, 0), R = without_coordinate(r, 0);
    for (const Point3* x : {&a, &b, &c})
      if (const int s = sgn(predicates::orient2d(Q, R, without_coordinate(*x, 0)))) return s;
    if (Q.y != R.y) return Q.y > R.y ? 1 : -1;  // the d term: (q_z - r_z) d
    return R.x > Q.x ? 1 : (R.x < Q.x ? -1 : 0);  // the d^2 term: (r_y - q_y) d^2
  }

  // The same for orient3d(q0, q1, q2, p').
  static int perturbed_orient3d(const Triangle& T, const Surface3& s, const Point3& a, const Point3& b, const Point3& c) {
    const Point3 &q0 = s.points[T[0]], &q1 = s.points[T[1]], &q2 = s.points[T[2]];
    for (const Point3* x : {&a, &b, &c})
      if (const int o = sgn(predicates::orient3d(q0, q1, q2, *x))) return o;
    if (const int ny = normal_sign(q0, q1, q2, 1)) return -ny;  // -(n_y d + n_z d^2)
    return -normal_sign(q0, q1, q2, 2);
  }

  // How T changes the winding number along the ray from p' towards +x: +-1 when the ray
  // crosses T (the sign of T's normal's x component), 0 when it misses.
  int crossing(std::uint32_t T, const Point3& a, const Point3& b, const Point3& c) const {
    const Triangle& v = s_.triangles[T];
    const Point3 &q0 = s_.points[v[0]], &q1 = s_.points[v[1]], &q2 = s_.points[v[2]];
    const int nx = normal_sign(q0, q1, q2, 0);
    if (nx == 0) return 0;  // parallel to the ray: the perturbed ray misses it
    if (perturbed_orient_yz(q0, q1, a, b, c) != nx || perturbed_orient_yz(q1, q2, a, b, c) != nx || perturbed_orient_yz(q2, q0, a, b, c) != nx) return 0;
    return perturbed_orient3d(v, s_, a, b, c) == nx ? nx : 0;  // the plane is met beyond p'
  }

  // A triangle of the shell not parallel to the x axis (a closed shell has one).
  std::uint32_t ray_triangle(std::uint32_t shell) const {
    for (const std::uint32_t t : members_[shell])
      if (normal_sign(corner(t, 0), corner(t, 1), corner(t, 2), 0) != 0) return t;
    return members_[shell].front();
  }

  // The winding number, just in front of the ray triangle t (the side its normal points to), of
  // the triangles of `candidates` that `which` accepts (t's own shell counted when t is one).
  template <class Which>
  int winding_in_front(std::uint32_t t, const std::vector<std::uint32_t>& candidates, Which which) const {
    const Point3 &a = corner(t, 0), &b = corner(t, 1), &c = corner(t, 2);
    int w = 0;
    bool own_in_count = false;
    for (const std::uint32_t T : candidates) {
      if (!which(T)) continue;
      if (T == t) {
        own_in_count = true;
        continue;
      }
      w += crossing(T, a, b, c);
    }
    // The ray leaves t towards +x: in front of t if its normal has a positive x component;
    // behind it (where the winding is one more, when t is counted) otherwise.
    if (own_in_count && normal_sign(a, b, c, 0) < 0) --w;
    return w;
  }

  void stage_windings() {
    const std::size_t shells = out_.shells.size();
    std::vector<std::uint32_t> ray(shells);
    // Each shell alone: winding 0 in front of an outward triangle, -1 in front of an inward one.
    for (std::uint32_t k = 0; k < shells; ++k) {
      ray[k] = ray_triangle(k);
      const int own = winding_in_front(ray[k], members_[k], [](std::uint32_t) { return true; });
      out_.shells[k].orientation = own == 0 ? 1 : -1;
      if (!s_.oriented && own != 0) {
        for (const std::uint32_t t : members_[k]) flip(t);
        out_.shells[k].orientation = 1;
      }
    }
    s_.oriented = true;
    // The triangles listed by the grid column (over y and z) that their box meets: a ray along
    // x from a point p can cross only those listed in p's column.
    std::vector<Box> boxes(s_.triangles.size());
    constexpr double inf = std::numeric_limits<double>::infinity();
    Box all{{inf, inf, inf}, {-inf, -inf, -inf}};
    for (std::uint32_t t = 0; t < boxes.size(); ++t) {
      boxes[t] = box_of(t);
      for (std::size_t a = 0; a < 3; ++a) all.lo[a] = std::min(all.lo[a], boxes[t].lo[a]), all.hi[a] = std::max(all.hi[a], boxes[t].hi[a]);
    }
    const Columns grid = columns_for(boxes, all, 0);
    std::vector<std::pair<std::uint64_t, std::uint32_t>> entries;
    for (std::uint32_t t = 0; t < boxes.size(); ++t)
      for (std::uint64_t i = grid.cu(boxes[t].lo[grid.u]); i <= grid.cu(boxes[t].hi[grid.u]); ++i)
        for (std::uint64_t j = grid.cw(boxes[t].lo[grid.w]); j <= grid.cw(boxes[t].hi[grid.w]); ++j) entries.push_back({i * grid.count_w + j, t});
    std::sort(entries.begin(), entries.end());
    std::vector<std::uint32_t> column;
    for (std::uint32_t k = 0; k < shells; ++k) {
      const Point3& a = corner(ray[k], 0);
      const std::uint64_t home = grid.cu(a.y) * grid.count_w + grid.cw(a.z);
      column.clear();
      for (auto e = std::lower_bound(entries.begin(), entries.end(), std::make_pair(home, std::uint32_t{0})); e != entries.end() && e->first == home; ++e)
        column.push_back(e->second);
      // The other shells' winding number at the ray's start, which is theirs all along shell k
      // (shells cross nowhere); only triangles whose box the ray can reach matter.
      const int others = winding_in_front(ray[k], column, [&](std::uint32_t T) {
        const Box& b = boxes[T];
        return out_.shell_of[T] != k && b.hi[0] >= a.x && b.lo[1] <= a.y && a.y <= b.hi[1] && b.lo[2] <= a.z && a.z <= b.hi[2];
      });
      SurfaceShell& shell = out_.shells[k];
      shell.winding_outside = others;
      shell.winding_inside = others + shell.orientation;
      out_.solids += shell.winding_outside == 0;
      out_.cavities += shell.winding_inside == 0;
      out_.interfaces += shell.winding_outside != 0 && shell.winding_inside != 0;
    }
  }

  void count_unused_vertices() {
    std::vector<char> used(s_.points.size());
    for (const Triangle& t : s_.triangles)
      for (const std::uint32_t v : t) used[v] = 1;
    out_.unused_vertices = static_cast<std::size_t>(std::count(used.begin(), used.end(), 0));
  }

  static constexpr std::uint32_t kNone = 0xffffffffu;
  Surface3& s_;
  std::size_t cap_;
  SurfaceCheck& out_;
  std::vector<std::uint32_t> neighbour_;            // per triangle edge: the triangle joined across it
  std::vector<std::vector<std::uint32_t>> members_; // per shell: its triangles
};

}  // namespace

SurfaceCheck check_surface(Surface3& surface, std::size_t max_problems) {
  SurfaceCheck out;
  for (std::uint32_t t = 0; t < surface.triangles.size(); ++t)
    for (const std::uint32_t v : surface.triangles[t])
      if (v >= surface.points.size()) {
        out.problems.push_back({SurfaceProblemKind::vertex_index_out_of_range, {t}, {v},
                                "triangle " + std::to_string(t) + " names vertex " + std::to_string(v) + ", which does not exist"});
        return out;
      }
  Validator(surface, std::max<std::size_t>(max_problems, 1), out).run();
  return out;
}

SurfaceCheck validate_surface(Surface3& surface, std::size_t max_problems) {
  SurfaceCheck out = check_surface(surface, max_problems);
  if (!out.problems.empty()) throw InvalidSurface(std::move(out.problems));
  return out;
}

InvalidSurface::InvalidSurface(std::vector<SurfaceProblem> problems)
    : std::runtime_error(problems.empty() ? std::string("invalid surface") : problems.front().message), problems_(std::move(problems)) {}

const char* to_string(SurfaceProblemKind kind) noexcept {
  switch (kind) {
    case SurfaceProblemKind::wrong_dimension: return "wrong_dimension";
    case SurfaceProblemKind::no_triangles: return "no_triangles";
    case SurfaceProblemKind::non_finite_coordinate: return "non_finite_coordinate";
    case SurfaceProblemKind::vertex_index_out_of_range: return "vertex_index_out_of_range";
    case SurfaceProblemKind::bad_facet: return "bad_facet";
    case SurfaceProblemKind::duplicate_vertices: return "duplicate_vertices";
    case SurfaceProblemKind::degenerate_triangle: return "degenerate_triangle";
    case SurfaceProblemKind::duplicate_triangles: return "duplicate_triangles";
    case SurfaceProblemKind::open_edge: return "open_edge";
    case SurfaceProblemKind::non_manifold_edge: return "non_manifold_edge";
    case SurfaceProblemKind::inconsistent_orientation: return "inconsistent_orientation";
    case SurfaceProblemKind::self_intersection: return "self_intersection";
    case SurfaceProblemKind::non_orientable: return "non_orientable";
  }
  return "unknown";
}

}  // namespace certimesh::generators
