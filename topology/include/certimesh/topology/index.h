// Typed 0-based indices of the mesh model. A vertex id and an element id are different types
// so that one cannot be passed where the other is meant; the all-ones value is the typed
// "none" sentinel (the monograph's Fortran code uses 0 = null with 1-based arrays).
#pragma once

#include <compare>
#include <cstdint>
#include <functional>
#include <limits>

namespace certimesh::topology {

template <class Tag>
struct Id {
  std::uint32_t value = std::numeric_limits<std::uint32_t>::max();

  static constexpr Id none() noexcept { return Id{}; }
  constexpr bool is_none() const noexcept { return value == std::numeric_limits<std::uint32_t>::max(); }
  friend constexpr auto operator<=>(const Id&, const Id&) = default;
};

struct VertexTag {};
struct ElementTag {};

using VertexId = Id<VertexTag>;
using ElementId = Id<ElementTag>;

/// The neighbour across a facet that no element shares: a boundary (open) facet.
inline constexpr ElementId no_element = ElementId::none();
inline constexpr VertexId no_vertex = VertexId::none();

}  // namespace certimesh::topology
