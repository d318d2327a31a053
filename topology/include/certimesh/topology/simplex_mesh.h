// The mesh model: a simplicial mesh of SimplexDim-simplices embedded in EmbeddingDim-space,
// stored as structure of arrays, with element adjacency kept up to date by local O(1) updates.
//
//   TriangleMesh2     2D triangle meshes
//   SurfaceMesh3      triangulated surfaces in 3D
//   TetrahedralMesh3  tetrahedral meshes
//
// Storage (one array per attribute, indexed by slot):
//   coordinates        EmbeddingDim doubles per vertex slot
//   element vertices   SimplexDim+1 vertex ids per element slot
//   neighbours         SimplexDim+1 element ids per element slot; entry i is the element across
//                      facet i (the facet opposite local vertex i, local_facets.h), or no_element
//   element labels     one material label per element slot
//   facet labels       a label per facet, by facet key (boundary facets and, where a file gives
//                      them, labelled interfaces); 0 when none was set
//
// Why a facet table: the generators and the local modifications of chapters 3-5 insert,
// delete and flip elements millions of times. Every facet that some live element holds is in
// one hash table, keyed by its sorted vertex ids, with one holder; a new element finds the
// twin of each of its facets there in O(1) expected time, and removal unlinks in O(1). The
// table is never iterated, so its (value-hashed) order cannot leak into any result; boundary
// facets are found by scanning the neighbour array in slot order.
//
// Slots: removing an element or a vertex frees its slot; the next add reuses the most recently
// freed slot (a LIFO free list). No live id ever changes.
//
// The mesh is combinatorial: it does not decide orientation or validity (the generators do,
// through the exact predicates, and certificate/ checks the result). It does refuse what it
// cannot represent: an element with a repeated or dead vertex, and a third element on a facet.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <unordered_map>
#include <vector>

#include "certimesh/io/mesh_data.h"
#include "certimesh/topology/facet_key.h"
#include "certimesh/topology/index.h"

namespace certimesh::topology {

using Label = io::Label;

/// Work done by the facet table, for checking that adjacency updates are O(1): `lookups`
/// counts facet-table searches, `probes` the stored keys compared against a searched key.
struct FacetTableStats {
  std::uint64_t lookups = 0;
  std::uint64_t probes = 0;
};

template <int EmbeddingDim, int SimplexDim>
class SimplexMesh {
  static_assert(EmbeddingDim >= SimplexDim && EmbeddingDim <= 3 && SimplexDim >= 2);

 public:
  static constexpr int embedding_dimension = EmbeddingDim;
  static constexpr int simplex_dimension = SimplexDim;
  static constexpr int vertices_per_element = SimplexDim + 1;
  static constexpr int vertices_per_facet = SimplexDim;

  using Point = std::array<double, EmbeddingDim>;
  using Element = std::array<VertexId, vertices_per_element>;
  using Facet = std::array<VertexId, vertices_per_facet>;
  using Key = FacetKey<vertices_per_facet>;

  // --- vertices -------------------------------------------------------------------------
  VertexId add_vertex(const Point& p);
  /// Frees the slot of a vertex no live element uses; throws TopologyError otherwise.
  void remove_vertex(VertexId v);
  void move_vertex(VertexId v, const Point& p);
  bool is_live(VertexId v) const noexcept;
  Point point(VertexId v) const;
  std::size_t vertex_count() const noexcept { return live_vertices_; }
  std::size_t vertex_slot_count() const noexcept { return vertex_live_.size(); }
  /// Number of live elements that use v (exact).
  std::uint32_t incident_element_count(VertexId v) const { return vertex_degree_.at(v.value); }
  /// A live element that uses v, or no_element if none does. Kept up to date by every add and
  /// remove so that star walks can start from it. After a removal it is found among the
  /// removed element's neighbours; if v's star is not connected through facets (a pinched,
  /// non-manifold star) and none of those neighbours uses v, it may be no_element even though
  /// incident_element_count(v) > 0.
  ElementId incident_element(VertexId v) const { return vertex_hint_.at(v.value); }

