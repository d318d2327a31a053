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
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/generators/progress.h"
#include "certimesh/predicates/point.h"

namespace certimesh::generators {

using predicates::Point2;

/// Thrown for input the triangulation cannot take: non-finite or duplicate points, or a
/// constraint that crosses another constraint or passes through a vertex. The message names
/// the ids involved.
class DelaunayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

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

  std::size_t vertex_count() const noexcept;
  const Point2& point(VertexId v) const;

  /// Triangle slots: ids in [0, triangle_slot_count()) that are live are real triangles.
  std::size_t triangle_slot_count() const noexcept;
  bool is_live(TriangleId t) const;
  /// Counterclockwise vertices of a live triangle.
  std::array<VertexId, 3> vertices(TriangleId t) const;
  /// The live triangle across the edge opposite local vertex i, or `none` (hull).
  TriangleId neighbour(TriangleId t, int i) const;
  /// Whether the edge opposite local vertex i is constrained.
  bool is_constrained(TriangleId t, int i) const;
  /// Some live triangle incident to v, or `none`.
  TriangleId incident_triangle(VertexId v) const;

  /// Flood fill that never crosses a constrained edge. Outside (-1): everything reachable
  /// from the hull or from a triangle containing a hole point. Every other triangle gets the
  /// label of the region seed in its component (0 when none). Indexed by triangle slot;
  /// dead slots are -1.
  std::vector<int> classify(std::span<const Point2> holes, std::span<const RegionSeed> regions) const;

  /// The live triangles, in a deterministic order.
  std::vector<std::array<VertexId, 3>> triangles() const;

  ~ConstrainedDelaunay2();
  ConstrainedDelaunay2(ConstrainedDelaunay2&&) noexcept;
  ConstrainedDelaunay2& operator=(ConstrainedDelaunay2&&) noexcept;

 private:
  struct Impl;
  Impl* impl_;
};

}  // namespace certimesh::generators
