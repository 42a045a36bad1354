#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "peers.hpp"
#include "petersen/generators/graph_generators.hpp"
#include "petersen/graph/connectivity.hpp"
#include "petersen/lemon_peer/lemon_peer.hpp"
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
                      Algorithm::gw, Algorithm::frink, Algorithm::lrs, Algorithm::lemon}) {
    EXPECT_EQ(parse_algorithm(to_string(a)), a);
  }
  EXPECT_EQ(to_string(Algorithm::automatic), "auto");
  EXPECT_EQ(PerfectMatchingOptions{}.algorithm, Algorithm::automatic);
  EXPECT_FALSE(parse_algorithm("blossom").has_value());
  EXPECT_EQ(parse_augment("faithful"), Augment::faithful);
}

TEST(PerfectMatching, LemonNeedsTheCallersPeer) {
  EXPECT_THROW(perfect_matching(petersen_graph(), {.algorithm = Algorithm::lemon}),
               std::invalid_argument);
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
  EXPECT_THROW(
      perfect_matching(g, {.algorithm = Algorithm::lemon, .peer = &lemon_peer::maximum_matching}),
      GraphError);
}

RC_GTEST_PROP(PerfectMatching, LemonIsPerfectAndAgreesWithBoost, ()) {
  const auto n = *rc::gen::inRange<std::uint32_t>(1, 150) * 2;
  CubicGraph g = random_cubic_bridgeless(n, *rc::gen::arbitrary<std::uint64_t>());
  PerfectMatchingResult result =
      perfect_matching(g, {.algorithm = Algorithm::lemon, .peer = &lemon_peer::maximum_matching});
  MatchingCheck check = verify_perfect_matching(g, result.matching);
  RC_ASSERT(check.ok());
  RC_ASSERT(testing::boost_matching_size(n, testing::edge_list(g)) == n / 2);
}

}  // namespace
}  // namespace petersen
