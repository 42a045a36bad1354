#include "petersen/generators/graph_generators.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "petersen/graph/connectivity.hpp"

namespace petersen {
namespace {

TEST(Generators, NamedGraphsAreCubicConnectedBridgeless) {
  for (const CubicGraph& g : {theta_graph(), complete_k4(), complete_k33(), petersen_graph(),
                              prism(2), prism(7), necklace(1), necklace(6)}) {
    EXPECT_NO_THROW(validate_connected_bridgeless(g));
  }
  EXPECT_EQ(petersen_graph().node_count(), 10u);
  EXPECT_EQ(necklace(6).node_count(), 24u);
  EXPECT_EQ(prism(7).edge_count(), 21u);
}

TEST(Generators, RandomIsSeeded) {
  CubicGraph a = random_cubic_bridgeless(100, 42), b = random_cubic_bridgeless(100, 42);
  EXPECT_TRUE(std::equal(a.edge_ends().begin(), a.edge_ends().end(), b.edge_ends().begin()));
}

RC_GTEST_PROP(Generators, RandomCubicIsConnectedAndBridgeless, ()) {
  const auto n = *rc::gen::inRange<std::uint32_t>(1, 200) * 2;
  CubicGraph g = random_cubic_bridgeless(n, *rc::gen::arbitrary<std::uint64_t>());
  RC_ASSERT(g.node_count() == n);
  RC_ASSERT(count_components(g) == 1u);
  RC_ASSERT(!find_bridge(g).has_value());
}

}  // namespace
}  // namespace petersen
