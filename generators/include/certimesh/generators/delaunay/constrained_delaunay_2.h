// A 2D (constrained) Delaunay triangulation, built incrementally with exact predicates and
// symbolic perturbation (incircle_sos / orient2d_sos), so cocircular and collinear input
// never breaks it and the result does not depend on the insertion order beyond what SoS
// fixes (design decision 5: same input, same output, bit for bit).
//
// Two uses (issue 5): triangulating a point set (the convex hull), and completing any region
// the advancing front leaves -- constraints recovered by flips, never by Steiner points.
//
// Triangles are counterclockwise and non-degenerate: SoS may create flat triangles along a
// collinear piece of the convex hull; they are never reported. Ids of input points are their
// indices; inserted points get the next ids.
//
// Storage: flat arrays, three vertices and three neighbours per triangle slot, no
// per-triangle allocation. The hull is closed by "ghost" triangles sharing one infinite
// vertex (no far-away super-triangle, whose vertices would change the hull: digest B §2.3);
// they are internal and never reported.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "certimesh/generators/delaunay/delaunay_error.h"
#include "certimesh/generators/delaunay/large_array.h"
#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/generators/progress.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators {

using predicates::Point2;

class ConstrainedDelaunay2 {
 public:
  using VertexId = std::uint32_t;
  using TriangleId = std::uint32_t;
  static constexpr std::uint32_t none = 0xffffffffu;

  /// The Delaunay triangulation of conv(points). Points must be finite and pairwise
  /// distinct (DelaunayError names the first offending indices). Fewer than three points,
  /// or all collinear: no triangle.
  explicit ConstrainedDelaunay2(std::span<const Point2> points, const ProgressCallback& progress = {});

  /// Makes segment (a, b) an edge and marks it constrained, restoring the constrained
  /// Delaunay property around it. DelaunayError if a vertex lies in the open segment or it
  /// crosses an existing constrained edge.
  void insert_constraint(VertexId a, VertexId b);

  /// Inserts p, keeping the triangulation constrained Delaunay. p must lie strictly inside
  /// a live triangle or on an unconstrained edge; returns `none` and changes nothing when p
  /// is outside the triangulation, on a constrained edge, or equal to a vertex. `hint` speeds
  /// up point location.
  VertexId insert_point(const Point2& p, TriangleId hint = none);

  /// Splits the constrained edge (a, b) at p, which need not lie exactly on it (a Steiner
  /// point on a segment is the rounding of an exact point of it, design decision 2): p must
  /// lie on the open edge or strictly inside the triangle (or beyond the hull edge) on its
  /// side. Then (a, p) and (p, b) become constrained edges in place of (a, b) and the
  /// triangulation stays constrained Delaunay. Returns `none` and changes nothing when (a, b)
  /// is not a constrained edge or p does not fit that way.
  VertexId split_constraint(VertexId a, VertexId b, const Point2& p);

  /// The live triangle that has the directed edge a -> b counterclockwise, or `none`.
  TriangleId triangle_left_of(VertexId a, VertexId b) const;

  std::size_t vertex_count() const noexcept { return points_.size(); }
  const Point2& point(VertexId v) const { return points_[internal_[v]]; }

  /// Triangle slots: ids in [0, triangle_slot_count()) that are live are real triangles.
  std::size_t triangle_slot_count() const noexcept { return flags_.size(); }
  bool is_live(TriangleId t) const;
  /// Counterclockwise vertices of a live triangle.
  std::array<VertexId, 3> vertices(TriangleId t) const {
    const VertexId* c = &corner_[3 * std::size_t{t}];
    return {external_[c[0]], external_[c[1]], external_[c[2]]};
  }
  /// The live triangle across the edge opposite local vertex i, or `none` (hull).
  TriangleId neighbour(TriangleId t, int i) const;
  /// Whether the edge opposite local vertex i is constrained.
  bool is_constrained(TriangleId t, int i) const { return (flags_[t] >> i) & 1u; }
  /// Some live triangle incident to v, or `none`.
  TriangleId incident_triangle(VertexId v) const;

