#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "peers.hpp"
#include "petersen/generators/graph_generators.hpp"
#include "petersen/graph/connectivity.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "petersen/testing/arbitrary.hpp"

namespace petersen {
namespace {

using Problem = MatchingCheck::Problem;

TEST(Verifier, AcceptsAPerfectMatchingOfK4) {
  CubicGraph g = complete_k4();  // edges 0:{0,1} 5:{2,3}
  Matching m(4);
  m.match(g, 0);
  m.match(g, 5);
  EXPECT_TRUE(verify_perfect_matching(g, m).ok());
  EXPECT_EQ(m.unmatched_count(), 0u);
}

TEST(Verifier, NamesTheUnmatchedNode) {
  CubicGraph g = complete_k4();
  Matching m(4);
  m.match(g, 0);
  MatchingCheck check = verify_perfect_matching(g, m);
  EXPECT_EQ(check.problem, Problem::unmatched);
  EXPECT_EQ(check.node, 2u);
  EXPECT_TRUE(verify_matching(g, m).ok());
}

TEST(Verifier, NamesANodeMatchedTwice) {
  CubicGraph g = complete_k4();  // edges 0:{0,1} 1:{0,2}
  Matching m(4);
  m.mate_edge = {0, 0, 1, kNoEdge};  // node 2 claims edge {0,2} but node 0 holds edge {0,1}
  MatchingCheck check = verify_matching(g, m);
  EXPECT_EQ(check.problem, Problem::inconsistent);
  EXPECT_EQ(check.node, 2u);
  EXPECT_EQ(check.edge, 1u);
}

TEST(Verifier, NamesAnEdgeOutOfRangeOrNotIncident) {
  CubicGraph g = complete_k4();
  Matching m(4);
  m.mate_edge = {99, kNoEdge, kNoEdge, kNoEdge};
  EXPECT_EQ(verify_matching(g, m).problem, Problem::edge_out_of_range);
  m.mate_edge = {5, kNoEdge, kNoEdge, kNoEdge};  // edge 5 joins 2 and 3
  EXPECT_EQ(verify_matching(g, m).problem, Problem::not_incident);
  m.mate_edge = {0, 0};
  EXPECT_EQ(verify_matching(g, m).problem, Problem::wrong_size);
}

TEST(Algorithms, NamesRoundTrip) {
  for (Algorithm a : {Algorithm::automatic, Algorithm::sg, Algorithm::ps, Algorithm::ds,
                      Algorithm::gw, Algorithm::frink}) {
    EXPECT_EQ(parse_algorithm(to_string(a)), a);
  }
  EXPECT_EQ(to_string(Algorithm::automatic), "auto");
  EXPECT_EQ(PerfectMatchingOptions{}.algorithm, Algorithm::automatic);
  // lrs needs a mesh (the front door's PairingAlgorithm), LEMON is a peer of the tests and bench.
  for (const char* other : {"blossom", "lrs", "lemon"}) {
    EXPECT_FALSE(parse_algorithm(other).has_value()) << other;
  }
  EXPECT_EQ(parse_augment("faithful"), Augment::faithful);
}

RC_GTEST_PROP(PerfectMatching, RefusesEveryPlantedBridge, ()) {
  const testing::GraphWithBridge input = *testing::cubic_graphs_with_a_bridge();
  RC_ASSERT(find_bridge(input.graph) == std::optional<EdgeId>(input.bridge));
  RC_ASSERT_THROWS_AS(perfect_matching(input.graph), GraphError);
}

TEST(PerfectMatching, RefusesABridgeAtTheDoor) {
  // Two theta-like blobs (K4 with a subdivided edge) joined by a bridge.
  std::vector<std::array<NodeId, 2>> edges;
  for (NodeId base : {0u, 5u}) {
    NodeId a = base, b = base + 1, c = base + 2, d = base + 3, s = base + 4;
    edges.insert(edges.end(), {{a, b}, {a, c}, {a, d}, {b, c}, {b, d}, {c, s}, {s, d}});
  }
  edges.push_back({4, 9});
  CubicGraph g = CubicGraph::from_edges(10, edges);
  EXPECT_THROW(perfect_matching(g), GraphError);
}

RC_GTEST_PROP(PerfectMatching, LemonIsPerfectAndAgreesWithBoost, ()) {
  const auto n = *rc::gen::inRange<std::uint32_t>(1, 150) * 2;
  CubicGraph g = random_cubic_bridgeless(n, *rc::gen::arbitrary<std::uint64_t>());
  RC_ASSERT(verify_perfect_matching(g, testing::lemon_matching(g)).ok());
  RC_ASSERT(testing::boost_matching_size(n, testing::edge_list(g)) == n / 2);
}

}  // namespace
}  // namespace petersen
