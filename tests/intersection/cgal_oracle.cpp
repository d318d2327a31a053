#include "cgal_oracle.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <type_traits>
#include <variant>
#include <vector>

namespace certimesh::testing {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using P3 = K::Point_3;
using Seg = K::Segment_3;
using Tri = K::Triangle_3;
using Tet = K::Tetrahedron_3;
using Piece = std::variant<P3, Seg, Tri, Tet>;
using Points = std::vector<P3>;

struct Element {
  Points points;  // as given, repeats included
  std::vector<std::int64_t> ids;
};

Element element(const Vertex2* v, std::size_t n) {
  Element e;
  for (std::size_t i = 0; i < n; ++i) {
    e.points.emplace_back(v[i].point.x, v[i].point.y, 0.0);
    e.ids.push_back(v[i].id);
  }
  return e;
}
Element element(const Vertex3* v, std::size_t n) {
  Element e;
  for (std::size_t i = 0; i < n; ++i) {
    e.points.emplace_back(v[i].point.x, v[i].point.y, v[i].point.z);
    e.ids.push_back(v[i].id);
  }
  return e;
}

Points distinct(const Points& in) {
  Points out;
  for (const P3& p : in)
    if (std::find(out.begin(), out.end(), p) == out.end()) out.push_back(p);
  return out;
}

bool independent(const Points& s) {
  switch (s.size()) {
    case 1:
      return true;
    case 2:
      return s[0] != s[1];
    case 3:
      return !CGAL::collinear(s[0], s[1], s[2]);
    default:
      return !CGAL::coplanar(s[0], s[1], s[2], s[3]);
  }
}

int affine_dimension(const Points& d) {
  int dim = 0;
  const std::size_t n = d.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 1; j < n; ++j) {
      dim = std::max(dim, 1);
      for (std::size_t k = j + 1; k < n; ++k) {
        if (!CGAL::collinear(d[i], d[j], d[k])) dim = std::max(dim, 2);
        for (std::size_t l = k + 1; l < n; ++l)
          if (!CGAL::coplanar(d[i], d[j], d[k], d[l])) dim = 3;
      }
    }
  return dim;
}

Piece make_piece(const Points& s) {
  switch (s.size()) {
    case 1:
      return s[0];
    case 2:
      return Seg(s[0], s[1]);
    case 3:
      return Tri(s[0], s[1], s[2]);
    default:
      return Tet(s[0], s[1], s[2], s[3]);
  }
}

// Every affinely independent subset of dim+1 distinct points: their hulls cover the hull.
std::vector<Piece> cover(const Points& pts) {
  const Points d = distinct(pts);
  const std::size_t size = static_cast<std::size_t>(affine_dimension(d)) + 1;
  std::vector<Piece> out;
  const std::size_t n = d.size();
  for (unsigned mask = 1; mask < (1u << n); ++mask) {
    Points s;
    for (std::size_t i = 0; i < n; ++i)
      if (mask & (1u << i)) s.push_back(d[i]);
    if (s.size() == size && independent(s)) out.push_back(make_piece(s));
  }
  return out;
}

// Vertices of a CGAL intersection result.
struct Collect {
  Points* out;
  void operator()(const P3& p) const { out->push_back(p); }
  void operator()(const Seg& s) const {
    out->push_back(s.source());
    out->push_back(s.target());
  }
  void operator()(const Tri& t) const {
    for (int i = 0; i < 3; ++i) out->push_back(t.vertex(i));
  }
  void operator()(const Points& v) const { out->insert(out->end(), v.begin(), v.end()); }
};

template <class A, class B>
void intersect_objects(const A& a, const B& b, Points& out) {
  const auto r = CGAL::intersection(a, b);
  if (r) boost::apply_visitor(Collect{&out}, *r);
}

bool point_in(const P3& p, const Piece& x) {
  return std::visit(
      [&](const auto& o) -> bool {
        using T = std::decay_t<decltype(o)>;
        if constexpr (std::is_same_v<T, P3>)
          return o == p;
        else if constexpr (std::is_same_v<T, Tet>)
          return !o.has_on_unbounded_side(p);
        else
          return o.has_on(p);
      },
      x);
}

// Vertices of a n b (a, b non-degenerate pieces); empty when they do not meet.
Points meet(const Piece& a, const Piece& b) {
  Points out;
  if (const P3* p = std::get_if<P3>(&a)) {
    if (point_in(*p, b)) out.push_back(*p);
    return out;
  }
  if (const P3* p = std::get_if<P3>(&b)) {
    if (point_in(*p, a)) out.push_back(*p);
    return out;
  }
  std::visit(
      [&](const auto& x, const auto& y) {
        using X = std::decay_t<decltype(x)>;
        using Y = std::decay_t<decltype(y)>;
        if constexpr (std::is_same_v<X, P3> || std::is_same_v<Y, P3>) {
        } else if constexpr (std::is_same_v<X, Tet> && std::is_same_v<Y, Tet>) {
          throw std::logic_error("tetrahedron pairs are not tested");
        } else {
          intersect_objects(x, y, out);
        }
      },
      a, b);
  return out;
}

bool in_hull(const P3& x, const Points& s) {
  for (const Piece& p : cover(s))
    if (point_in(x, p)) return true;
  return false;
}

bool oracle(const Element& a, const Element& b) {
  Points shared;
  for (std::size_t i = 0; i < a.points.size(); ++i)
    for (std::size_t j = 0; j < b.points.size(); ++j)
      if (a.ids[i] == b.ids[j] && a.points[i] == b.points[j]) shared.push_back(a.points[i]);
  shared = distinct(shared);
  for (const Piece& pa : cover(a.points))
    for (const Piece& pb : cover(b.points))
      for (const P3& x : meet(pa, pb))
        if (shared.empty() || !in_hull(x, shared)) return true;
  return false;
}

}  // namespace

bool oracle_segment_segment_2d(const std::array<Vertex2, 2>& s, const std::array<Vertex2, 2>& t) {
  return oracle(element(s.data(), 2), element(t.data(), 2));
}
bool oracle_triangle_segment_2d(const std::array<Vertex2, 3>& tri,
                                const std::array<Vertex2, 2>& seg) {
  return oracle(element(tri.data(), 3), element(seg.data(), 2));
}
bool oracle_triangle_segment_3d(const std::array<Vertex3, 3>& tri,
                                const std::array<Vertex3, 2>& seg) {
  return oracle(element(tri.data(), 3), element(seg.data(), 2));
}
bool oracle_triangle_triangle_3d(const std::array<Vertex3, 3>& a, const std::array<Vertex3, 3>& b) {
  return oracle(element(a.data(), 3), element(b.data(), 3));
}
bool oracle_tetrahedron_triangle(const std::array<Vertex3, 4>& tet,
                                 const std::array<Vertex3, 3>& tri) {
  return oracle(element(tet.data(), 4), element(tri.data(), 3));
}

}  // namespace certimesh::testing
