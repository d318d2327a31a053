#include "domain_text.h"

#include "certimesh/io/mesh_file.h"

namespace certimesh::generators::detail {

std::string point_text(const Point2& p) {
  std::string text = "(";
  io::append_double(text, p.x);
  text += ' ';
  io::append_double(text, p.y);
  text += ')';
  return text;
}

std::string segment_text(const PlanarDomain& domain, std::uint32_t segment) {
  const DomainSegment& s = domain.segments[segment];
  return std::to_string(segment) + " " + point_text(domain.points[s.a]) + "-" +
         point_text(domain.points[s.b]);
}

std::string id_list_text(const std::vector<std::uint32_t>& ids) {
  std::string text;
  for (std::size_t i = 0; i < ids.size(); ++i) {
    if (i > 0) text += (i + 1 == ids.size()) ? " and " : ", ";
    text += std::to_string(ids[i]);
  }
  return text;
}

}  // namespace certimesh::generators::detail
