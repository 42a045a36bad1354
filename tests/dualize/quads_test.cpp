#include "petersen/dualize/quads.hpp"

#include <gtest/gtest.h>

#include "petersen/dualize/dual.hpp"
#include "petersen/lemon_peer/lemon_peer.hpp"
#include "petersen/matching/perfect_matching.hpp"

namespace petersen {
namespace {

// An octahedron: 8 triangles, every vertex of degree 4.
TriangleMesh octahedron() {
  TriangleMesh mesh;
  mesh.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  mesh.triangles = {{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                    {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};
  return mesh;
}

TEST(Quads, KeepTheOrientationOfBothTriangles) {
  // Triangles (a, b, c) = (0, 2, 4) and (b, a, d) = (2, 0, 5) share 0-2: quad (a, d, b, c).
  const TriangleMesh mesh = octahedron();
  const Dual dual = build_dual(mesh);
  Matching matching(8);
  for (auto [t1, t2] : {std::pair{0u, 4u}, {1u, 5u}, {2u, 6u}, {3u, 7u}}) {
    for (int k = 0; k < 3; ++k) {
      const EdgeId e = dual.dual_edge(t1, k);
      if (dual.graph.other_end(e, t1) == t2) matching.match(dual.graph, e);
    }
  }
  const QuadMesh quads = quads_from_matching(mesh, dual.graph, matching);
  ASSERT_EQ(quads.quads.size(), 4u);
  EXPECT_EQ(quads.quads[0], (std::array<VertexId, 4>{0, 5, 2, 4}));
  EXPECT_TRUE(check_quad_mesh(mesh, quads).ok()) << check_quad_mesh(mesh, quads).problem;
}

TEST(Quads, LemonMatchingGivesAValidQuadMesh) {
  const TriangleMesh mesh = octahedron();
  const CubicGraph dual = dual_graph(mesh);
  const PerfectMatchingResult result = perfect_matching(
      dual, {.algorithm = Algorithm::lemon, .peer = &lemon_peer::maximum_matching});
  const QuadMesh quads = quads_from_matching(mesh, dual, result.matching);
  EXPECT_EQ(quads.quads.size(), 4u);
  EXPECT_TRUE(check_quad_mesh(mesh, quads).ok()) << check_quad_mesh(mesh, quads).problem;
}

TEST(Quads, ImperfectMatchingIsRefused) {
  const TriangleMesh mesh = octahedron();
  const CubicGraph dual = dual_graph(mesh);
  EXPECT_THROW(quads_from_matching(mesh, dual, Matching(8)), MeshError);
  EXPECT_THROW(quads_from_matching(mesh, dual, Matching(6)), MeshError);
}

TEST(Quads, CheckFindsEachKindOfDefect) {
  const TriangleMesh mesh = octahedron();
  const CubicGraph dual = dual_graph(mesh);
  const QuadMesh good = quads_from_matching(
      mesh, dual,
      perfect_matching(dual, {.algorithm = Algorithm::lemon, .peer = &lemon_peer::maximum_matching})
          .matching);
  auto problem = [&](auto edit) {
    QuadMesh q = good;
    edit(q);
    return check_quad_mesh(mesh, q).problem;
  };
  EXPECT_EQ(problem([](QuadMesh& q) { q.positions[0][0] = 7; }),
            "positions differ from the source's");
  EXPECT_NE(
      problem([](QuadMesh& q) { q.quads[1][2] = q.quads[1][0]; }).find("quad 1 repeats vertex"),
      std::string::npos);
  EXPECT_NE(
      problem([](QuadMesh& q) { q.quads[0][1] = 77; }).find("quad 0 has corner 77 out of range"),
      std::string::npos);
  EXPECT_NE(problem([](QuadMesh& q) { q.quads.pop_back(); }).find("quads (first"),
            std::string::npos);
  EXPECT_NE(problem([](QuadMesh& q) {
              std::swap(q.quads[0][1], q.quads[0][3]);
            }).find("in the same direction"),
            std::string::npos);
  // Two quads over the same four vertices in opposite directions: a closed "pillow" with a
  // different vertex set and Euler characteristic.
  EXPECT_NE(problem([](QuadMesh& q) {
              q.quads = {{0, 2, 1, 3}, {3, 1, 2, 0}};
            }).find("source vertex 4 is in no quad"),
            std::string::npos);
}

}  // namespace
}  // namespace petersen
