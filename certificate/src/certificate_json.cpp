// The mesh hash and the JSON certificate. Keys and their order are stable (documented in
// proofs/mesh_certificate.md); numbers use the shortest round-trip decimal.
#include <openssl/evp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <utility>

#include "certimesh/io/mesh_file.h"
#include "stages.h"

namespace certimesh::certificate {
namespace detail {

std::string mesh_sha256(const io::MeshData& mesh) {
  const std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> ctx(EVP_MD_CTX_new(), EVP_MD_CTX_free);
  EVP_DigestInit_ex(ctx.get(), EVP_sha256(), nullptr);
  std::string buffer = "certimesh-mesh-v1\n";
  auto put = [&](auto value) {  // little-endian whatever the host, through a small buffer
    char bytes[sizeof value];
    std::memcpy(bytes, &value, sizeof value);
    if constexpr (std::endian::native == std::endian::big) std::reverse(bytes, bytes + sizeof value);
    buffer.append(bytes, sizeof value);
    if (buffer.size() >= 65536) EVP_DigestUpdate(ctx.get(), buffer.data(), buffer.size()), buffer.clear();
  };
  const bool solid = mesh.dimension == 3;
  const auto& cells = solid ? mesh.tetrahedra : mesh.triangles;
  const auto& labels = solid ? mesh.tetrahedron_labels : mesh.triangle_labels;
  const std::size_t corners = solid ? 4 : 3, count = cells.size() / corners;
  put(static_cast<std::uint32_t>(mesh.dimension));
  put(static_cast<std::uint64_t>(mesh.point_count()));
  put(static_cast<std::uint64_t>(count));
  // On a little-endian host the arrays already are their canonical bytes (f64, u32, i32): hashed
  // in place instead of copied value by value through the buffer.
  auto array = [&](const auto& values, std::size_t n) {
    if constexpr (std::endian::native == std::endian::little) {
      EVP_DigestUpdate(ctx.get(), buffer.data(), buffer.size()), buffer.clear();
      EVP_DigestUpdate(ctx.get(), values.data(), n * sizeof(values[0]));
    } else {
      for (std::size_t i = 0; i < n; ++i) put(values[i]);
    }
  };
  static_assert(sizeof(double) == 8 && sizeof(io::Index) == 4 && sizeof(io::Label) == 4);
  array(mesh.coordinates, mesh.coordinates.size());
  array(cells, count * corners);
  array(labels, std::min(labels.size(), count));  // labels past the list's end are 0
  for (std::size_t e = labels.size(); e < count; ++e) put(std::int32_t{0});
  EVP_DigestUpdate(ctx.get(), buffer.data(), buffer.size());
  unsigned char digest[EVP_MAX_MD_SIZE];
  unsigned int length = 0;
  EVP_DigestFinal_ex(ctx.get(), digest, &length);
  std::string hex;
  for (unsigned int i = 0; i < length; ++i) hex += "0123456789abcdef"[digest[i] >> 4], hex += "0123456789abcdef"[digest[i] & 15];
  return hex;
}

}  // namespace detail

namespace {

void quoted(std::string& out, const std::string& text) {
  out += '"';
  for (char c : text) {
    char esc[8] = {c, 0};  // control characters as \u00XX, quote and backslash escaped
    if (static_cast<unsigned char>(c) < 0x20) std::snprintf(esc, sizeof esc, "\\u%04x", static_cast<unsigned>(c));
    out += std::string(c == '"' || c == '\\' ? "\\" : "") + esc;
  }
  out += '"';
}

std::string number(double value) {
  std::string out;
  if (std::isfinite(value)) io::append_double(out, value);
  return out.empty() ? "null" : out;
}

}  // namespace

std::string certificate_json(const Report& report, const std::string& certimesh_version) {
  const Statistics& s = report.statistics;
  const Finding& f = report.finding;
  std::string out = "{\n  \"certimesh_version\": ";
  quoted(out, certimesh_version);
  out += ",\n  \"valid\": " + std::string(report.valid ? "true" : "false") + ",\n  \"defect\": ";
  quoted(out, std::string(defect_name(f.defect)));
  out += ",\n  \"location\": {\"element\": " + std::to_string(f.element) + ", \"other\": " +
         std::to_string(f.other) + ", \"vertex\": " + std::to_string(f.vertex) + "},\n  \"message\": ";
  quoted(out, f.message);
  out += ",\n  \"mesh_sha256\": ";
  quoted(out, report.mesh_sha256);
  const std::pair<const char*, std::string> stats[] = {
      {"dimension", std::to_string(s.dimension)},
      {"vertices", std::to_string(s.vertices)},
      {"elements", std::to_string(s.elements)},
      {"interior_facets", std::to_string(s.interior_facets)},
      {"boundary_facets", std::to_string(s.boundary_facets)},
      {"boundary_components", std::to_string(s.boundary_components)},
      {"worst_quality", number(s.worst_quality)},
      {"worst_element", std::to_string(s.worst_element)},
      {"vertices_exactly_on_domain_boundary", std::to_string(s.vertices_exactly_on_domain_boundary)},
      {"vertices_in_rounding_box_only", std::to_string(s.vertices_in_rounding_box_only)},
      {"max_boundary_deviation", number(s.max_boundary_deviation)},
      {"measure", number(s.measure)},
      {"domain_measure", number(s.domain_measure)},
      {"measure_difference", number(s.measure_difference)},
      {"measure_difference_bound", number(s.measure_difference_bound)},
      {"boundary_tolerance_absolute", number(s.boundary_tolerance.absolute)},
      {"boundary_tolerance_ulps", number(s.boundary_tolerance.ulps)}};
  out += ",\n  \"statistics\": {";
  for (const auto& [key, value] : stats) out += std::string(key == stats[0].first ? "\n" : ",\n") + "    \"" + key + "\": " + value;
  return out + "\n  }\n}\n";
}

}  // namespace certimesh::certificate
