#include "petersen/dualize/dual.hpp"

#include <gtest/gtest.h>

#include "petersen/generators/surface_generators.hpp"
#include "petersen/graph/connectivity.hpp"

namespace petersen {
namespace {

// A tetrahedron, every face counter-clockwise seen from outside.
PolygonMesh tetrahedron() {
  PolygonMesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  mesh.corners = {0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2};
  return mesh;
}

void set_face(PolygonMesh& mesh, FaceId t, std::array<VertexId, 3> corners) {
  std::copy(corners.begin(), corners.end(), mesh.corners.begin() + 3 * t);
}

std::string error_of(const PolygonMesh& mesh) {
  try {
    build_dual(mesh);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "no error";
}

TEST(Dual, TetrahedronIsK4WithMatchingSides) {
  const PolygonMesh mesh = tetrahedron();
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
      const auto t1 = mesh.face(first / 3);
      const auto t2 = mesh.face(second / 3);
      EXPECT_EQ(t1[first % 3], t2[(second % 3 + 1) % 3]);
      EXPECT_EQ(t1[(first % 3 + 1) % 3], t2[second % 3]);
      EXPECT_EQ(dual.graph.endpoints(e)[0], first / 3);
      EXPECT_EQ(dual.graph.endpoints(e)[1], second / 3);
    }
  }
}

TEST(Dual, PlateOfGenusTwoValidates) {
  const PolygonMesh mesh = voxel_plate({2, 1, 2, false});
  const CubicGraph graph = dual_graph(mesh);
  EXPECT_EQ(graph.node_count(), mesh.face_count());
  validate_connected_bridgeless(graph);
}

TEST(Dual, TwoComponentsGiveADisconnectedCubicGraph) {
  PolygonMesh mesh = tetrahedron();
  const PolygonMesh second = tetrahedron();
  for (auto p : second.positions) mesh.positions.push_back(p);
  for (VertexId v : second.corners) mesh.corners.push_back(v + 4);
  EXPECT_EQ(count_components(dual_graph(mesh)), 2u);
}

TEST(Dual, BoundaryEdgeIsNamed) {
  PolygonMesh mesh = tetrahedron();
  mesh.corners.resize(9);
  EXPECT_NE(error_of(mesh).find("boundary edge (0, 2): only triangle 0 has it"), std::string::npos)
      << error_of(mesh);
}

TEST(Dual, NonManifoldEdgeIsNamed) {
  PolygonMesh mesh = tetrahedron();
  mesh.positions.push_back({1, 1, 1});
  for (VertexId v : {0, 1, 4, 1, 0, 4}) mesh.corners.push_back(v);
  const std::string error = error_of(mesh);
  EXPECT_NE(error.find("non-manifold edge (1, 0): in 4 triangles (0, 1, 4, ...)"),
            std::string::npos)
      << error;
}

TEST(Dual, InconsistentOrientationIsNamed) {
  PolygonMesh mesh = tetrahedron();
  set_face(mesh, 3, {0, 2, 3});
  const std::string error = error_of(mesh);
  EXPECT_NE(error.find("inconsistent orientation"), std::string::npos) << error;
  EXPECT_NE(error.find("triangles"), std::string::npos) << error;
}

TEST(Dual, DegenerateAndOutOfRangeTrianglesAreNamed) {
  PolygonMesh mesh = tetrahedron();
  set_face(mesh, 2, {1, 1, 3});
  EXPECT_NE(error_of(mesh).find("triangle 2 is degenerate"), std::string::npos);
  set_face(mesh, 2, {1, 2, 9});
  EXPECT_NE(error_of(mesh).find("triangle 2 has corner 9 out of range"), std::string::npos);
}

TEST(Dual, FaceThatIsNoTriangleIsNamed) {
  PolygonMesh mesh = tetrahedron();
  const std::array<VertexId, 4> quad{0, 1, 2, 3};
  mesh.add_face(quad);
  EXPECT_EQ(error_of(mesh), "face 4 has 4 corners; the dual is built on triangles only");
}

// The same dual, whatever face_start holds, as long as every face is a triangle.
TEST(Dual, ExplicitFaceStartsOfTrianglesGiveTheSameDual) {
  PolygonMesh mesh = voxel_plate({1, 1, 1, false});
  const CubicGraph implicit = dual_graph(mesh);
  const auto faces = static_cast<std::uint32_t>(mesh.face_count());
  for (std::uint32_t f = 0; f <= faces; ++f) mesh.face_start.push_back(3 * f);
  const CubicGraph explicit_starts = dual_graph(mesh);
  EXPECT_EQ(std::vector<EdgeId>(implicit.node_edges().begin(), implicit.node_edges().end()),
            std::vector<EdgeId>(explicit_starts.node_edges().begin(),
                                explicit_starts.node_edges().end()));
}

}  // namespace
}  // namespace petersen
