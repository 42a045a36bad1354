// The worst-corner measure on quads whose angles are known by construction.

#include "petersen/render/quad_quality.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace petersen {
namespace {

using P = std::array<double, 3>;

TEST(QuadQuality, RightAnglesCostNothing) {
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}), 0, 1e-12);
  EXPECT_NEAR(quad_corner_deviation({0, 0, 5}, {3, 0, 5}, {3, 1, 5}, {0, 1, 5}), 0, 1e-12);
  // The same square seen from the other side (corners reversed): still 0.
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 0, 0}), 0, 1e-12);
}

TEST(QuadQuality, AParallelogramOf60And120DegreesCosts30) {
  const double s = 1 / std::sqrt(3.0);  // the top edge shifted by cot 60° for height 1
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {1, 0, 0}, {1 + s, 1, 0}, {s, 1, 0}), 30, 1e-9);
}

TEST(QuadQuality, ATrapezoidOf45And135DegreesCosts45InAnyPlane) {
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {4, 0, 0}, {3, 1, 0}, {1, 1, 0}), 45, 1e-9);
  // Rotated into the plane x = z: the same quad.
  const double r = 1 / std::sqrt(2.0);
  EXPECT_NEAR(quad_corner_deviation({0, 0, 0}, {4 * r, 0, 4 * r}, {3 * r, 1, 3 * r}, {r, 1, r}), 45,
              1e-9);
}

TEST(QuadQuality, ANonConvexDartCostsMoreThan90) {
  // Corner c = (0.5, 0.5) is reflex: its edges (1.5, −0.5) and (−0.5, 1.5) meet at acos(−0.6),
  // so the interior angle is 360° minus that, and the cost that minus 90°.
  const double cost = quad_corner_deviation({0, 0, 0}, {2, 0, 0}, {0.5, 0.5, 0}, {0, 2, 0});
  EXPECT_GT(cost, 90);
  EXPECT_NEAR(cost, 270 - std::acos(-0.6) * 180 / std::numbers::pi, 1e-9);
}

TEST(QuadQuality, DegenerateQuadsCostTheMaximum) {
  EXPECT_EQ(quad_corner_deviation({0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}), kDegenerateQuadCost);
  EXPECT_EQ(quad_corner_deviation({0, 0, 0}, {0, 0, 0}, {1, 1, 0}, {0, 1, 0}), kDegenerateQuadCost);
  EXPECT_EQ(quad_corner_deviation({NAN, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}),
            kDegenerateQuadCost);
}

TEST(QuadQuality, FiguresAreNearestRankOverTheQuadsOnly) {
  PolygonMesh mesh;
  const double s = 1 / std::sqrt(3.0);
  for (P p :
       {P{0, 0, 0}, P{1, 0, 0}, P{1, 1, 0}, P{0, 1, 0}, P{1 + s, 1, 0}, P{s, 1, 0}, P{2, 0, 0}}) {
    mesh.positions.push_back(p);
  }
  mesh.add_face(std::vector<VertexId>{0, 1, 2, 3});  // 0°
  mesh.add_face(std::vector<VertexId>{0, 1, 4, 5});  // 30°
  mesh.add_face(std::vector<VertexId>{1, 6, 2});     // a triangle: not a quad, not counted
  mesh.add_face(std::vector<VertexId>{0, 6, 2, 3});  // (0,0) (2,0) (1,1) (0,1): 90, 45, 135, 90
  const std::vector<double> costs = quad_costs(mesh);
  ASSERT_EQ(costs.size(), 3u);
  EXPECT_NEAR(costs[0], 0, 1e-9);
  EXPECT_NEAR(costs[1], 30, 1e-9);
  EXPECT_NEAR(costs[2], 45, 1e-9);  // angles 90, 45, 135, 90
  const QuadQualityFigures f = quality_figures(costs);
  EXPECT_EQ(f.quads, 3u);
  EXPECT_NEAR(f.median, 30, 1e-9);
  EXPECT_NEAR(f.p95, 45, 1e-9);
  EXPECT_EQ(f.nonconvex, 0u);
  EXPECT_EQ(quality_figures({}).quads, 0u);
  EXPECT_EQ(quality_figures({100, 10}).nonconvex, 1u);
}

}  // namespace
}  // namespace petersen
