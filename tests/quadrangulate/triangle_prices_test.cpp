// The price of leaving a triangle (triangle_prices.hpp): the rule on a small graph, and what it
// is for: a chamfered cube exported triangulated comes back with every quad, its corner
// triangles left.

#include "petersen/quadrangulate/triangle_prices.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <vector>

#include "petersen/generators/mesh_class_generators.hpp"
#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen {
namespace {

// A path a–b–c–d with costs 70, 0, 70: b and c are each other's best pair, a good quad; a and d
// can only take one of them from it, 70 over its best; a price of 90 is lowered for a and d
// (70 >= 60), not for b and c (regret 0).
TEST(TrianglePrices, LowersThePriceOfANodeWhoseEveryPairCostsANeighbourItsBest) {
  const std::vector<NodeId> ends = {0, 1, 1, 2, 2, 3};
  const std::vector<Cost> costs = {70, 0, 70};
  const std::pmr::vector<Cost> prices = triangle_prices(4, ends, costs, 90);
  EXPECT_EQ(prices[0], 54);
  EXPECT_EQ(prices[1], 90);
  EXPECT_EQ(prices[2], 90);
  EXPECT_EQ(prices[3], 54);
  // Below the regret share: no node is lowered; an isolated node keeps the price.
  const std::vector<Cost> close = {59, 0, 59};
  const std::pmr::vector<Cost> kept = triangle_prices(5, ends, close, 90);
  EXPECT_TRUE(std::all_of(kept.begin(), kept.end(), [](Cost p) { return p == 90; }));
  // b and c in a mediocre quad (31 > 90 / 3): a and d protect no good quad and keep the price.
  const std::vector<Cost> mediocre = {101, 31, 101};
  const std::pmr::vector<Cost> held = triangle_prices(4, ends, mediocre, 90);
  EXPECT_TRUE(std::all_of(held.begin(), held.end(), [](Cost p) { return p == 90; }));
  const std::vector<Cost> good = {100, 30, 100};
  EXPECT_EQ(triangle_prices(4, ends, good, 90)[0], 54);
}

TEST(TrianglePrices, AChamferedCubeComesBackWithEveryQuadItsCornersLeft) {
  const PolygonMesh cube = chamfered_cube();
  ASSERT_EQ(cube.face_count(), 26u);
  std::set<std::set<VertexId>> quads;
  for (FaceId f = 0; f < cube.face_count(); ++f) {
    const auto c = cube.face(f);
    if (c.size() == 4) quads.insert({c[0], c[1], c[2], c[3]});
  }
  ASSERT_EQ(quads.size(), 18u);
  for (bool first_diagonal : {true, false}) {
    const PolygonMesh triangles = split_quads(cube, first_diagonal);
    const QuadResult result = quadrangulate(triangles);
    ASSERT_TRUE(result.stats.optimality_certified);
    EXPECT_EQ(result.stats.triangles_left, 8u);
    std::size_t back = 0;
    for (FaceId o = 0; o < result.mesh.face_count(); ++o) {
      const auto c = result.mesh.face(o);
      back += c.size() == 4 && quads.count({c[0], c[1], c[2], c[3]});
    }
    EXPECT_EQ(back, 18u);
    // The maximum pairing has to pair the corners through the bevels, breaking four of them.
    const QuadResult quality = quadrangulate(triangles, {.objective = Objective::quality});
    EXPECT_EQ(quality.stats.triangles_left, 0u);
  }
}

}  // namespace
}  // namespace petersen
