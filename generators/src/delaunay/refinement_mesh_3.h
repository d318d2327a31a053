// Internal: the mutable tetrahedral mesh Delaunay refinement works on (tetrahedral_refinement_3.h
// states the rules). Flat arrays, as Delaunay3: per tetrahedron slot four corners, four
// neighbour half-faces (4 * slot + local face, the face opposite the local corner; `none` on
// the solid's boundary), a label and one flag byte (dead, in the cavity, and four bits: face i
// is a constraint). Freed slots are reused. The mesh need not be Delaunay: insertion shrinks
// the cavity until the point sees all of it (why that suffices: proofs/tetrahedral_refinement_3.md).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "certimesh/generators/delaunay/tetrahedral_refinement_3.h"

namespace certimesh::generators::detail {

class RefinementMesh3 {
 public:
  static constexpr std::uint32_t none = 0xffffffffu;

  enum class Insertion {
    inserted,
    behind_constraint,  // the walk would cross a boundary face or an internal facet
    walk_too_long,
    on_vertex,
    on_constraint,      // the point lies in the plane of a constraint face of its tetrahedron
    not_visible,        // no cavity in which the point sees every face
    too_close,          // a cavity vertex nearer than the minimum distance, or inside the
                        // diametral ball of a constraint face of the cavity
  };

  /// Builds the adjacency (faces matched by sorting) and the constraint bits of `mesh`;
  /// std::invalid_argument for a non-positive tetrahedron or a face in three tetrahedra.
  explicit RefinementMesh3(const Tetrahedralization3& mesh);

  std::size_t slot_count() const { return flags_.size(); }
  bool is_live(std::uint32_t t) const { return t < flags_.size() && !(flags_[t] & dead_flag); }
  const std::uint32_t* corners(std::uint32_t t) const { return &corner_[4 * std::size_t{t}]; }
  const Point3& point(std::uint32_t v) const { return points_[v]; }
  std::size_t vertex_count() const { return points_.size(); }
  std::size_t tetrahedron_count() const { return live_count_; }
  /// Whether face i of tetrahedron t is on the solid's boundary (no tetrahedron across).
  bool is_boundary(std::uint32_t t, int i) const { return adjacent_[4 * std::size_t{t} + static_cast<std::size_t>(i)] == none; }

  /// Inserts p, walking from tetrahedron `start`, unless a cavity vertex lies nearer than
  /// `min_distance` or p lies in the diametral ball, scaled by `ball_factor` about its centre,
  /// of a constraint face of the cavity (the faces cannot be split, so a point that near would
  /// only make a flat tetrahedron on it). On success the new vertex is vertex_count() - 1, created() holds the new
  /// tetrahedra and link() the cavity's vertices.
  Insertion insert(const Point3& p, std::uint32_t start, double min_distance, double ball_factor);
  const std::vector<std::uint32_t>& created() const { return created_; }
  const std::vector<std::uint32_t>& link() const { return link_; }

  /// The live tetrahedra in slot order, their labels, and the points.
  void export_to(Tetrahedralization3& mesh) const;

 private:
  static constexpr std::uint8_t dead_flag = 1u << 0;
  static constexpr std::uint8_t cavity_flag = 1u << 1;
  static constexpr std::uint8_t candidate_flag = 1u << 2;  // while the cavity is reconnected
  static constexpr int constraint_shift = 4;

  struct CavityFace {  // a face of the cavity's boundary: tetrahedron t, its local face i
    std::uint32_t t;
    int i;
  };
  struct NewTetrahedron {
    std::array<std::uint32_t, 4> corner;
    std::uint32_t outer;  // the half-face across face `face`, or none
    int face;             // the local face opposite the new vertex
    bool constraint;
    io::Label label;
  };

  bool is_constraint(std::uint32_t t, int i) const {
    return adjacent_[4 * std::size_t{t} + static_cast<std::size_t>(i)] == none ||
           ((flags_[t] >> (constraint_shift + i)) & 1u);
  }
  int side(std::uint32_t t, int i, const Point3& p) const;  // volume sign with corner i moved to p
  bool in_sphere(std::uint32_t t, const Point3& p) const;
  bool encroaches(const CavityFace& f, const Point3& p, double ball_factor) const;  // steers only
  Insertion walk(const Point3& p, std::uint32_t start, std::uint32_t* found) const;
  bool grow_cavity(const Point3& p, std::uint32_t seed, double min_distance, double ball_factor);
  bool shrink_to_star(const Point3& p, std::uint32_t seed);  // false: the seed itself fails
  void keep_connected(std::uint32_t seed);
  void collect_faces();
  void clear_cavity();
  void fill(const Point3& p);
  void match_side_faces();
  std::uint32_t new_slot();

  std::vector<Point3> points_;
  std::vector<std::uint32_t> corner_;
  std::vector<std::uint32_t> adjacent_;
  std::vector<io::Label> label_;
  std::vector<std::uint8_t> flags_;
  std::vector<std::uint32_t> free_;
  std::size_t live_count_ = 0;

  // Scratch of one insertion.
  std::vector<std::uint32_t> cavity_;
  std::vector<CavityFace> faces_;
  std::vector<std::uint32_t> created_;
  std::vector<std::uint32_t> link_;
  std::vector<std::uint32_t> vertex_stamp_;
  std::uint32_t stamp_ = 0;
  std::vector<NewTetrahedron> pending_;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> side_faces_;
  std::vector<std::pair<std::uint64_t, std::uint32_t>> edge_table_;  // match_side_faces()
  static constexpr std::uint32_t matched = none - 1;
};

}  // namespace certimesh::generators::detail
