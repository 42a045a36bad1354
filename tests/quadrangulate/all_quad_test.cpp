// --all-quad: the meshes the path search refused (a left triangle among input polygons, a
// prism's caps, pentagons among quads, faces enclosed by a non-manifold edge), a threshold run on
// a shared mesh, and random meshes. Every output is judged by check_quad_result; the minimum by
// its certificate, and where a lower bound follows from the mesh by hand, against that bound.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>
#include <string>

#include "petersen/io/read_mesh.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"
#include "petersen/testing/arbitrary.hpp"
#include "result_check.hpp"
#include "shared_meshes.hpp"

namespace petersen {
namespace {

using testing::check_quad_result;

PolygonMesh mesh_of(std::vector<std::array<double, 3>> positions,
                    std::vector<std::vector<VertexId>> faces) {
  PolygonMesh mesh;
  for (const auto& p : positions) mesh.positions.push_back(p);
  for (const auto& f : faces) mesh.add_face(f);
  return mesh;
}

// Every face a quad but those keep_polygons keeps, and the counts consistent with each other.
void expect_all_quad(const PolygonMesh& mesh, const QuadResult& result,
                     const QuadOptions& options) {
  EXPECT_EQ(check_quad_result(mesh, result, true, false, {}, {}, options.max_corner_deviation), "");
  const QuadStats& s = result.stats;
  for (FaceId o = 0; o < result.mesh.face_count(); ++o) {
    const bool kept = options.keep_polygons && result.sources[o][1] == kNoFace &&
                      mesh.arity(result.sources[o][0]) != 3;
    if (!kept) {
      EXPECT_EQ(result.mesh.arity(o), 4u) << "face " << o;
    }
  }
  EXPECT_EQ(result.mesh.positions.size(), mesh.positions.size() + s.added_vertices);
  EXPECT_EQ(s.added_vertices, s.split_edges + s.centre_vertices);
  EXPECT_LE(s.added_vertices_minimum, s.split_edges);
  if (s.all_quad_certified) {
    EXPECT_EQ(s.split_edges, s.added_vertices_minimum);
  }
  if (options.objective == Objective::pairs) {
    EXPECT_EQ(s.centre_vertices, 0u);
  }
  EXPECT_LE(s.split_quality_median, s.split_quality_p95);
}

// A triangle with an input quad on each side, its outer sides on the boundary: no pair, and no
// pair quad to cross. T = {the triangle} plus the boundary's sink; the nearest boundary edge is
// two edges away (a side of the triangle, then the quad's outer side).
PolygonMesh triangle_among_quads() {
  std::vector<std::array<double, 3>> p = {{0, 0, 0}, {2, 0, 0}, {1, 2, 0}};
  std::vector<std::vector<VertexId>> faces = {{0, 1, 2}};
  for (VertexId k = 0; k < 3; ++k) {
    const VertexId u = k, v = (k + 1) % 3;
    const double dx = p[v][0] - p[u][0], dy = p[v][1] - p[u][1];
    const double length = std::hypot(dx, dy);
    const double nx = dy / length, ny = -dx / length;  // outward, the triangle running CCW
    const auto base = static_cast<VertexId>(p.size());
    p.push_back({p[u][0] + nx, p[u][1] + ny, 0});
    p.push_back({p[v][0] + nx, p[v][1] + ny, 0});
    faces.push_back({v, u, base, VertexId(base + 1)});
  }
  return mesh_of(p, faces);
}

TEST(AllQuad, ALeftTriangleAmongInputQuads) {
  const PolygonMesh mesh = triangle_among_quads();
  const QuadOptions options{.all_quad = true};
  const QuadResult result = quadrangulate(mesh, options);
  EXPECT_EQ(result.stats.triangles_left, 1u);
  expect_all_quad(mesh, result, options);
  EXPECT_TRUE(result.stats.all_quad_certified);
  EXPECT_EQ(result.stats.added_vertices, 2u);
}

// With the quads kept whole the triangle is alone, and its three sides can change nothing: the
// refusal is the parity proof, and names the option that makes it so.
TEST(AllQuad, KeepPolygonsMayMakeItImpossibleAndSaysSo) {
  const PolygonMesh mesh = triangle_among_quads();
  try {
    quadrangulate(mesh, {.all_quad = true, .keep_polygons = true});
    ADD_FAILURE() << "no refusal";
  } catch (const MeshError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("--all-quad"), std::string::npos) << message;
    EXPECT_NE(message.find("--keep-polygons"), std::string::npos) << message;
    EXPECT_NE(message.find("input face 0"), std::string::npos) << message;
  }
}

// A closed triangular prism with `rows` rows of quads: its caps are the only triangles, and
// they are rows + 1 dual edges apart, which bounds any T-join from below.
PolygonMesh prism(std::uint32_t rows) {
  std::vector<std::array<double, 3>> p;
  std::vector<std::vector<VertexId>> faces;
  for (std::uint32_t r = 0; r <= rows; ++r)
    for (int j = 0; j < 3; ++j) {
      const double angle = 2 * M_PI * j / 3;
      p.push_back({std::cos(angle), std::sin(angle), double(r)});
    }
  faces.push_back({0, 2, 1});
  for (VertexId r = 0; r < rows; ++r)
    for (VertexId j = 0; j < 3; ++j) {
      const VertexId k = (j + 1) % 3;
      faces.push_back({3 * r + j, 3 * r + k, 3 * (r + 1) + k, 3 * (r + 1) + j});
    }
  faces.push_back({3 * rows, 3 * rows + 1, 3 * rows + 2});
  return mesh_of(p, faces);
}

TEST(AllQuad, APrismsCapsAreJoinedThroughItsQuads) {
  for (std::uint32_t rows : {1u, 2u, 5u}) {
    SCOPED_TRACE(rows);
    const PolygonMesh mesh = prism(rows);
    for (Objective objective : {Objective::pairs, Objective::quality}) {
      const QuadOptions options{.objective = objective, .all_quad = true};
      const QuadResult result = quadrangulate(mesh, options);
      EXPECT_EQ(result.stats.triangles_left, 2u);
      expect_all_quad(mesh, result, options);
      EXPECT_TRUE(result.stats.all_quad_certified);
      EXPECT_EQ(result.stats.split_edges, rows + 1);
      EXPECT_EQ(result.stats.added_vertices_minimum, rows + 1);
    }
  }
}

// A grid of quads with a vertex inserted on an inner edge (two pentagons side by side) and on a
// boundary edge (one pentagon): three odd faces and an odd sink, so at least two splits.
PolygonMesh grid_with_pentagons() {
  constexpr VertexId n = 5;
  std::vector<std::array<double, 3>> p;
  for (VertexId y = 0; y <= n; ++y)
    for (VertexId x = 0; x <= n; ++x) p.push_back({double(x), double(y), 0});
  const auto inner = static_cast<VertexId>(p.size());
  p.push_back({1.5, 2, 0});  // on the edge between cells (1, 1) and (1, 2)
  const VertexId outer = inner + 1;
  p.push_back({3.5, 0, 0});  // on the bottom side of cell (3, 0)
  std::vector<std::vector<VertexId>> faces;
  for (VertexId y = 0; y < n; ++y)
    for (VertexId x = 0; x < n; ++x) {
      const VertexId a = (n + 1) * y + x, b = a + 1, c = b + n + 1, d = a + n + 1;
      if (x == 1 && y == 1) {
        faces.push_back({a, b, c, inner, d});
      } else if (x == 1 && y == 2) {
        faces.push_back({a, inner, b, c, d});
      } else if (x == 3 && y == 0) {
        faces.push_back({a, outer, b, c, d});
      } else {
        faces.push_back({a, b, c, d});
      }
    }
  return mesh_of(p, faces);
}

TEST(AllQuad, PentagonsAmongQuads) {
  const PolygonMesh mesh = grid_with_pentagons();
  const QuadOptions options{.all_quad = true};
  const QuadResult result = quadrangulate(mesh, options);
  expect_all_quad(mesh, result, options);
  EXPECT_TRUE(result.stats.all_quad_certified);
  EXPECT_EQ(result.stats.added_vertices, 2u);
  // Kept whole, the polygons leave nothing to split: the output is the input.
  const QuadResult kept = quadrangulate(mesh, {.all_quad = true, .keep_polygons = true});
  EXPECT_EQ(kept.mesh.corners, mesh.corners);
  EXPECT_EQ(kept.stats.added_vertices, 0u);
  EXPECT_TRUE(kept.stats.all_quad_certified);
}

// Even polygons are cut by a fan of quads, no vertex added; an odd one takes one midpoint on the
// boundary. A polygon of many sides tries a few fans only, and still ends as s/2 − 1 quads.
TEST(AllQuad, PolygonsAreFannedWithoutNewVertices) {
  for (std::uint32_t sides : {6u, 7u, 1000u, 1001u}) {
    SCOPED_TRACE(sides);
    std::vector<std::array<double, 3>> p;
    std::vector<VertexId> polygon;
    for (std::uint32_t k = 0; k < sides; ++k) {
      const double angle = 2 * M_PI * k / sides;
      p.push_back({std::cos(angle), std::sin(angle), 0});
      polygon.push_back(k);
    }
    const PolygonMesh mesh = mesh_of(p, {polygon});
    const QuadOptions options{.all_quad = true};
    const QuadResult result = quadrangulate(mesh, options);
    expect_all_quad(mesh, result, options);
    EXPECT_TRUE(result.stats.all_quad_certified);
    EXPECT_EQ(result.stats.added_vertices, sides % 2);
    EXPECT_EQ(result.mesh.face_count(), (sides + sides % 2) / 2 - 1);
  }
}

// Three triangles on one edge, every other side of each bordered by a quad. With the quads kept
// each triangle is alone with an odd side count: only the non-manifold edge, whose midpoint all
// three take, makes them even (and the minimum is then not certified as a T-join alone).
PolygonMesh triangles_on_one_edge_among_quads() {
  std::vector<std::array<double, 3>> p = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
  std::vector<std::vector<VertexId>> faces = {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}};
  for (std::size_t t = 0; t < 3; ++t) {
    const std::vector<VertexId> triangle = faces[t];
    for (int k = 1; k < 3; ++k) {  // sides 1 and 2; side 0 is the shared edge
      const VertexId u = triangle[k], v = triangle[(k + 1) % 3];
      const auto base = static_cast<VertexId>(p.size());
      std::array<double, 3> out{};
      for (int d = 0; d < 3; ++d) out[d] = p[triangle[(k + 2) % 3]][d];
      for (VertexId w : {u, v}) {
        std::array<double, 3> q;
        for (int d = 0; d < 3; ++d) q[d] = 2 * p[w][d] - out[d];  // away from the third corner
        p.push_back(q);
      }
      faces.push_back({v, u, base, VertexId(base + 1)});
    }
  }
  return mesh_of(p, faces);
}

