// Stage 2 of boundary recovery: every surface triangle T becomes a union of mesh faces
// (Algorithm 18's PROCESS_FACES, digest C section 2.2, done triangle by triangle). Once the
// edges of T are chains of mesh edges (stage 1), T is a union of mesh faces exactly when no
// mesh edge crosses its relative interior (proofs/boundary_recovery_3.md section 3), so every
// such edge is removed: by an edge removal with the fan from a corner of T where that is
// valid (no Steiner point), else split at its exact crossing point with T. The split creates only edges through
// the new point, which lies in T, so none of them crosses T: the crossing edges of T, found
// once, are split one by one (each is still an edge when its turn comes, since a split
// removes only the edge it splits), and the check after that finds none.
#include <algorithm>
#include <deque>
#include <string>
#include <utility>

#include "recovery_mesh_3.h"

namespace certimesh::generators::detail {

namespace {

using Edge = std::pair<VertexId, VertexId>;

struct Box {
  Point3 low, high;
};

bool boxes_meet(const Box& a, const Box& b) {
  return a.low.x <= b.high.x && b.low.x <= a.high.x && a.low.y <= b.high.y && b.low.y <= a.high.y &&
         a.low.z <= b.high.z && b.low.z <= a.high.z;
}

// Marks reused from triangle to triangle (a search is local; clearing arrays the size of the
// mesh for each triangle would make the stage quadratic), and each vertex's side of the
// current triangle's plane, computed once per search (an exact sign, often of a zero
// determinant on a flat surface).
class SearchScratch {
 public:
  void start(std::size_t elements, std::size_t vertices) {
    if (++stamp_ == 0) {  // wrapped: clear once
      std::fill(element_.begin(), element_.end(), 0);
      std::fill(vertex_.begin(), vertex_.end(), 0);
      std::fill(side_stamp_.begin(), side_stamp_.end(), 0);
      stamp_ = 1;
    }
    if (element_.size() < elements) element_.resize(elements, 0);
    if (vertex_.size() < vertices) vertex_.resize(vertices, 0), side_.resize(vertices, 0), side_stamp_.resize(vertices, 0);
  }
  /// true the first time t is seen in this search
  bool visit(ElementId t) { return std::exchange(element_[t.value], stamp_) != stamp_; }
  /// true the first time v is expanded in this search
  bool expand(VertexId v) { return std::exchange(vertex_[v.value], stamp_) != stamp_; }
  template <class Sign>
  int side(VertexId v, const Sign& sign) {
    if (side_stamp_[v.value] != stamp_) side_[v.value] = static_cast<signed char>(sign(v)), side_stamp_[v.value] = stamp_;
    return side_[v.value];
  }

 private:
  std::uint32_t stamp_ = 0;
  std::vector<std::uint32_t> element_, vertex_, side_stamp_;
  std::vector<signed char> side_;
};

class TriangleCrossings {
 public:
  TriangleCrossings(const RecoveryMesh& m, const std::array<std::uint32_t, 3>& t, SearchScratch& scratch)
      : m_(m), scratch_(scratch) {
    for (int i = 0; i < 3; ++i) corner_[i] = VertexId{t[static_cast<std::size_t>(i)]};
    box_ = box_of(corner_);
  }

  /// The mesh edges whose relative interior crosses the relative interior of the triangle,
  /// in a deterministic order. The search visits the tetrahedra that may meet the triangle,
  /// through vertex stars from the star of its first corner (the closed tetrahedra meeting a
  /// connected set are connected through shared vertices).
  std::vector<Edge> find() const {
    scratch_.start(m_.mesh.element_slot_count(), m_.mesh.vertex_slot_count());
    std::deque<ElementId> queue;
    for (const ElementId t : m_.star(corner_[0])) scratch_.visit(t), queue.push_back(t);
    std::vector<Edge> crossing;
    while (!queue.empty()) {
      const ElementId t = queue.front();
      queue.pop_front();
      const auto c = m_.mesh.vertices(t);
      for (int i = 0; i < 4; ++i)
        for (int j = i + 1; j < 4; ++j)
          if (crosses(c[static_cast<std::size_t>(i)], c[static_cast<std::size_t>(j)]))
            crossing.push_back(std::minmax(c[static_cast<std::size_t>(i)], c[static_cast<std::size_t>(j)],
                                           [](VertexId x, VertexId y) { return x.value < y.value; }));
      for (const VertexId v : c) {
        if (!scratch_.expand(v)) continue;
        for (const ElementId n : m_.star(v))
          if (scratch_.visit(n) && may_meet(n)) queue.push_back(n);
      }
    }
    std::sort(crossing.begin(), crossing.end(),
              [](const Edge& x, const Edge& y) { return std::pair(x.first.value, x.second.value) < std::pair(y.first.value, y.second.value); });
    crossing.erase(std::unique(crossing.begin(), crossing.end()), crossing.end());
    return crossing;
  }

