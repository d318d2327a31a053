// The SVG picture: one closed path per triangle and one line per segment, every drawn point
// inside the picture, and refusals for what it cannot draw.
#include <gtest/gtest.h>

#include <cstdlib>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "certimesh/io/format_error.h"
#include "certimesh/io/svg_cut_3.h"
#include "certimesh/io/svg_picture.h"

namespace {

using certimesh::io::MeshData;

MeshData two_triangles() {
  MeshData m;
  m.dimension = 2;
  m.coordinates = {0, 0, 2, 0, 2, 1, 0, 1};
  m.triangles = {0, 1, 2, 0, 2, 3};
  m.triangle_labels = {1, 2};
  m.segments = {0, 1, 1, 2, 2, 3, 3, 0};
  return m;
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(SvgPicture, OneShapePerTriangleAndSegment) {
  const std::string svg = certimesh::io::svg_picture(two_triangles());
  EXPECT_EQ(count(svg, "<path "), 2u);
  EXPECT_EQ(count(svg, "<line "), 4u);
  EXPECT_EQ(svg.rfind("</svg>"), svg.size() - 7);
}

TEST(SvgPicture, EveryPointIsInsideThePicture) {
  certimesh::io::SvgOptions options;
  options.width_px = 400;
  const std::string svg = certimesh::io::svg_picture(two_triangles(), options);
  // Aspect ratio 2:1, so the picture is 400 x 200 (plus a margin).
  const std::regex number(R"((x1|y1|x2|y2)=\"(-?[0-9.]+)\")");
  for (auto it = std::sregex_iterator(svg.begin(), svg.end(), number); it != std::sregex_iterator(); ++it) {
    const double v = std::atof((*it)[2].str().c_str());
    EXPECT_GE(v, 0.0);
    EXPECT_LE(v, (*it)[1].str()[0] == 'x' ? 400.0 : 200.0);
  }
}

TEST(SvgPicture, RefusesWhatItCannotDraw) {
  MeshData m = two_triangles();
  m.triangles[4] = 9;
  EXPECT_THROW(certimesh::io::svg_picture(m), certimesh::io::FormatError);
  MeshData space = two_triangles();
  space.dimension = 3;
  EXPECT_THROW(certimesh::io::svg_picture(space), certimesh::io::FormatError);
}

}  // namespace

// The cut of tetrahedra by a plane: the corner tetrahedron at z = 1/2 is one triangle (one
// corner below) with three boundary segments; a tetrahedron with two corners on each side
// is a quadrilateral (two triangles) with four; the fill follows the given values.
MeshData one_tetrahedron(std::vector<double> coordinates) {
  MeshData m;
  m.dimension = 3;
  m.coordinates = std::move(coordinates);
  m.tetrahedra = {0, 1, 2, 3};
  return m;
}

TEST(SvgCutPicture, CutPolygonsAndBoundaryTrace) {
  const MeshData corner = one_tetrahedron({0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1});
  const std::string one = certimesh::io::svg_cut_picture(corner, 0.5, {1.0});
  EXPECT_EQ(count(one, "<path "), 1u);
  EXPECT_EQ(count(one, "<line "), 3u);
  EXPECT_EQ(count(one, "rgb(0,200,90)"), 1u);  // value 1: green
  const MeshData two_two = one_tetrahedron({0, 0, 0, 1, 0, 0, 0, 1, 1, 0, 0, 1});
  const std::string quad = certimesh::io::svg_cut_picture(two_two, 0.5, {0.0});
  EXPECT_EQ(count(quad, "<path "), 2u);
  EXPECT_EQ(count(quad, "<line "), 4u);
  EXPECT_EQ(count(quad, "rgb(255,0,90)"), 2u);  // value 0: red
  EXPECT_EQ(count(certimesh::io::svg_cut_picture(corner, 2.0, {1.0}), "<path "), 0u);  // above it all
  EXPECT_DOUBLE_EQ(certimesh::io::middle_z(corner), 0.5);
  EXPECT_THROW(certimesh::io::svg_cut_picture(corner, 0.5, {}), certimesh::io::FormatError);
  EXPECT_THROW(certimesh::io::svg_cut_picture(two_triangles(), 0.5, {}), certimesh::io::FormatError);
}
