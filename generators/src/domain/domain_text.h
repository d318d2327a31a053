// How domain problems name points and segments: coordinates printed as the shortest decimal
// that reads back bit for bit (io::append_double), so a message can be pasted into a file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "certimesh/generators/domain/planar_domain.h"

namespace certimesh::generators::detail {

/// "(x y)".
std::string point_text(const Point2& p);

/// "3 (x0 y0)-(x1 y1)": a segment id and its end coordinates (ends must be in range).
std::string segment_text(const PlanarDomain& domain, std::uint32_t segment);

/// "2 and 9", "2, 9 and 11".
std::string id_list_text(const std::vector<std::uint32_t>& ids);

}  // namespace certimesh::generators::detail