TEST(AllQuad, ANonManifoldEdgeFixesTheFacesItEncloses) {
  const PolygonMesh mesh = triangles_on_one_edge_among_quads();
  const QuadOptions keep{.all_quad = true, .keep_polygons = true};
  const QuadResult kept = quadrangulate(mesh, keep);
  EXPECT_EQ(kept.stats.triangles_left, 3u);
  expect_all_quad(mesh, kept, keep);
  EXPECT_EQ(kept.stats.added_vertices, 1u);
  EXPECT_EQ(kept.stats.added_vertices_minimum, 1u);
  EXPECT_FALSE(kept.stats.all_quad_certified);
  // Without keep_polygons each triangle reaches the boundary through its quads: two splits each.
  // One split of the shared edge would do, which the T-join over edges of two faces cannot see:
  // so the run does not claim its six splits are the fewest.
  // (The pairs objective: the cost objectives may add a centre where a crossed quad is better.)
  const QuadOptions split{.objective = Objective::pairs, .all_quad = true};
  const QuadResult result = quadrangulate(mesh, split);
  expect_all_quad(mesh, result, split);
  EXPECT_FALSE(result.stats.all_quad_certified);
  EXPECT_EQ(result.stats.added_vertices, 6u);
}

// A threshold run leaves many triangles scattered among quads the threshold refused: every run
// ends all quads, at the certified minimum (Objective::pairs) or with centres counted apart.
TEST(AllQuad, ThresholdRunOnASharedMesh) {
  const auto dir = testing::shared_mesh_dir();
  if (!dir) GTEST_SKIP() << "no ../shared/meshes (set PETERSEN_SHARED_MESHES)";
  PolygonMesh mesh = read_mesh(*dir + "/fandisk.obj.gz");
  mesh.attributes = {};
  for (Objective objective : {Objective::pairs, Objective::quality}) {
    const QuadOptions options{
        .objective = objective, .all_quad = true, .max_corner_deviation = 30.0};
    const QuadResult result = quadrangulate(mesh, options);
    EXPECT_GT(result.stats.triangles_left, 100u);
    expect_all_quad(mesh, result, options);
    EXPECT_TRUE(result.stats.all_quad_certified);
    EXPECT_EQ(result.stats.split_edges, result.stats.added_vertices_minimum);
    // Every triangle left gets at least one midpoint, each midpoint serves at most two of them.
    EXPECT_GE(2 * result.stats.split_edges, result.stats.triangles_left);
  }
}

