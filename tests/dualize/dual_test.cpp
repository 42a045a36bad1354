#include "petersen/dualize/dual.hpp"

#include <gtest/gtest.h>

#include "petersen/generators/surface_generators.hpp"
#include "petersen/graph/connectivity.hpp"

namespace petersen {
namespace {

// A tetrahedron, every face counter-clockwise seen from outside.
TriangleMesh tetrahedron() {
  TriangleMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {0, 3, 2}};
  return mesh;
}

std::string error_of(const TriangleMesh& mesh) {
  try {
    build_dual(mesh);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Dual, TetrahedronIsK4WithMatchingSides) {
  const TriangleMesh mesh = tetrahedron();
  const Dual dual = build_dual(mesh);
  ASSERT_EQ(dual.graph.node_count(), 4u);
  ASSERT_EQ(dual.graph.edge_count(), 6u);
  validate_connected_bridgeless(dual.graph);
  for (FaceId t = 0; t < 4; ++t) {
    for (int k = 0; k < 3; ++k) {
      const EdgeId e = dual.dual_edge(t, k);
      const HalfedgeId h = 3 * t + k;
      const HalfedgeId first = dual.side(e, 0), second = dual.side(e, 1);
      ASSERT_TRUE(h == first || h == second);
      // The two sides are the same mesh edge, run in opposite directions.
      const auto& t1 = mesh.triangles[first / 3];
      const auto& t2 = mesh.triangles[second / 3];
      EXPECT_EQ(t1[first % 3], t2[(second % 3 + 1) % 3]);
      EXPECT_EQ(t1[(first % 3 + 1) % 3], t2[second % 3]);
      EXPECT_EQ(dual.graph.endpoints(e)[0], first / 3);
      EXPECT_EQ(dual.graph.endpoints(e)[1], second / 3);
    }
  }
}

TEST(Dual, PlateOfGenusTwoValidates) {
  const TriangleMesh mesh = voxel_plate({2, 1, 2, false});
  const CubicGraph graph = dual_graph(mesh);
  EXPECT_EQ(graph.node_count(), mesh.triangles.size());
  validate_connected_bridgeless(graph);
}

TEST(Dual, TwoComponentsGiveADisconnectedCubicGraph) {
  TriangleMesh mesh = tetrahedron();
  const TriangleMesh second = tetrahedron();
  for (auto p : second.positions) mesh.positions.push_back(p);
  for (auto t : second.triangles) mesh.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
  EXPECT_EQ(count_components(dual_graph(mesh)), 2u);
}

TEST(Dual, BoundaryEdgeIsNamed) {
  TriangleMesh mesh = tetrahedron();
  mesh.triangles.pop_back();
  EXPECT_NE(error_of(mesh).find("boundary edge (0, 2): only triangle 0 has it"), std::string::npos)
      << error_of(mesh);
}

TEST(Dual, NonManifoldEdgeIsNamed) {
  TriangleMesh mesh = tetrahedron();
  mesh.positions.push_back({1, 1, 1});
  mesh.triangles.push_back({0, 1, 4});
  mesh.triangles.push_back({1, 0, 4});
  const std::string error = error_of(mesh);
  EXPECT_NE(error.find("non-manifold edge (1, 0): in 4 triangles (0, 1, 4, ...)"),
            std::string::npos)
      << error;
}

TEST(Dual, InconsistentOrientationIsNamed) {
  TriangleMesh mesh = tetrahedron();
  mesh.triangles[3] = {0, 2, 3};
  const std::string error = error_of(mesh);
  EXPECT_NE(error.find("inconsistent orientation"), std::string::npos) << error;
  EXPECT_NE(error.find("triangles"), std::string::npos) << error;
}

TEST(Dual, DegenerateAndOutOfRangeTrianglesAreNamed) {
  TriangleMesh mesh = tetrahedron();
  mesh.triangles[2] = {1, 1, 3};
  EXPECT_NE(error_of(mesh).find("triangle 2 is degenerate"), std::string::npos);
  mesh.triangles[2] = {1, 2, 9};
  EXPECT_NE(error_of(mesh).find("triangle 2 has corner 9 out of range"), std::string::npos);
}

}  // namespace
}  // namespace petersen