  // --- elements -------------------------------------------------------------------------
  /// Adds an element and links each of its facets to the element already holding it.
  /// Throws TopologyError (and leaves the mesh unchanged) if a vertex is dead or repeated,
  /// or if a facet already has two elements.
  ElementId add_element(const Element& vertices, Label label = 0);
  /// Removes a live element, unlinking its neighbours (their facets become open).
  void remove_element(ElementId e);
  bool is_live(ElementId e) const noexcept;
  Element vertices(ElementId e) const;
  ElementId neighbour(ElementId e, int facet) const;
  Label label(ElementId e) const;
  void set_label(ElementId e, Label label);
  /// The vertices of facet i of e (opposite local vertex i), outward for a positive element.
  Facet facet(ElementId e, int i) const;
  /// The local index j with neighbour(n, j) == e for n = neighbour(e, i).
  int mirror_facet(ElementId e, int i) const;
  std::size_t element_count() const noexcept { return live_elements_; }
  std::size_t element_slot_count() const noexcept { return element_live_.size(); }

  /// Where a facet (any orientation) is held: one live element having it and its local index;
  /// std::nullopt when no live element has it.
  struct FacetRef {
    ElementId element;
    int local = 0;
  };
  std::optional<FacetRef> find_facet(const Facet& f) const;

  // --- facet labels ---------------------------------------------------------------------
  /// Labels a facet by its vertex set, whether or not an element holds it now: the label
  /// survives the removal and re-addition of elements around it (a boundary facet keeps its
  /// marker through local modifications that keep the facet). Label 0 clears it. Labels are
  /// not cleared when a vertex is removed: clear them first if the vertex slot will be reused.
  void set_facet_label(const Facet& f, Label label);
  /// The label set for this facet (any orientation), 0 if none was.
  Label facet_label(const Facet& f) const;

  FacetTableStats facet_table_stats() const noexcept {
    return FacetTableStats{lookups_, facets_.key_eq().comparisons};
  }
  void reserve(std::size_t vertices, std::size_t elements);

  static Key key_of(const Facet& f) noexcept;

 private:
  struct FacetHolder {
    ElementId element;
    int local = 0;
  };

  void check_live(VertexId v) const;
  void check_live(ElementId e) const;
  void check_new_vertices(const Element& vertices) const;
  static Key facet_key(const Element& vertices, int i) noexcept;
  ElementId take_element_slot();
  void count_lookup() const noexcept;
  FacetHolder* find_holder(const Key& key);
  const FacetHolder* find_holder(const Key& key) const;
  ElementId& neighbour_slot(ElementId e, int i) noexcept;
  void unlink_facet(ElementId e, const Element& vertices, int i);
  void refresh_hint_after_removal(ElementId removed, VertexId v);
  int local_vertex(ElementId e, VertexId v) const noexcept;

  std::vector<double> coordinates_;
  std::vector<std::uint8_t> vertex_live_;
  std::vector<std::uint32_t> vertex_degree_;
  std::vector<ElementId> vertex_hint_;
  std::vector<VertexId> free_vertices_;
  std::size_t live_vertices_ = 0;

  std::vector<VertexId> element_vertices_;
  std::vector<ElementId> neighbours_;
  std::vector<Label> element_labels_;
  std::vector<std::uint8_t> element_live_;
  std::vector<ElementId> free_elements_;
  std::size_t live_elements_ = 0;

  std::unordered_map<Key, FacetHolder, FacetKeyHash, CountingFacetKeyEqual> facets_;
  std::unordered_map<Key, Label, FacetKeyHash> facet_labels_;
  std::vector<std::uint32_t> labelled_facets_at_;  // per vertex slot: its facets in facet_labels_
  mutable std::uint64_t lookups_ = 0;
};

using TriangleMesh2 = SimplexMesh<2, 2>;
using SurfaceMesh3 = SimplexMesh<3, 2>;
using TetrahedralMesh3 = SimplexMesh<3, 3>;

extern template class SimplexMesh<2, 2>;
extern template class SimplexMesh<3, 2>;
extern template class SimplexMesh<3, 3>;

}  // namespace certimesh::topology
