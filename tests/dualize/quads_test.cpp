#include <gtest/gtest.h>

#include "peers.hpp"
#include "petersen/dualize/dual.hpp"
#include "quad_mesh_check.hpp"

namespace petersen {
namespace {

using testing::quad_mesh_problem;
using testing::quads_of_matching;

// An octahedron: 8 triangles, every vertex of degree 4.
PolygonMesh octahedron() {
  PolygonMesh mesh;
  mesh.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  mesh.corners = {0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5};
  return mesh;
}

std::array<VertexId, 4> quad(const PolygonMesh& quads, FaceId q) {
  const auto c = quads.face(q);
  return {c[0], c[1], c[2], c[3]};
}

TEST(Quads, KeepTheOrientationOfBothTriangles) {
  // Triangles (a, b, c) = (0, 2, 4) and (b, a, d) = (2, 0, 5) share 0-2: quad (a, d, b, c).
  const PolygonMesh mesh = octahedron();
  const Dual dual = build_dual(mesh);
  Matching matching(8);
  for (auto [t1, t2] : {std::pair{0u, 4u}, {1u, 5u}, {2u, 6u}, {3u, 7u}}) {
    for (int k = 0; k < 3; ++k) {
      const EdgeId e = dual.dual_edge(t1, k);
      if (dual.graph.other_end(e, t1) == t2) matching.match(dual.graph, e);
    }
  }
  const PolygonMesh quads = quads_of_matching(mesh, dual.graph, matching);
  ASSERT_EQ(quads.face_count(), 4u);
  EXPECT_EQ(quad(quads, 0), (std::array<VertexId, 4>{0, 5, 2, 4}));
  EXPECT_EQ(quad_mesh_problem(mesh, quads), "");
}

TEST(Quads, LemonMatchingGivesAValidQuadMesh) {
  const PolygonMesh mesh = octahedron();
  const CubicGraph dual = dual_graph(mesh);
  const PolygonMesh quads = quads_of_matching(mesh, dual, testing::lemon_matching(dual));
  EXPECT_EQ(quads.face_count(), 4u);
  EXPECT_EQ(quad_mesh_problem(mesh, quads), "");
}

TEST(Quads, ImperfectMatchingIsRefused) {
  const PolygonMesh mesh = octahedron();
  const CubicGraph dual = dual_graph(mesh);
  EXPECT_THROW(quads_of_matching(mesh, dual, Matching(8)), MeshError);
  EXPECT_THROW(quads_of_matching(mesh, dual, Matching(6)), MeshError);
}

TEST(Quads, CheckFindsEachKindOfDefect) {
  const PolygonMesh mesh = octahedron();
  const CubicGraph dual = dual_graph(mesh);
  const PolygonMesh good = quads_of_matching(mesh, dual, testing::lemon_matching(dual));
  // Corner k of quad q is corners[4q + k]: every face of `good` has four.
  auto problem = [&](auto edit) {
    PolygonMesh q = good;
    edit(q);
    return quad_mesh_problem(mesh, q);
  };
  EXPECT_EQ(problem([](PolygonMesh& q) { q.positions[0][0] = 7; }),
            "positions differ from the source's");
  EXPECT_NE(
      problem([](PolygonMesh& q) { q.corners[6] = q.corners[4]; }).find("quad 1 repeats vertex"),
      std::string::npos);
  EXPECT_NE(
      problem([](PolygonMesh& q) { q.corners[1] = 77; }).find("quad 0 has corner 77 out of range"),
      std::string::npos);
  EXPECT_NE(problem([](PolygonMesh& q) {
              q.corners.resize(q.corners.size() - 4);
              q.face_start.pop_back();
            }).find("quads (first"),
            std::string::npos);
  EXPECT_NE(problem([](PolygonMesh& q) {
              std::swap(q.corners[1], q.corners[3]);
            }).find("in the same direction"),
            std::string::npos);
  EXPECT_NE(problem([](PolygonMesh& q) {
              PolygonMesh triangle;
              triangle.positions = q.positions;
              triangle.corners = {0, 2, 1};
              q = triangle;
            }).find("face 0 has 3 corners, not 4"),
            std::string::npos);
  // Two quads over the same four vertices in opposite directions: a closed "pillow" with a
  // different vertex set and Euler characteristic.
  EXPECT_NE(problem([](PolygonMesh& q) {
              q.corners = {0, 2, 1, 3, 3, 1, 2, 0};
              q.face_start = {0, 4, 8};
            }).find("source vertex 4 is in no quad"),
            std::string::npos);
}

}  // namespace
}  // namespace petersen
