// Flat shading is no seam: a model exported with one normal per face (the most common export)
// pairs as the same mesh without normals, while a hard edge between smooth-shaded triangles, and
// the border between a flat and a smooth triangle, still cut.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <string>

#include "petersen/generators/polygon_generators.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "result_check.hpp"

namespace petersen {
namespace {

using Vec = std::array<double, 3>;

Vec face_normal(const PolygonMesh& mesh, FaceId f) {
  const auto t = mesh.face(f);
  const Vec& a = mesh.positions[t[0]];
  const Vec& b = mesh.positions[t[1]];
  const Vec& c = mesh.positions[t[2]];
  const Vec u = {b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const Vec v = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
  return {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
}

// The mesh as an OBJ exported flat shaded: one `vn` per face, its unit normal written with four
// decimals, every corner of the face naming it.
std::string flat_shaded_obj(const PolygonMesh& mesh) {
  std::string obj;
  char line[128];
  for (const Vec& p : mesh.positions) {
    std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", p[0], p[1], p[2]);
    obj += line;
  }
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    const Vec n = face_normal(mesh, f);
    const double length = std::hypot(n[0], n[1], n[2]);
    std::snprintf(line, sizeof line, "vn %.4f %.4f %.4f\n", n[0] / length, n[1] / length,
                  n[2] / length);
    obj += line;
  }
  for (FaceId f = 0; f < mesh.face_count(); ++f) {
    obj += 'f';
    for (VertexId v : mesh.face(f))
      obj += " " + std::to_string(v + 1) + "//" + std::to_string(f + 1);
    obj += '\n';
  }
  return obj;
}

void expect_pairs_like_without_normals(const PolygonMesh& plain) {
  const PolygonMesh shaded = parse_mesh(flat_shaded_obj(plain), MeshFormat::obj, "flat.obj");
  ASSERT_EQ(shaded.attributes.corner_normal.size(), shaded.corners.size());
  const QuadResult without = quadrangulate(plain);
  const QuadResult with = quadrangulate(shaded);
  EXPECT_EQ(with.stats.cuts.by_cause[int(CutCause::normal_seam)], 0u);
  EXPECT_EQ(with.stats.pairs, without.stats.pairs);
  EXPECT_EQ(with.stats.triangles_left, without.stats.triangles_left);
  EXPECT_EQ(testing::check_quad_result(shaded, with, QuadOptions{}), "");
  EXPECT_EQ(testing::check_attributes_kept(shaded, with), "");
}

TEST(FlatShading, AClosedModelPairsAsWithoutNormals) {
  expect_pairs_like_without_normals(jittered_grid({.nx = 36, .ny = 12, .torus = true}));
}

TEST(FlatShading, AnOpenModelPairsAsWithoutNormals) {
  expect_pairs_like_without_normals(punch_holes(open_grid(20, 14), 3, 2));
}

RC_GTEST_PROP(FlatShading, RandomGridsPairAsWithoutNormals, ()) {
  const auto nx = *rc::gen::inRange<std::uint32_t>(9, 30);
  const auto ny = *rc::gen::inRange<std::uint32_t>(3, nx / 3 + 1);
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const bool torus = *rc::gen::arbitrary<bool>();
  expect_pairs_like_without_normals(
      jittered_grid({.nx = nx, .ny = ny, .jitter = 0.2, .torus = torus, .seed = seed}));
}

// The square (0, 1, 2, 3) cut along 0-2 and folded by lifting vertex 3; normals per corner.
PolygonMesh folded_square(std::vector<Vec> normals, std::vector<std::uint32_t> corner_normal) {
  PolygonMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.5, 0.5, 0.6}};
  for (const std::array<VertexId, 3> t : {std::array<VertexId, 3>{0, 1, 2}, {0, 2, 3}}) {
    mesh.add_face(t);
  }
  mesh.attributes.normals.assign(normals.begin(), normals.end());
  mesh.attributes.corner_normal.assign(corner_normal.begin(), corner_normal.end());
  return mesh;
}

TEST(FlatShading, AHardEdgeBetweenSmoothTrianglesStillCuts) {
  // Each triangle's corners lean 20 degrees off its own normal, and the two sides disagree at
  // the shared edge: smooth shading on both sides of a hard edge.
  const double s = std::sin(20 * M_PI / 180), c = std::cos(20 * M_PI / 180);
  const PolygonMesh mesh = folded_square({{s, 0, c}, {-s, 0, c}}, {0, 0, 0, 1, 1, 1});
  const QuadResult result = quadrangulate(mesh);
  EXPECT_EQ(result.stats.cuts.by_cause[int(CutCause::normal_seam)], 1u);
  EXPECT_EQ(result.stats.triangles_left, 2u);
  EXPECT_EQ(testing::check_quad_result(mesh, result, false, false), "");
}

TEST(FlatShading, AFlatTriangleBesideASmoothOneStillCuts) {
  // Triangle 0 is flat (its normal is +z); triangle 1's corners lean off its own normal.
  const PolygonMesh mesh = folded_square({{0, 0, 1}, {0.3, -0.3, 0.9}}, {0, 0, 0, 1, 1, 1});
  const QuadResult result = quadrangulate(mesh);
  EXPECT_EQ(result.stats.cuts.by_cause[int(CutCause::normal_seam)], 1u);
  EXPECT_EQ(testing::check_quad_result(mesh, result, false, false), "");
  // Both flat: each triangle's one normal is its own, and the two pair.
  const Vec n1 = face_normal(mesh, 1);
  const PolygonMesh both = folded_square({{0, 0, 1}, n1}, {0, 0, 0, 1, 1, 1});
  const QuadResult paired = quadrangulate(both);
  EXPECT_EQ(paired.stats.pairs, 1u);
  EXPECT_EQ(testing::check_quad_result(both, paired, false, false), "");
}

}  // namespace
}  // namespace petersen
