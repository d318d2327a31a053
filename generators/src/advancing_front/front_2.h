// The front of Algorithm 10: directed edges with the unmeshed region on their left.
//
// Three views of the same set, kept in step by insert/erase:
//   - the edges themselves, in a slot array whose dead slots are reused last-freed first (so
//     the memory follows the front, not the mesh, and ids stay deterministic);
//   - per vertex, the list of its outgoing edges (an intrusive singly linked list): this is
//     the (a, b) -> edge map of the front update rule, and tells whether a vertex is still a
//     front vertex (a closed front has out-degree = in-degree >= 1 at each of its vertices);
//     and the list of its incoming edges, so that both front neighbours of an edge are known;
//   - a binary min-heap on (rank, squared length, a, b) with lazy deletion (an entry is stale when
//     its slot is dead or holds another edge), so the shortest edge is found in O(log n) and
//     ties are broken by vertex ids, never by memory layout.
#pragma once

#include <cstdint>
#include <vector>

#include "certimesh/generators/advancing_front/advancing_front_2.h"

namespace certimesh::generators::advancing_front_detail {

inline constexpr std::uint32_t no_id = 0xffffffffu;

class Front2 {
 public:
  struct Edge {
    std::uint32_t a = 0, b = 0;
    std::uint32_t next_out = no_id;  // next outgoing edge of `a`
    std::uint32_t next_in = no_id;   // next incoming edge of `b`
    bool alive = false;
  };

  void reserve(std::size_t vertices, std::size_t edges);
  /// Makes room for vertex ids below `count`.
  void grow_vertices(std::size_t count);

  /// Adds a -> b; (`rank`, `length2`) is its heap key: the least rank first, then the least
  /// squared length.
  std::uint32_t insert(std::uint32_t a, std::uint32_t b, std::uint32_t rank, double length2);
  void erase(std::uint32_t e);
  /// The live edge a -> b, or no_id.
  std::uint32_t find(std::uint32_t a, std::uint32_t b) const;

  /// The shortest live edge of the least rank (ties: smallest a, then b), or no_id when the
  /// front is empty.
  std::uint32_t shortest();

  bool is_front_vertex(std::uint32_t v) const { return first_out_[v] != no_id; }
  std::uint32_t first_out(std::uint32_t v) const { return first_out_[v]; }
  std::uint32_t first_in(std::uint32_t v) const { return first_in_[v]; }
  const Edge& edge(std::uint32_t e) const { return edges_[e]; }
  std::size_t slot_count() const { return edges_.size(); }
  std::size_t live_count() const { return live_; }

 private:
  struct HeapEntry {  // 24 bytes: the double first, so that no padding is needed
    double length2;
    std::uint32_t rank, a, b, edge;
  };
  // Heap order: the least (rank, length2, a, b) on top.
  static bool after(const HeapEntry& x, const HeapEntry& y) {
    if (x.rank != y.rank) return x.rank > y.rank;
    if (x.length2 != y.length2) return x.length2 > y.length2;
    if (x.a != y.a) return x.a > y.a;
    return x.b > y.b;
  }

  std::vector<Edge> edges_;
  std::vector<std::uint32_t> first_out_, first_in_;
  std::vector<HeapEntry> heap_;
  std::vector<std::uint32_t> free_slots_;
  std::size_t live_ = 0;
};

}  // namespace certimesh::generators::advancing_front_detail