  bool crosses(VertexId p, VertexId q) const {
    const int op = side(p), oq = side(q);
    if (op * oq >= 0) return false;
    const int s0 = m_.orient(p, q, corner_[0], corner_[1]);
    const int s1 = m_.orient(p, q, corner_[1], corner_[2]);
    const int s2 = m_.orient(p, q, corner_[2], corner_[0]);
    return s0 != 0 && s0 == s1 && s1 == s2;
  }

  VertexId corner(int i) const { return corner_[i]; }

 private:
  template <class Range>
  Box box_of(const Range& vertices) const {
    Box b{m_.vertices[vertices[0].value].low, m_.vertices[vertices[0].value].high};
    for (const VertexId v : vertices) {
      const RecoveryVertex& r = m_.vertices[v.value];
      b.low = {std::min(b.low.x, r.low.x), std::min(b.low.y, r.low.y), std::min(b.low.z, r.low.z)};
      b.high = {std::max(b.high.x, r.high.x), std::max(b.high.y, r.high.y), std::max(b.high.z, r.high.z)};
    }
    return b;
  }

  // Conservative: false only when the tetrahedron cannot meet the triangle.
  bool may_meet(ElementId t) const {
    const auto c = m_.mesh.vertices(t);
    if (!boxes_meet(box_of(c), box_)) return false;
    int positive = 0, negative = 0;
    for (const VertexId v : c) {
      const int o = side(v);
      positive += o > 0, negative += o < 0;
    }
    return positive < 4 && negative < 4;
  }

  // The side of the triangle's plane v is on (orient3d), cached for the current search.
  int side(VertexId v) const {
    return scratch_.side(v, [&](VertexId x) { return m_.orient(corner_[0], corner_[1], corner_[2], x); });
  }

  const RecoveryMesh& m_;
  SearchScratch& scratch_;
  VertexId corner_[3];
  Box box_;
};

// The crossing edge (p, q) removed by the fan from a corner of the triangle: the new edges all
// end at that corner, in the triangle's plane, so none crosses the triangle's interior, and
// the removal removes no other edge (the list found once stays valid).
bool remove_by_fan_from_corner(RecoveryMesh& m, const TriangleCrossings& triangle, VertexId p, VertexId q) {
  for (int i = 0; i < 3; ++i)
    if (try_remove_edge(m, p, q, triangle.corner(i))) return true;
  return false;
}

}  // namespace

void recover_faces(RecoveryMesh& m, const RecoverySurface3& s, BoundaryRecoveryCounts& counts, const ProgressCallback& progress) {
  SearchScratch scratch;
  for (std::uint32_t f = 0; f < s.triangles.size(); ++f) {
    // Already a mesh face (the common case after the flips of stage 1): a mesh edge cannot
    // cross a mesh face's interior, so there is nothing to recover, and no search is needed
    // (the search costs exact signs of every point near the triangle's plane, all zero on a
    // flat part of the surface).
    const auto& corners = s.triangles[f];
    if (m.mesh.find_facet({VertexId{corners[0]}, VertexId{corners[1]}, VertexId{corners[2]}})) continue;
    const TriangleCrossings triangle(m, s.triangles[f], scratch);
    // Copies: a split appends to m.vertices, which may move its elements.
    const QPoint a = m.vertices[triangle.corner(0).value].exact, b = m.vertices[triangle.corner(1).value].exact,
                 c = m.vertices[triangle.corner(2).value].exact;
    for (const auto& [p, q] : triangle.find()) {  // the termination measure: this list's length
      if (remove_by_fan_from_corner(m, triangle, p, q)) {
        ++counts.flips;
        continue;
      }
      const QPoint &qp = m.vertices[p.value].exact, &qq = m.vertices[q.value].exact;
      const mpq_class op = orient_q(a, b, c, qp), oq = orient_q(a, b, c, qq);
      const VertexId edge[2] = {p, q};
      ++counts.face_steiner_points;
      m.split(edge, make_vertex(along(qp, qq, op / (op - oq)), RecoveryVertex::Origin::on_face, f));
    }
    if (!triangle.find().empty())
      recovery_invariant_broken("surface triangle " + std::to_string(f) + " is still crossed after its recovery");
    if ((f & 255) == 0) report(progress, "recovery", s.edges.size() + f, s.edges.size() + s.triangles.size());
  }
}

}  // namespace certimesh::generators::detail
