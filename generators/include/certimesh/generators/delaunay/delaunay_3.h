// The 3D Delaunay tetrahedralization of a point set (issue 13, item 1), built incrementally
// (Bowyer-Watson) with exact predicates and symbolic perturbation, so cospherical and
// coplanar input (integer grids, points exactly on a sphere) never breaks it and the result
// is unique: the same tetrahedra for every order of the same points (design decision 5).
//
// The perturbation is insphere_sos's lifted one (perturbed_predicates_3.h says why the
// orientation stays exact): the result is the Delaunay tetrahedralization of the points
// after an infinitesimal, rank-ordered change of the lifted coordinate |p|^2 -- where the
// points are in general position it is the Delaunay tetrahedralization, and otherwise one of
// the Delaunay tetrahedralizations, chosen independently of the input order. No tetrahedron
// is flat: every reported tetrahedron has positive volume by exact orient3d.
//
// Tetrahedra are positive in the Medit/Gmsh sense (volume_sign > 0, design decision 4).
// Ids of input points are their indices.
//
// Storage: flat arrays, per tetrahedron slot four corners and four neighbour half-faces
// (4 * slot + local face, the face opposite the local corner), 32-bit each, and one flag
// byte: 33 bytes per tetrahedron; per vertex its point and the two id maps, 32 bytes. The
// hull is closed by "ghost" tetrahedra sharing one infinite vertex, their fourth corner; they
// are internal and never reported. No per-tetrahedron allocation.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "certimesh/generators/delaunay/delaunay_error.h"
#include "certimesh/generators/delaunay/large_array.h"
#include "certimesh/generators/progress.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators {

using predicates::Point3;

class Delaunay3 {
 public:
  using VertexId = std::uint32_t;
  using TetrahedronId = std::uint32_t;
  static constexpr std::uint32_t none = 0xffffffffu;

  /// The Delaunay tetrahedralization of conv(points). DelaunayError, naming the first
  /// offending indices and coordinates, for a non-finite or repeated point, for fewer than
  /// four points and for points all in one plane (no tetrahedron).
  explicit Delaunay3(std::span<const Point3> points, const ProgressCallback& progress = {});

  std::size_t vertex_count() const noexcept { return points_.size(); }
  const Point3& point(VertexId v) const { return points_[internal_[v]]; }

  /// Tetrahedron slots: ids in [0, tetrahedron_slot_count()) that are live are real ones.
  std::size_t tetrahedron_slot_count() const noexcept { return flags_.size(); }
  bool is_live(TetrahedronId t) const {
    return t < flags_.size() && !(flags_[t] & dead_flag) && corner_[4 * std::size_t{t} + 3] != none;
  }
  /// The corners of a live tetrahedron (public ids), positively oriented.
  std::array<VertexId, 4> vertices(TetrahedronId t) const {
    const VertexId* c = &corner_[4 * std::size_t{t}];
    return {external_[c[0]], external_[c[1]], external_[c[2]], external_[c[3]]};
  }
  /// The live tetrahedron across the face opposite local corner i, or `none` (hull).
  TetrahedronId neighbour(TetrahedronId t, int i) const {
    const TetrahedronId n = adjacent_[4 * std::size_t{t} + static_cast<std::size_t>(i)] / 4;
    return is_live(n) ? n : none;
  }
  /// The number of live tetrahedra.
  std::size_t tetrahedron_count() const noexcept { return live_count_; }
  /// The live tetrahedra, in a deterministic order.
  std::vector<std::array<VertexId, 4>> tetrahedra() const;

  /// The slot of a tetrahedron (live or ghost) whose closure holds p, found by a walk from
  /// `hint`; a ghost slot means p lies outside the hull, beyond its hull face. `none` for a
  /// non-finite p.
  TetrahedronId locate(const Point3& p, TetrahedronId hint = none) const;
  /// Whether slot t is a ghost (hull) tetrahedron: its fourth corner is the infinite vertex.
  bool is_ghost(TetrahedronId t) const { return corner_[4 * std::size_t{t} + 3] == none; }

 private:
  static constexpr std::uint8_t dead_flag = 1u << 0;
  static constexpr std::uint8_t cavity_flag = 1u << 1;    // only during insert_vertex

  struct BoundaryFace {
    std::array<VertexId, 3> corner;  // counterclockwise seen from inside the cavity
    std::uint32_t outer;             // the half-face across, outside the cavity
  };
  struct EdgeSlot {                  // the side-face matching of a new star
    std::uint64_t key;
    std::uint32_t half_face;
  };
  struct PendingFace {               // a side face waiting for its twin
    std::uint64_t twin;              // the twin's key
    std::uint32_t half_face;
    std::uint32_t slot;              // its own table entry
  };

  void build(std::span<const Point3> input, const ProgressCallback& progress);
  void check_distinct() const;  // throws for the first duplicate, by sorting
  void make_first_tetrahedron(VertexId a, VertexId b, VertexId c, VertexId d);
  void insert_vertex(VertexId v);
  void dig_cavity(const Point3& p, VertexId v);  // fills cavity_, boundary_
  void fill_star(VertexId v);                    // replaces the cavity by the star of v
  void link_around(VertexId apex, std::span<const TetrahedronId> tetrahedra);
  bool conflicts(TetrahedronId t, const Point3& p, VertexId pid) const;
  bool in_sphere(TetrahedronId t, const Point3& p, VertexId pid) const;  // t finite
  TetrahedronId walk(const Point3& p, TetrahedronId start, VertexId* equal_vertex) const;
  TetrahedronId new_slot();
  void link(std::uint32_t half_face_a, std::uint32_t half_face_b) {
    adjacent_[half_face_a] = half_face_b;
    adjacent_[half_face_b] = half_face_a;
  }
  [[noreturn]] void throw_duplicate(VertexId a, VertexId b) const;  // internal ids
  const Point3& pt(VertexId v) const { return points_[v]; }

  // Vertices are numbered internally in insertion (Hilbert) order, so the per-vertex arrays
  // are read with locality; the public ids are the input indices.
  template <class T>
  using Array = std::vector<T, detail::LargeArrayAllocator<T>>;  // large_array.h
  Array<Point3> points_;            // by internal id
  Array<VertexId> external_;        // internal id -> public id
  Array<VertexId> internal_;        // public id -> internal id
  Array<VertexId> corner_;          // 4 per slot; `none` is the infinite vertex (corner 3 only)
  Array<std::uint32_t> adjacent_;   // 4 per slot: the half-face across, 4 * slot + local
  Array<std::uint8_t> flags_;       // dead, cavity
  std::vector<TetrahedronId> free_slots_;
  std::size_t live_count_ = 0;
  TetrahedronId last_ = none;       // where the next walk starts
  // Scratch of insert_vertex, kept to avoid reallocation.
  std::vector<TetrahedronId> cavity_;
  std::vector<TetrahedronId> stack_;
  std::vector<BoundaryFace> boundary_;
  std::vector<TetrahedronId> star_;
  std::vector<EdgeSlot> edges_;     // open-addressing table, a power of two long, empty between uses
  std::vector<PendingFace> pending_;
};

}  // namespace certimesh::generators
