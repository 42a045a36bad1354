// Pictures of a known small mesh, read back with cairo: size, not blank, the colours expected
// where the faces are.

#include "petersen/render/render_mesh.hpp"

#include <cairo.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>

#include "petersen/dualize/quad_quality.hpp"

namespace petersen {
namespace {

namespace fs = std::filesystem;

// A square (cost 0), a 60°/120° parallelogram (cost 30) and a triangle, left to right in the
// plane z = 0; the tests mark vertex 10 (the triangle's apex) as added.
PolygonMesh known_mesh() {
  PolygonMesh mesh;
  const double s = 1 / std::sqrt(3.0);
  for (std::array<double, 3> p : {std::array<double, 3>{0, 0, 0},
                                  {1, 0, 0},
                                  {1, 1, 0},
                                  {0, 1, 0},  // square
                                  {1.5, 0, 0},
                                  {2.5, 0, 0},
                                  {2.5 + s, 1, 0},
                                  {1.5 + s, 1, 0},  // parallelogram
                                  {3.5, 0, 0},
                                  {4.5, 0, 0},
                                  {4.0, 1, 0}}) {  // triangle
    mesh.positions.push_back(p);
  }
  mesh.add_face(std::vector<VertexId>{0, 1, 2, 3});
  mesh.add_face(std::vector<VertexId>{4, 5, 6, 7});
  mesh.add_face(std::vector<VertexId>{8, 9, 10});
  return mesh;
}

struct Pixels {
  std::unique_ptr<cairo_surface_t, void (*)(cairo_surface_t*)> surface{nullptr,
                                                                       &cairo_surface_destroy};
  int width = 0, height = 0;
  // The colour at (x, y) as 0..255 channels (ARGB32, opaque).
  std::array<int, 3> at(int x, int y) const {
    const unsigned char* row = cairo_image_surface_get_data(surface.get()) +
                               y * cairo_image_surface_get_stride(surface.get());
    const std::uint32_t argb = reinterpret_cast<const std::uint32_t*>(row)[x];
    return {int(argb >> 16 & 255), int(argb >> 8 & 255), int(argb & 255)};
  }
};

Pixels read_png(const std::string& path) {
  Pixels p;
  p.surface.reset(cairo_image_surface_create_from_png(path.c_str()));
  EXPECT_EQ(cairo_surface_status(p.surface.get()), CAIRO_STATUS_SUCCESS);
  cairo_surface_flush(p.surface.get());
  p.width = cairo_image_surface_get_width(p.surface.get());
  p.height = cairo_image_surface_get_height(p.surface.get());
  return p;
}

std::array<int, 3> bytes(const Rgb& c) {
  return {int(std::lround(c.r * 255)), int(std::lround(c.g * 255)), int(std::lround(c.b * 255))};
}

bool close(const std::array<int, 3>& a, const std::array<int, 3>& b) {
  for (int k = 0; k < 3; ++k) {
    if (std::abs(a[k] - b[k]) > 1) return false;
  }
  return true;
}

// Where the pixels of one colour are, inside the mesh's part of the picture (left of the legend).
struct Region {
  std::uint64_t count = 0;
  double mean_x = 0, mean_y = 0;
};
Region region(const Pixels& p, const std::array<int, 3>& colour, int max_x) {
  Region r;
  for (int y = 0; y < p.height; ++y) {
    for (int x = 0; x < max_x; ++x) {
      if (close(p.at(x, y), colour)) ++r.count, r.mean_x += x, r.mean_y += y;
    }
  }
  if (r.count) r.mean_x /= double(r.count), r.mean_y /= double(r.count);
  return r;
}

class RenderMesh : public ::testing::Test {
 protected:
  fs::path dir = fs::temp_directory_path() / ("petersen-render-" + std::to_string(::getpid()));
  void SetUp() override { fs::create_directories(dir); }
  void TearDown() override { fs::remove_all(dir); }
};

TEST_F(RenderMesh, ColoursEachFaceByItsShapeSeenHeadOn) {
  const std::string path = (dir / "known.png").string();
  RenderOptions options;
  options.width = 900;
  options.height = 400;
  options.view = std::array<double, 3>{0, 0, -1};  // x to the right, y up, faces head-on
  options.first_added_vertex = 10;
  options.caption = {"a square, a parallelogram, a triangle"};
  render_mesh(known_mesh(), path, options);
  const Pixels p = read_png(path);
  ASSERT_EQ(p.width, 900);
  ASSERT_EQ(p.height, 400);
  const int legend_x = 900 - 130;  // the mesh's part of the picture
  // Head-on, a flat face shows its colour exactly (shade 1): the square's, the parallelogram's
  // and the triangle's colours each cover a region, in that order from left to right, with areas
  // in the faces' ratio 1 : 1 : 1/2.
  const Region square = region(p, bytes(quality_colour(0)), legend_x);
  const Region parallelogram = region(p, bytes(quality_colour(30)), legend_x);
  const Region triangle = region(p, bytes(kTriangleColour), legend_x);
  ASSERT_GT(square.count, 1000u);
  EXPECT_NEAR(double(parallelogram.count) / double(square.count), 1.0, 0.1);
  EXPECT_NEAR(double(triangle.count) / double(square.count), 0.5, 0.1);
  EXPECT_LT(square.mean_x, parallelogram.mean_x);
  EXPECT_LT(parallelogram.mean_x, triangle.mean_x);
  EXPECT_NEAR(square.mean_y, parallelogram.mean_y, 3);  // both span the same heights
  EXPECT_GT(triangle.mean_y, square.mean_y);            // a triangle's centroid is low (y down)
  // The added vertex is a dot at the triangle's apex, above the triangle's centroid.
  const Region dot = region(p, bytes(kAddedVertexColour), legend_x);
  EXPECT_GT(dot.count, 5u);
  EXPECT_LT(dot.count, 100u);
  EXPECT_LT(dot.mean_y, triangle.mean_y);
  EXPECT_NEAR(dot.mean_x, triangle.mean_x, 3);
  // The legend: the bar's bands on the right, 0° to 90° and no further, as no quad is non-convex.
  const Region legend_blue(region(p, bytes(quality_colour(0.5)), 900));
  EXPECT_GT(legend_blue.count, 30u);
  EXPECT_GT(legend_blue.mean_x, legend_x);
  EXPECT_GT(region(p, bytes(quality_colour(89.5)), 900).mean_x, legend_x);
  EXPECT_EQ(region(p, bytes(quality_colour(90.5)), 900).count, 0u);
  // The background is white in the corner; the caption has dark pixels at the bottom.
  EXPECT_TRUE(close(p.at(2, 2), {255, 255, 255}));
  std::uint64_t caption_ink = 0;
  for (int y = 400 - 28; y < 400; ++y) {
    for (int x = 0; x < 300; ++x) caption_ink += p.at(x, y)[0] < 128;
  }
  EXPECT_GT(caption_ink, 20u);
}

TEST_F(RenderMesh, TheColourBarCoversANonConvexQuad) {
  PolygonMesh mesh;
  // A dart: the corner at (0.5, 0.5) is reflex, so the quad costs more than 90°.
  for (std::array<double, 3> p :
       {std::array<double, 3>{0, 0, 0}, {2, 0, 0}, {0.5, 0.5, 0}, {0, 2, 0}}) {
    mesh.positions.push_back(p);
  }
  mesh.add_face(std::vector<VertexId>{0, 1, 2, 3});
  const double cost = quad_corner_deviation(mesh.positions[0], mesh.positions[1], mesh.positions[2],
                                            mesh.positions[3]);
  ASSERT_GT(cost, 110);
  const std::string path = (dir / "dart.png").string();
  RenderOptions options;
  options.view = std::array<double, 3>{0, 0, -1};
  render_mesh(mesh, path, options);
  const Pixels p = read_png(path);
  const int legend_x = p.width - 130;
  EXPECT_GT(region(p, bytes(quality_colour(cost)), legend_x).count, 1000u);  // the dart
  // The bar goes on past 90° to the dart's cost: its bands there are in the legend (95° is far
  // enough from the dart's cost for its colour to differ from the dart's).
  const Region beyond = region(p, bytes(quality_colour(95.5)), p.width);
  EXPECT_GT(beyond.count, 10u);
  EXPECT_GT(beyond.mean_x, legend_x);
}

TEST_F(RenderMesh, TrianglesOfAMeshWithoutQuadsArePlainAndThereIsNoLegend) {
  PolygonMesh mesh;
  for (std::array<double, 3> p : {std::array<double, 3>{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}) {
    mesh.positions.push_back(p);
  }
  mesh.add_face(std::vector<VertexId>{0, 1, 2});
  const std::string path = (dir / "triangle.png").string();
  RenderOptions options;
  options.view = std::array<double, 3>{0, 0, 1};  // from behind: lit the same
  render_mesh(mesh, path, options);
  const Pixels p = read_png(path);
  EXPECT_GT(region(p, bytes(kPlainColour), p.width).count, 10000u);
  EXPECT_EQ(region(p, bytes(kTriangleColour), p.width).count, 0u);
  EXPECT_EQ(region(p, bytes(quality_colour(0.5)), p.width).count, 0u);
}

TEST_F(RenderMesh, WritesSvgAndRefusesOtherExtensionsAndBadViews) {
  const std::string svg = (dir / "known.svg").string();
  render_mesh(known_mesh(), svg);
  std::ifstream in(svg);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("<svg"), std::string::npos);
  EXPECT_NE(text.find("path"), std::string::npos);
  EXPECT_THROW(render_mesh(known_mesh(), (dir / "x.jpg").string()), MeshError);
  RenderOptions zero;
  zero.view = std::array<double, 3>{0, 0, 0};
  EXPECT_THROW(render_mesh(known_mesh(), (dir / "x.png").string(), zero), MeshError);
  PolygonMesh bad = known_mesh();
  bad.corners[0] = 99;
  EXPECT_THROW(render_mesh(bad, (dir / "x.png").string()), MeshError);
  EXPECT_THROW(render_mesh(known_mesh(), (dir / "missing-dir" / "x.png").string()), MeshError);
}

}  // namespace
}  // namespace petersen
