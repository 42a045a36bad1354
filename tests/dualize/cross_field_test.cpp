#include "petersen/dualize/cross_field.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/generators/polygon_generators.hpp"

namespace petersen {
namespace {

// Whether side k of triangle t runs along a lattice axis (the jittered grid's squares' sides) or
// across a square (its diagonal): by its direction, up to the jitter.
bool is_diagonal(const PolygonMesh& mesh, FaceId t, int k) {
  const auto corners = mesh.face(t);
  const auto& p = mesh.positions[corners[k]];
  const auto& q = mesh.positions[corners[(k + 1) % 3]];
  const double dx = std::abs(q[0] - p[0]), dy = std::abs(q[1] - p[1]);
  return std::min(dx, dy) > 0.4 * std::max(dx, dy);
}

TEST(CrossField, FollowsTheQuadsOfATriangulatedGrid) {
  // Squares cut by random diagonals and jittered: the field runs along the lattice, so the squares'
  // sides lie near it and the diagonals near 45° across it.
  const PolygonMesh mesh = jittered_grid({.nx = 24, .ny = 24, .jitter = 0.1, .seed = 3});
  const PairableGraph graph = build_pairable_graph(mesh);
  const CrossField field = cross_field(graph, mesh);
  ASSERT_EQ(field.cross.size(), graph.node_count);
  EXPECT_LT(field.residual, 1e-5);
  const std::pmr::vector<double> alignment = side_alignment(field);
  double side_sum = 0, diagonal_sum = 0;
  int sides = 0, diagonals = 0;
  for (NodeId t = 0; t < graph.node_count; ++t) {
    for (int k = 0; k < 3; ++k) {
      const double m = alignment[3 * t + k];
      ASSERT_GE(m, 0);
      ASSERT_LE(m, 45 + 1e-9);
      if (is_diagonal(mesh, t, k)) {
        diagonal_sum += m;
        ++diagonals;
      } else {
        side_sum += m;
        ++sides;
      }
    }
  }
  ASSERT_EQ(2 * diagonals, sides);
  EXPECT_GT(side_sum / sides, 37.0);
  EXPECT_LT(diagonal_sum / diagonals, 15.0);
}

TEST(CrossField, FlowOfAPairIsLeastAcrossTheDiagonal) {
  const PolygonMesh mesh = jittered_grid({.nx = 16, .ny = 16, .jitter = 0.05, .seed = 5});
  const PairableGraph graph = build_pairable_graph(mesh);
  const std::pmr::vector<double> flow =
      pairable_edge_flow(graph, side_alignment(cross_field(graph, mesh)));
  ASSERT_EQ(flow.size(), graph.edge_count());
  // Each square's two triangles (faces 2q, 2q + 1) share its diagonal, which runs across the field;
  // every other pair would remove a side of a square, which runs along it.
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const NodeId a = graph.edge_ends[2 * e], b = graph.edge_ends[2 * e + 1];
    if (a / 2 == b / 2) {
      EXPECT_LT(flow[e], 25.0) << "square " << a / 2;
    } else {
      EXPECT_GT(flow[e], 65.0) << "triangles " << a << ", " << b;
    }
  }
}

TEST(CrossField, DoesNotDependOnTheMeshsPlacement) {
  // A rigid motion moves the frames with the mesh: the alignment of every side is the same.
  const PolygonMesh mesh = jittered_grid({.nx = 10, .ny = 8, .jitter = 0.2, .seed = 9});
  PolygonMesh moved = mesh;
  const double c = std::cos(0.7), s = std::sin(0.7);
  for (auto& p : moved.positions) {
    p = {c * p[0] - s * p[2] + 3, p[1] - 2, s * p[0] + c * p[2] + 1};
  }
  const PairableGraph graph = build_pairable_graph(mesh);
  const std::pmr::vector<double> before = side_alignment(cross_field(graph, mesh));
  const std::pmr::vector<double> after = side_alignment(cross_field(graph, moved));
  ASSERT_EQ(before.size(), after.size());
  for (std::size_t i = 0; i < before.size(); ++i) EXPECT_NEAR(before[i], after[i], 1e-6) << i;
}

TEST(CrossField, DegenerateTrianglesHaveNoCross) {
  PolygonMesh mesh = open_grid(3, 3);
  mesh.positions[5] = mesh.positions[6];  // two triangles at vertex 5 lose their area
  const PairableGraph graph = build_pairable_graph(mesh);
  const CrossField field = cross_field(graph, mesh);
  const std::pmr::vector<double> alignment = side_alignment(field);
  for (NodeId t = 0; t < graph.node_count; ++t) {
    ASSERT_TRUE(std::isfinite(std::abs(field.cross[t])));
    for (int k = 0; k < 3; ++k) ASSERT_TRUE(std::isfinite(alignment[3 * t + k]));
  }
}

TEST(CrossField, RefusesAnAlignmentThatIsNotPositive) {
  const PolygonMesh mesh = open_grid(2, 2);
  const PairableGraph graph = build_pairable_graph(mesh);
  EXPECT_THROW(cross_field(graph, mesh, {.alignment = 0}), std::invalid_argument);
  EXPECT_THROW(cross_field(graph, mesh, {.alignment = std::nan("")}), std::invalid_argument);
}

}  // namespace
}  // namespace petersen
