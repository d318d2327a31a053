#include "certimesh/io/mesh_file.h"

#include <charconv>
#include <cstdio>
#include <fstream>
#include <optional>
#include <system_error>

#include "certimesh/io/format_error.h"
#include "certimesh/io/gmsh_format.h"
#include "certimesh/io/medit_format.h"
#include "certimesh/io/off_format.h"
#include "certimesh/io/stl_format.h"
#include "certimesh/io/triangle_format.h"
#include "certimesh/io/vtu_format.h"

namespace certimesh::io {

Format format_of(const std::filesystem::path& path) {
  const std::string ext = path.extension().string();
  if (ext == ".node" || ext == ".ele" || ext == ".face" || ext == ".poly" || ext == ".smesh") return Format::triangle;
  if (ext == ".mesh") return Format::medit;
  if (ext == ".msh") return Format::gmsh;
  if (ext == ".vtu") return Format::vtu;
  if (ext == ".off") return Format::off;
  if (ext == ".stl") return Format::stl;
  throw FormatError(path.string(), 0,
                    "unknown mesh format '" + ext +
                        "' (known: .node .ele .face .poly .smesh .mesh .msh .vtu .off .stl)");
}

MeshData read_mesh(const std::filesystem::path& path) {
  switch (format_of(path)) {
    case Format::triangle: return read_triangle_format(path);
    case Format::medit: return read_medit_format(path);
    case Format::gmsh: return read_gmsh_format(path);
    case Format::vtu: return read_vtu_format(path);
    case Format::off: return read_off_format(path);
    case Format::stl: return read_stl_format(path);
  }
  throw FormatError(path.string(), 0, "unreachable format");
}

namespace {

// A facet list whose every facet is one triangle without holes, as boundary triangles (what the
// other formats can hold); nullopt when a facet is anything else.
std::optional<MeshData> facets_as_triangles(const MeshData& mesh) {
  MeshData out = mesh;
  out.facets = {};
  const FacetList& f = mesh.facets;
  for (std::size_t i = 0; i < f.facet_count(); ++i) {
    const std::uint64_t p = f.polygon_begin(i);
    if (f.facet_end[i] != p + 1 || f.polygon_end[p] - f.corner_begin(p) != 3 || f.hole_end[i] != f.hole_begin(i)) return std::nullopt;
    for (std::uint64_t c = f.corner_begin(p); c < f.polygon_end[p]; ++c) out.triangles.push_back(f.corners[c]);
    if (!f.labels.empty()) out.triangle_labels.push_back(f.labels[i]);
  }
  return out;
}

}  // namespace

void write_mesh(const MeshData& mesh, const std::filesystem::path& path) {
  const Format format = format_of(path);
  if (!mesh.facets.empty() && format != Format::triangle) {
    if (!mesh.triangles.empty()) throw FormatError(path.string(), 0, "the domain has both facets and triangles");
    const std::optional<MeshData> triangles = facets_as_triangles(mesh);
    if (!triangles) {
      throw FormatError(path.string(), 0, "the domain's facets are not all triangles: polygonal facets can be written only to a .poly or .smesh file");
    }
    write_mesh(*triangles, path);
    return;
  }
  switch (format) {
    case Format::triangle: write_triangle_format(mesh, path); return;
    case Format::medit: write_medit_format(mesh, path); return;
    case Format::gmsh: write_gmsh_format(mesh, path); return;
    case Format::vtu: write_vtu_format(mesh, path); return;
    case Format::off:
    case Format::stl: throw FormatError(path.string(), 0, "certimesh reads " + path.extension().string() + " surfaces but does not write them (write .mesh, .msh, .vtu or .poly)");
  }
}

void write_file_atomically(const std::filesystem::path& path, const std::string& contents) {
  // The temporary lives in the destination folder so that the rename cannot cross devices.
  std::filesystem::path temporary = path;
  temporary += ".certimesh-partial";
  {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw FormatError(path.string(), 0, "cannot open the file for writing");
    out.write(contents.data(), static_cast<std::streamsize>(contents.size()));
    out.flush();
    if (!out) {
      out.close();
      std::error_code ignored;
      std::filesystem::remove(temporary, ignored);
      throw FormatError(path.string(), 0, "write error (disk full?)");
    }
  }
  std::error_code ec;
  std::filesystem::rename(temporary, path, ec);
  if (ec) {
    std::error_code ignored;
    std::filesystem::remove(temporary, ignored);
    throw FormatError(path.string(), 0, "cannot move the written file into place: " + ec.message());
  }
}

void append_double(std::string& out, double value) {
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  out.append(buffer, result.ptr);
}

}  // namespace certimesh::io
