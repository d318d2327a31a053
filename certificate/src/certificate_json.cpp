// The mesh hash and the JSON certificate. Keys and their order are stable (documented in
// proofs/mesh_certificate.md); numbers use the shortest round-trip decimal.
#include <openssl/evp.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "certimesh/io/mesh_file.h"
#include "stages.h"

namespace certimesh::certificate {
namespace detail {
namespace {

// Bytes fed to SHA-256 in little-endian order whatever the host, through a small buffer.
class Hasher {
 public:
  Hasher() : ctx_(EVP_MD_CTX_new(), EVP_MD_CTX_free) { EVP_DigestInit_ex(ctx_.get(), EVP_sha256(), nullptr); }
  template <class T>
  void put(T value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::big) std::reverse(bytes, bytes + sizeof(T));
    if (used_ + sizeof(T) > sizeof(buffer_)) flush();
    std::memcpy(buffer_ + used_, bytes, sizeof(T));
    used_ += sizeof(T);
  }
  std::string hex() {
    flush();
    unsigned char digest[EVP_MAX_MD_SIZE];
    unsigned int length = 0;
    EVP_DigestFinal_ex(ctx_.get(), digest, &length);
    std::string out;
    char two[3];
    for (unsigned int i = 0; i < length; ++i) std::snprintf(two, sizeof two, "%02x", digest[i]), out += two;
    return out;
  }

 private:
  void flush() {
    EVP_DigestUpdate(ctx_.get(), buffer_, used_);
    used_ = 0;
  }
  std::unique_ptr<EVP_MD_CTX, void (*)(EVP_MD_CTX*)> ctx_;
  unsigned char buffer_[1 << 16];
  std::size_t used_ = 0;
};

}  // namespace

std::string mesh_sha256(const io::MeshData& mesh) {
  const bool solid = mesh.dimension == 3;
  const auto& cells = solid ? mesh.tetrahedra : mesh.triangles;
  const auto& labels = solid ? mesh.tetrahedron_labels : mesh.triangle_labels;
  const std::size_t corners = solid ? 4 : 3, count = cells.size() / corners;
  auto hasher = std::make_unique<Hasher>();
  for (char c : std::string("certimesh-mesh-v1\n")) hasher->put(c);
  hasher->put(static_cast<std::uint32_t>(mesh.dimension));
  hasher->put(static_cast<std::uint64_t>(mesh.point_count()));
  hasher->put(static_cast<std::uint64_t>(count));
  for (double x : mesh.coordinates) hasher->put(x);
  for (std::size_t i = 0; i < count * corners; ++i) hasher->put(static_cast<std::uint32_t>(cells[i]));
  for (std::size_t e = 0; e < count; ++e) hasher->put(static_cast<std::int32_t>(e < labels.size() ? labels[e] : 0));
  return hasher->hex();
}

}  // namespace detail

namespace {

void quoted(std::string& out, const std::string& text) {
  out += '"';
  for (char c : text) {
    if (c == '"' || c == '\\') out += '\\', out += c;
    else if (static_cast<unsigned char>(c) < 0x20) {
      char esc[8];
      std::snprintf(esc, sizeof esc, "\\u%04x", static_cast<unsigned>(c));
      out += esc;
    } else out += c;
  }
  out += '"';
}

void number(std::string& out, double value) {
  if (std::isfinite(value)) io::append_double(out, value);
  else out += "null";
}

}  // namespace

std::string certificate_json(const Report& report, const std::string& certimesh_version) {
  const Statistics& s = report.statistics;
  const Finding& f = report.finding;
  std::string out = "{\n  \"certimesh_version\": ";
  quoted(out, certimesh_version);
  out += ",\n  \"valid\": " + std::string(report.valid ? "true" : "false");
  out += ",\n  \"defect\": ";
  quoted(out, std::string(defect_name(f.defect)));
  out += ",\n  \"location\": {\"element\": " + std::to_string(f.element) + ", \"other\": " +
         std::to_string(f.other) + ", \"vertex\": " + std::to_string(f.vertex) + "}";
  out += ",\n  \"message\": ";
  quoted(out, f.message);
  out += ",\n  \"mesh_sha256\": ";
  quoted(out, report.mesh_sha256);
  out += ",\n  \"statistics\": {\n    \"dimension\": " + std::to_string(s.dimension);
  out += ",\n    \"vertices\": " + std::to_string(s.vertices) + ",\n    \"elements\": " + std::to_string(s.elements);
  out += ",\n    \"interior_facets\": " + std::to_string(s.interior_facets);
  out += ",\n    \"boundary_facets\": " + std::to_string(s.boundary_facets);
  out += ",\n    \"boundary_components\": " + std::to_string(s.boundary_components);
  out += ",\n    \"worst_quality\": ";
  number(out, s.worst_quality);
  out += ",\n    \"worst_element\": " + std::to_string(s.worst_element);
  out += ",\n    \"vertices_exactly_on_domain_boundary\": " + std::to_string(s.vertices_exactly_on_domain_boundary);
  out += ",\n    \"vertices_in_rounding_box_only\": " + std::to_string(s.vertices_in_rounding_box_only);
  out += ",\n    \"max_boundary_deviation\": ";
  number(out, s.max_boundary_deviation);
  out += "\n  }\n}\n";
  return out;
}

}  // namespace certimesh::certificate
