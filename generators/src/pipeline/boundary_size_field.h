// The pipeline's default size (size_policy.h): the boundary's local feature size, grown away
// from the boundary at a bounded rate g, capped at a maximum H:
//     h(x) = min(H, min_i (lfs_i + g·|x − p_i|)).
// lfs_i of a domain point p_i: the distance to its nearest neighbour in the constrained
// Delaunay triangulation (CDT) of the domain's points and segments -- the lengths of its own
// segments among them -- and to the nearest constrained edge opposite p_i in a triangle of its
// star (a segment passing close by). The Delaunay property puts the nearest other point among
// the neighbours; a close segment is, in the generic case, opposite the point.
//
// Evaluation in near-linear time, never all pairs: the values at the CDT's vertices are
// propagated along its edges (Dijkstra, h_v ≤ h_u + g·|uv|: O(n log n)), and h(x) is the
// minimum over the three vertices v of the CDT triangle holding x of h_v + g·|x − v|, found by
// a walk (the triangle is unique under symbolic perturbation, so the value does not depend on
// the order of queries). Since each term is g-Lipschitz, h is g-Lipschitz inside every triangle;
// across a triangle edge it can jump (the third vertices differ), never below the smallest of
// the two sides' vertex values. Path lengths along CDT edges are at least the straight
// distances, so h is at least the formula's value; it is at most min over the triangle's
// vertices, which the formula never exceeds by more than a triangle's reach.
//
// Distances are approximate (they steer sizes only) and scale with the input: the pipeline
// meshes a copy of the domain scaled by a power of two, so the field is the same for every
// power-of-two scaling of the input.
#pragma once

#include <memory>
#include <vector>

#include "certimesh/generators/delaunay/constrained_delaunay_2.h"
#include "certimesh/generators/domain/planar_domain.h"
#include "certimesh/generators/size_policy.h"

namespace certimesh::generators::detail {

class BoundarySizeField2 {
 public:
  /// grading > 0 and maximum > 0, both finite. The domain must be valid (validate_domain).
  BoundarySizeField2(const PlanarDomain& domain, double grading, double maximum);
  BoundarySizeField2(const BoundarySizeField2&) = delete;
  BoundarySizeField2& operator=(const BoundarySizeField2&) = delete;

  /// h(p), positive and finite for every finite p.
  double operator()(const Point2& p) const;
  /// h at domain point v after propagation (≤ lfs_v).
  double at_vertex(std::uint32_t v) const { return h_[v]; }
  /// The smallest vertex value: when it is at least the maximum, h is the maximum everywhere.
  double smallest() const { return smallest_; }
  /// lfs of domain point v before propagation.
  double local_feature_size(std::uint32_t v) const { return lfs_[v]; }

 private:
  void measure_local_feature_sizes();
  void propagate();

  ConstrainedDelaunay2 cdt_;
  std::vector<double> lfs_, h_;
  double grading_, maximum_, smallest_ = 0.0;
  mutable ConstrainedDelaunay2::TriangleId hint_ = ConstrainedDelaunay2::none;
};

/// The largest size the boundary-adapted size defaults to: default_maximum_fraction of the
/// diagonal of the bounding box of the domain's points.
double default_maximum_size(const PlanarDomain& domain);

/// The policy the pipeline meshes with: `user` itself when it has a size function or
/// grading == 0; otherwise the boundary-adapted size as its size function (maximum
/// user.uniform_size when positive, default_maximum_size otherwise), user.growth kept -- or,
/// when every domain point's value reaches the maximum (h is then the maximum everywhere), that
/// maximum as a uniform size: the same mesh as `--grading 0 --size H`, without a walk per query.
SizePolicy boundary_adapted_policy(const PlanarDomain& domain, const SizePolicy& user);

}  // namespace certimesh::generators::detail
