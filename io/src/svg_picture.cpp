#include "certimesh/io/svg_picture.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "certimesh/io/format_error.h"
#include "certimesh/io/mesh_file.h"

namespace certimesh::io {

namespace {

struct Frame {  // world -> picture: y flipped so the picture looks like the plot
  double min_x, max_y, scale;
  double x(double wx) const { return (wx - min_x) * scale; }
  double y(double wy) const { return (max_y - wy) * scale; }
};

Frame frame_of(const MeshData& mesh, double width_px, double& height_px) {
  double min_x = std::numeric_limits<double>::max(), min_y = min_x;
  double max_x = -min_x, max_y = -min_x;
  for (std::size_t i = 0; i + 1 < mesh.coordinates.size(); i += 2) {
    min_x = std::min(min_x, mesh.coordinates[i]);
    max_x = std::max(max_x, mesh.coordinates[i]);
    min_y = std::min(min_y, mesh.coordinates[i + 1]);
    max_y = std::max(max_y, mesh.coordinates[i + 1]);
  }
  if (mesh.coordinates.empty()) min_x = min_y = max_x = max_y = 0.0;
  const double extent = std::max(max_x - min_x, max_y - min_y);
  const double scale = extent > 0.0 && std::isfinite(extent) ? width_px / std::max(max_x - min_x, extent * 1e-3) : 1.0;
  height_px = std::max(1.0, (max_y - min_y) * scale);
  return Frame{min_x, max_y, scale};
}

// A fixed palette of distinguishable pastel fills, one per region label.
const char* region_fill(Label label) {
  static constexpr std::array<const char*, 8> palette = {"#cfe2f3", "#d9ead3", "#fff2cc", "#f4cccc",
                                                         "#d9d2e9", "#fce5cd", "#d0e0e3", "#ead1dc"};
  const auto index = static_cast<std::size_t>((label % 8 + 8) % 8);
  return palette[index];
}

double triangle_quality(const std::array<double, 6>& p) {
  const double area = 0.5 * std::fabs((p[2] - p[0]) * (p[5] - p[1]) - (p[3] - p[1]) * (p[4] - p[0]));
  const double perimeter = std::hypot(p[2] - p[0], p[3] - p[1]) + std::hypot(p[4] - p[2], p[5] - p[3]) +
                           std::hypot(p[0] - p[4], p[1] - p[5]);
  return perimeter > 0.0 ? 12.0 * std::sqrt(3.0) * area / (perimeter * perimeter) : 0.0;
}

void append(std::string& out, const char* format, double a, double b) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, a, b);
  out += buffer;
}

}  // namespace

std::string svg_picture(const MeshData& mesh, const SvgOptions& options) {
  if (mesh.dimension != 2) throw FormatError("svg", 0, "an SVG picture needs a 2D mesh");
  if (options.fill_values && options.fill_values->size() != mesh.triangle_count())
    throw FormatError("svg", 0, "the fill values are not one per triangle");
  for (const Index v : mesh.triangles) {
    if (v >= mesh.point_count()) throw FormatError("svg", 0, "a triangle names vertex " + std::to_string(v) + ", out of range");
  }
  for (const Index v : mesh.segments) {
    if (v >= mesh.point_count()) throw FormatError("svg", 0, "a segment names vertex " + std::to_string(v) + ", out of range");
  }
  double height = 0.0;
  const Frame f = frame_of(mesh, options.width_px, height);
  const double margin = 4.0;
  std::string out;
  out += "<svg xmlns=\"http://www.w3.org/2000/svg\" ";
  append(out, "width=\"%.0f\" height=\"%.0f\" ", options.width_px + 2 * margin, height + 2 * margin);
  append(out, "viewBox=\"%.1f %.1f ", -margin, -margin);
  append(out, "%.1f %.1f\">\n", options.width_px + 2 * margin, height + 2 * margin);
  out += "<g stroke=\"#333\" stroke-width=\"0.3\" stroke-linejoin=\"round\">\n";
  for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
    std::array<double, 6> p{};
    for (int i = 0; i < 3; ++i) {
      const Index v = mesh.triangles[3 * t + static_cast<std::size_t>(i)];
      p[static_cast<std::size_t>(2 * i)] = mesh.coordinates[2 * static_cast<std::size_t>(v)];
      p[static_cast<std::size_t>(2 * i + 1)] = mesh.coordinates[2 * static_cast<std::size_t>(v) + 1];
    }
    out += "<path d=\"M";
    for (int i = 0; i < 3; ++i) {
      append(out, "%.2f %.2f ", f.x(p[static_cast<std::size_t>(2 * i)]), f.y(p[static_cast<std::size_t>(2 * i + 1)]));
    }
    out += "Z\" fill=\"";
    if (options.fill_values || options.colour_by_quality) {
      const double q = std::clamp(options.fill_values ? (*options.fill_values)[t] : triangle_quality(p), 0.0, 1.0);
      append(out, "rgb(%.0f,%.0f,90)", 255.0 * (1.0 - q), 200.0 * q);
    } else {
      out += region_fill(mesh.triangle_labels.empty() ? 0 : mesh.triangle_labels[t]);
    }
    out += "\"/>\n";
  }
  out += "</g>\n<g stroke=\"#000\" stroke-width=\"1.6\" stroke-linecap=\"round\">\n";
  for (std::size_t s = 0; s < mesh.segment_count(); ++s) {
    const std::size_t a = 2 * static_cast<std::size_t>(mesh.segments[2 * s]);
    const std::size_t b = 2 * static_cast<std::size_t>(mesh.segments[2 * s + 1]);
    append(out, "<line x1=\"%.2f\" y1=\"%.2f\" ", f.x(mesh.coordinates[a]), f.y(mesh.coordinates[a + 1]));
    append(out, "x2=\"%.2f\" y2=\"%.2f\"/>\n", f.x(mesh.coordinates[b]), f.y(mesh.coordinates[b + 1]));
  }
  out += "</g>\n</svg>\n";
  return out;
}

void write_svg_picture(const MeshData& mesh, const std::filesystem::path& path, const SvgOptions& options) {
  write_file_atomically(path, svg_picture(mesh, options));
}

}  // namespace certimesh::io
