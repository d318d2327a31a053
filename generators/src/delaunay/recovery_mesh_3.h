// Internal to boundary recovery (boundary_recovery_3.h): the tetrahedral mesh being
// recovered, with an exact rational point per vertex. The topology is a TetrahedralMesh3
// (O(1) add/remove with its facet table); its double coordinates are only approximations
// of the exact points, used for nothing but bounding boxes and search directions. Every sign
// is exact: orient3d on doubles when all four points are doubles, else a GMP determinant.
#pragma once

#include <gmpxx.h>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "certimesh/generators/delaunay/boundary_recovery_3.h"
#include "certimesh/predicates/point.h"
#include "certimesh/topology/simplex_mesh.h"

namespace certimesh::generators::detail {

using predicates::Point3;
using topology::ElementId;
using topology::VertexId;
using QPoint = std::array<mpq_class, 3>;

/// A vertex's exact point and where it came from (which decides which surface triangles it
/// lies on: an input vertex on its own triangles, a Steiner point on its edge's two or its
/// triangle, an interior point on none).
struct RecoveryVertex {
  enum class Origin : std::uint8_t { input, on_edge, on_face, interior };
  QPoint exact;
  bool is_double = true;   // exact == (x, y, z) of `approx`, bit for bit
  Point3 approx;           // the exact point when is_double; else within one ulp per coordinate
  Point3 low, high;        // a box that holds the exact point
  Origin origin = Origin::input;
  std::uint32_t on = 0;    // the surface edge (on_edge) or triangle (on_face)
};

/// The surface: its triangles, its edges (each with its two triangles) and per input vertex
/// its triangles.
struct RecoverySurface3 {
  std::span<const Point3> points;
  std::span<const std::array<std::uint32_t, 3>> triangles;
  std::vector<std::array<std::uint32_t, 2>> edges;           // sorted (lower, higher), sorted
  std::vector<std::array<std::uint32_t, 2>> edge_triangles;  // the two triangles of each edge
  std::vector<std::vector<std::uint32_t>> vertex_triangles;  // per input vertex
};

/// An internal inconsistency (a broken invariant of proofs/boundary_recovery_3.md): never
/// expected on a valid surface. Reported as a BoundaryRecoveryError naming the invariant.
[[noreturn]] void recovery_invariant_broken(const std::string& what);

class RecoveryMesh {
 public:
  topology::TetrahedralMesh3 mesh;
  std::vector<RecoveryVertex> vertices;  // by vertex slot

  VertexId add_vertex(RecoveryVertex v);
  /// Sets v's exact point to the double point p (after Algorithm 19 moved it).
  void set_double_point(VertexId v, const Point3& p, RecoveryVertex::Origin origin);

  /// The exact sign of Shewchuk's orient3d(a, b, c, d) (det[a - d, b - d, c - d]).
  int orient(VertexId a, VertexId b, VertexId c, VertexId d) const;
  /// > 0 when (a, b, c, d) is a positive (Medit) tetrahedron.
  int volume(VertexId a, VertexId b, VertexId c, VertexId d) const { return -orient(a, b, c, d); }
  /// orient3d with the fourth point given explicitly (a double point).
  int orient(VertexId a, VertexId b, VertexId c, const Point3& d) const;

  /// The tetrahedra holding v (its star), in increasing id order.
  std::vector<ElementId> star(VertexId v) const;
  /// The tetrahedra holding both a and b.
  std::vector<ElementId> around_edge(VertexId a, VertexId b) const;
  /// The tetrahedra holding face (a, b, c): one or two.
  std::vector<ElementId> around_face(VertexId a, VertexId b, VertexId c) const;

  /// Stellar subdivision: p (a new vertex) lies exactly in the relative interior of the
  /// simplex `corners` (an edge or a face of the mesh); every tetrahedron holding the simplex
  /// is replaced by the ones with one corner of it replaced by p. Returns p's id.
  VertexId split(std::span<const VertexId> corners, RecoveryVertex p);

  /// An upper bound on the mesh's vertices + edges + faces (for the termination measures).
  std::size_t cell_bound() const { return mesh.vertex_count() + 10 * mesh.element_count() + 4; }
};

// Flips (recovery_flips_3.cpp): each is done only when valid (every new tetrahedron positive,
// the same region filled) and returns whether it was; none adds a vertex.
/// The 2-3 flip of t and its neighbour across facet i: the face between them is replaced by
/// the edge from t's corner i to the neighbour's far corner.
bool try_flip_2_3(RecoveryMesh& m, ElementId t, int i);
/// Edge removal: the tetrahedra round edge (x, y) are replaced by a triangulation of its ring
/// polygon, each triangle with x and with y: when `target` is another vertex of the ring, any
/// valid triangulation with the diagonal (apex, target) (that edge is made); else the fan from
/// `apex` (every new cell goes through it). Removes only the edge (x, y) and the faces through
/// it. A ring open on the hull is removed only where the hull is flat (the 2-2 flip on the
/// hull, and its n-m generalisation). With `shrink` (the surface, whose edges are kept),
/// where no triangulation is valid, flips round the edge take one ring vertex (never apex or
/// target) out at a time -- a 2-3 flip of a face through the edge, else the removal of an
/// edge from that vertex to x or y -- and the removal is tried again (TetGen's nested flips,
/// one level). Returns whether the mesh changed: the edge removed, or only such flips made.
bool try_remove_edge(RecoveryMesh& m, VertexId x, VertexId y, VertexId apex,
                     std::optional<VertexId> target = std::nullopt, const RecoverySurface3* shrink = nullptr);

/// Whether v and w lie on one surface edge (so the mesh edge (v, w), if it is one, is part of
/// that edge's chain): decided by the vertices' origins.
bool on_one_surface_edge(const RecoveryMesh& m, const RecoverySurface3& s, VertexId v, VertexId w);

/// The vertex record of an exact rational point.
RecoveryVertex make_vertex(QPoint p, RecoveryVertex::Origin origin, std::uint32_t on);
/// The vertex record of an input point.
RecoveryVertex make_input_vertex(const Point3& p);

QPoint to_q(const Point3& p);
/// The determinant det[a - d, b - d, c - d] (Shewchuk's orient3d, unsigned by sign).
mpq_class orient_q(const QPoint& a, const QPoint& b, const QPoint& c, const QPoint& d);
/// a + t (b - a).
QPoint along(const QPoint& a, const QPoint& b, const mpq_class& t);

// The stages (boundary_recovery_3.h).
void recover_edges(RecoveryMesh& m, const RecoverySurface3& s, BoundaryRecoveryCounts& counts, const ProgressCallback& progress);
void recover_faces(RecoveryMesh& m, const RecoverySurface3& s, BoundaryRecoveryCounts& counts, const ProgressCallback& progress);
/// Removes the tetrahedra outside the solid (winding number 0).
void keep_solid(RecoveryMesh& m, const RecoverySurface3& s, BoundaryRecoveryCounts& counts);
/// Algorithm 19: every surface Steiner point moved inside, the surface re-triangulated.
void remove_surface_steiner_points(RecoveryMesh& m, const RecoverySurface3& s, BoundaryRecoveryCounts& counts);
/// The surface triangle that face (a, b, c) lies in, or -1: decided by the vertices' origins.
std::int64_t surface_triangle_of(const RecoveryMesh& m, const RecoverySurface3& s, VertexId a, VertexId b, VertexId c);

}  // namespace certimesh::generators::detail
