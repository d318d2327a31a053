// `certimesh convert` and `certimesh check`: file formats and the certificate, for a person.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <optional>
#include <string>
#include <system_error>

#include "certimesh/certificate/check_mesh.h"
#include "certimesh/io/format_error.h"
#include "certimesh/io/mesh_file.h"
#include "cli.h"

#ifndef CERTIMESH_VERSION
#define CERTIMESH_VERSION "unknown"
#endif

namespace certimesh::cli {

namespace {

// Reads a mesh, or prints `error: FILE:LINE: why` and returns nullopt.
std::optional<io::MeshData> read_or_report(const std::string& path) {
  try {
    return io::read_mesh(path);
  } catch (const io::FormatError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "error: %s: out of memory while reading\n", path.c_str());
  }
  return std::nullopt;
}

void print_statistics(const certificate::Statistics& s) {
  std::printf("%dD mesh: %zu vertices, %zu elements, %zu interior and %zu boundary facets, "
              "%zu boundary component(s)\n",
              s.dimension, s.vertices, s.elements, s.interior_facets, s.boundary_facets,
              s.boundary_components);
  if (s.elements > 0) {
    std::printf("worst quality %.6g (element %lld)\n", s.worst_quality,
                static_cast<long long>(s.worst_element));
  }
  if (s.vertices_exactly_on_domain_boundary + s.vertices_in_rounding_box_only > 0) {
    const bool tolerant = s.boundary_tolerance.active();
    std::printf("boundary vertices on the domain boundary: %zu exactly, %zu within %s "
                "(largest deviation %.3g)\n",
                s.vertices_exactly_on_domain_boundary, s.vertices_in_rounding_box_only,
                tolerant ? "the boundary tolerance" : "half an ulp", s.max_boundary_deviation);
    if (s.dimension == 2 && s.domain_measure != 0)  // computed: the check reached the segment chains
      std::printf("area %.17g, the domain's %.17g: difference %.3g, at most %.3g by the boundary "
                  "vertices' deviations\n", s.measure, s.domain_measure, s.measure_difference,
                  s.measure_difference_bound);
    if (tolerant && s.vertices_in_rounding_box_only > 0)
      std::printf("the mesh tiles exactly the %s through its own boundary vertices, which lie "
                  "within %.3g of the domain's boundary\n",
                  s.dimension == 2 ? "polygon" : "polyhedron", s.max_boundary_deviation);
  }
}

// A .node mesh has its elements in the .ele beside it; without one the reader would see a
// point set, and the checker would report "no elements" instead of the missing file.
bool elements_file_missing(const std::string& mesh) {
  const std::filesystem::path path(mesh);
  if (path.extension() != ".node") return false;
  const std::filesystem::path ele = std::filesystem::path(path).replace_extension(".ele");
  std::error_code ec;
  if (std::filesystem::exists(ele, ec)) return false;
  std::fprintf(stderr, "error: %s: no such file (the elements of %s are read from it)\n",
               ele.string().c_str(), mesh.c_str());
  return true;
}

}  // namespace

bool parse_boundary_tolerance(std::string_view text, certificate::BoundaryTolerance& out) {
  const bool ulps = text.ends_with("ulp") || text.ends_with("ulps");
  const std::string number(text.substr(0, ulps ? text.rfind("ulp") : text.size()));
  char* end = nullptr;
  const double value = std::strtod(number.c_str(), &end);
  if (number.empty() || end != number.c_str() + number.size() || !std::isfinite(value) || !(value > 0)) return false;
  (ulps ? out.ulps : out.absolute) = value;
  return true;
}

bool output_extension_supported(const std::string& path, std::string_view supported) {
  const std::string ext = std::filesystem::path(path).extension().string();
  // Whole words of `supported` only: ".me" must not match inside ".mesh".
  for (std::string_view rest = supported; !rest.empty();) {
    const std::size_t end = std::min(rest.find(' '), rest.size());
    if (!ext.empty() && rest.substr(0, end) == ext) return true;
    rest.remove_prefix(std::min(end + 1, rest.size()));
  }
  std::fprintf(stderr, "error: %s: unsupported output extension '%s' (supported: %.*s)\n",
               path.c_str(), ext.c_str(), static_cast<int>(supported.size()), supported.data());
  return false;
}

int run_convert(const std::string& input, const std::string& output) {
  if (!output_extension_supported(output, kMeshInputExtensions)) return 2;
  const std::optional<io::MeshData> mesh = read_or_report(input);
  if (!mesh) return 2;
  try {
    io::write_mesh(*mesh, output);
  } catch (const io::FormatError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return 2;
  }
  return 0;
}

int run_check(const CheckOptions& options) {
  if (elements_file_missing(options.mesh)) return 2;
  const std::optional<io::MeshData> mesh = read_or_report(options.mesh);
  if (!mesh) return 2;
  std::optional<io::MeshData> domain;
  if (!options.domain.empty()) {
    domain = read_or_report(options.domain);
    if (!domain) return 2;
  }
  certificate::Report report;
  try {  // bad geometry is a Finding; only a mesh too large to check, or memory, throws
    certificate::CheckOptions check_options;
    check_options.boundary_tolerance = options.boundary_tolerance;
    report = certificate::check_mesh(*mesh, domain ? &*domain : nullptr, check_options);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "error: %s: %s\n", options.mesh.c_str(), e.what());
    return 2;
  }
  print_statistics(report.statistics);
  if (report.valid) {
    std::printf("valid: %s\n", options.domain.empty()
                                   ? "every condition holds; the elements tile the region "
                                     "their boundary encloses exactly once"
                                   : "the elements tile the domain exactly once");
  } else {
    std::printf("invalid: %s: %s\n",
                std::string(certificate::defect_name(report.finding.defect)).c_str(),
                report.finding.message.c_str());
    if (report.finding.defect == certificate::Defect::invalid_domain)  // the user's input, not the mesh
      std::fprintf(stderr, "error: %s: %s\n", options.domain.c_str(), report.finding.message.c_str());
  }
  if (!options.certificate.empty()) {
    try {
      io::write_file_atomically(options.certificate,
                                certificate::certificate_json(report, CERTIMESH_VERSION));
    } catch (const io::FormatError& e) {
      std::fprintf(stderr, "error: %s\n", e.what());
      return 2;
    }
  }
  return report.valid ? 0 : 1;
}

}  // namespace certimesh::cli
