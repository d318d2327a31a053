// Region labels of generated triangles. The domain triangulation knows the label on the left
// of every front edge; a generated mesh inherits it by a flood fill that starts from the
// triangle on that side and never crosses a boundary or cut edge.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "certimesh/generators/advancing_front/advancing_front_2.h"
#include "certimesh/io/mesh_data.h"

namespace certimesh::generators::detail {

/// One label per triangle. `front[i]` has `front_region[i]` on its left; every front edge
/// blocks the fill. Triangles no seed reaches get `fallback`.
std::vector<io::Label> region_labels(std::span<const std::array<std::uint32_t, 3>> triangles,
                                     std::span<const FrontEdge> front, std::span<const io::Label> front_region,
                                     io::Label fallback);

}  // namespace certimesh::generators::detail