// Random meshes of every kind: all quads unless parity proves it impossible (then the message
// says so), the counts consistent and the T-join certified.
RC_GTEST_PROP(AllQuad, EveryMeshAllQuadsOrAParityProof, ()) {
  const PolygonMesh mesh = *testing::mixed_meshes();
  const QuadOptions options{.objective = *rc::gen::element(Objective::pairs, Objective::quality),
                            .all_quad = true,
                            .keep_polygons = *rc::gen::arbitrary<bool>()};
  QuadResult result;
  try {
    result = quadrangulate(mesh, options);
  } catch (const MeshError& e) {
    const std::string message = e.what();
    RC_ASSERT(message.find("--all-quad") != std::string::npos);
    RC_TAG(
        message.find("repeats a vertex") != std::string::npos ? "repeats a vertex" : "parity proof",
        options.keep_polygons ? "polygons kept" : "polygons split");
    return;
  }
  RC_ASSERT(check_quad_result(mesh, result, true, false) == "");
  const QuadStats& s = result.stats;
  RC_ASSERT(result.mesh.positions.size() == mesh.positions.size() + s.added_vertices);
  RC_ASSERT(s.added_vertices == s.split_edges + s.centre_vertices);
  RC_ASSERT(s.added_vertices_minimum <= s.split_edges);
  RC_ASSERT(s.all_quad_certified || s.added_vertices_minimum > 0);
  if (s.all_quad_certified) RC_ASSERT(s.split_edges == s.added_vertices_minimum);
  RC_TAG(s.all_quad_certified ? "certified" : "non-manifold splits");
}

}  // namespace
}  // namespace petersen