  /// Flood fill that never crosses a constrained edge. Outside (-1): everything reachable
  /// from the hull or from a triangle containing a hole point. Every other triangle gets the
  /// label of the region seed in its component (0 when none). Indexed by triangle slot;
  /// dead slots are -1.
  std::vector<int> classify(std::span<const Point2> holes, std::span<const RegionSeed> regions) const;

  /// The live triangles, in a deterministic order.
  std::vector<std::array<VertexId, 3>> triangles() const;

  /// The slot of a triangle (live, flat or ghost) containing p in the perturbed sense, found
  /// by a walk from `hint`; `none` when the triangulation is empty. Ghost slots mean p lies
  /// outside the hull. Used by classify() and the refinement.
  TriangleId locate(const Point2& p, TriangleId hint = none) const;
  /// Whether slot t is a ghost (hull) triangle; its ghost corner is `none`.
  bool is_ghost(TriangleId t) const { return (flags_[t] & ghost_flag) != 0; }

 private:
  static constexpr std::uint8_t dead_flag = 1u << 3;
  static constexpr std::uint8_t ghost_flag = 1u << 4;
  static constexpr std::uint8_t cavity_flag = 1u << 5;  // only during insert_vertex
  static constexpr std::uint8_t constrained_mask = 0x7;

  struct BoundaryEdge {
    VertexId a, b;         // counterclockwise as seen from the cavity
    std::uint32_t outer;   // the half-edge (3 * slot + local) across, outside the cavity
    bool constrained;
  };
  struct DigFrame {           // the cavity search's explicit recursion
    TriangleId t;
    std::uint32_t local;      // the next edge of t to look across
    std::uint32_t left;       // how many edges of t are still to look across
  };

  void build(std::span<const Point2> input, const ProgressCallback& progress);
  void make_first_triangle(VertexId a, VertexId b, VertexId c);
  void insert_vertex(VertexId v, TriangleId start, bool respect_constraints);
  void dig_cavity(const Point2& p, VertexId v, bool respect_constraints);  // fills cavity_, boundary_
  void finish_star(VertexId v);  // replaces the cavity by the star of v
  TriangleId walk(const Point2& p, TriangleId start, VertexId* equal_vertex, bool remember = false) const;
  bool in_circle(TriangleId t, const Point2& p, VertexId pid) const;
  TriangleId new_slot();
  void link(std::uint32_t half_edge_a, std::uint32_t half_edge_b);
  std::uint32_t find_half_edge(VertexId u, VertexId v) const;
  void set_constrained(std::uint32_t half_edge, bool constrained);
  bool fits_beside(std::uint32_t half_edge, const Point2& p) const;
  void flip(std::uint32_t half_edge);
  void restore_delaunay(std::vector<std::array<VertexId, 2>> edges);
  std::vector<std::array<VertexId, 2>> crossing_edges(VertexId a, VertexId b) const;
  [[noreturn]] void throw_duplicate(VertexId a, VertexId b) const;  // internal ids
  std::string constraint_name(VertexId a, VertexId b) const;          // internal ids
  const Point2& pt(VertexId v) const { return points_[v]; }

  // Vertices are numbered internally in insertion (Hilbert) order, so the per-vertex arrays
  // are read with locality; the public ids are the input indices.
  template <class T>
  using Array = std::vector<T, detail::LargeArrayAllocator<T>>;  // large_array.h
  Array<Point2> points_;                  // by internal id
  Array<VertexId> external_;              // internal id -> public id
  Array<VertexId> internal_;              // public id -> internal id
  Array<VertexId> corner_;                // 3 per slot; `none` is the ghost vertex
  Array<std::uint32_t> adjacent_;         // 3 per slot: the half-edge across, 3 * slot + local
  Array<std::uint8_t> flags_;             // bits 0-2 constrained edges, dead, ghost, cavity
  Array<TriangleId> vertex_triangle_;
  std::vector<TriangleId> free_slots_;
  TriangleId last_ = none;                // where the next walk starts
  // Scratch of insert_vertex, kept to avoid reallocation.
  std::vector<TriangleId> cavity_;
  std::vector<DigFrame> dig_;
  std::vector<BoundaryEdge> boundary_;    // in counterclockwise order around the cavity
};

}  // namespace certimesh::generators
