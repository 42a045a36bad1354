// Tarjan's augmenting paths (paper §3.1): SG/PS + local/faithful through the front door, the
// augmentation alone from an empty matching, and the general-graph (CSR) fallback, each checked
// by the verifier and against LEMON's and Boost's maximum sizes.

#include "petersen/matching/augment.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "peers.hpp"
#include "petersen/graph/csr_graph.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "petersen/matching/tutte_berge.hpp"
#include "petersen/testing/arbitrary.hpp"

namespace petersen {
namespace {

using testing::edge_list;

constexpr Algorithm kGreedy[] = {Algorithm::sg, Algorithm::ps, Algorithm::automatic};
constexpr Augment kVariants[] = {Augment::local, Augment::faithful};

RC_GTEST_PROP(GreedyThenAugment, IsPerfectAndAsLargeAsLemonAndBoost, ()) {
  CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  const auto edges = edge_list(g);
  const std::uint32_t lemon = testing::lemon_matching_size(g.node_count(), edges);
  const std::uint32_t boost = testing::boost_matching_size(g.node_count(), edges);
  RC_ASSERT(lemon == boost);
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  for (Algorithm algorithm : kGreedy) {
    for (Augment augment : kVariants) {
      PerfectMatchingResult r =
          perfect_matching(g, {.algorithm = algorithm, .augment = augment, .seed = seed});
      MatchingCheck check = verify_perfect_matching(g, r.matching);
      RC_ASSERT(check.ok());
      RC_ASSERT(g.node_count() / 2 == lemon);
      RC_ASSERT(r.stats.augmenting_paths * 2 == r.stats.unpaired_after_initial);
    }
  }
}

RC_GTEST_PROP(GreedyThenAugment, SameSeedSameMatching, ()) {
  CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  const PerfectMatchingOptions options{
      .algorithm = *rc::gen::element(Algorithm::sg, Algorithm::ps, Algorithm::automatic),
      .augment = *rc::gen::element(Augment::local, Augment::faithful),
      .seed = *rc::gen::arbitrary<std::uint64_t>()};
  PerfectMatchingResult first = perfect_matching(g, options);
  PerfectMatchingResult second = perfect_matching(g, options);
  RC_ASSERT(verify_perfect_matching(g, first.matching).ok());
  RC_ASSERT(first.matching.mate_edge == second.matching.mate_edge);
}

RC_GTEST_PROP(AugmentMatching, MakesTheEmptyMatchingPerfect, ()) {
  // No greedy start: every node is free, so the searches meet long paths and many blossoms.
  CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  for (Augment augment : kVariants) {
    Matching m(g.node_count());
    AugmentStats stats = augment_matching(g, m, augment);
    RC_ASSERT(verify_perfect_matching(g, m).ok());
    RC_ASSERT(stats.augmenting_paths == g.node_count() / 2);
  }
}

TEST(AugmentMatching, FindsTheBlossomInThePetersenGraph) {
  // Outer 5-cycle matched on {0,1} and {2,3}; node 4 and the inner pentagram are free. The
  // graph is all odd cycles (girth 5), so the searches must shrink blossoms.
  CubicGraph g = petersen_graph();
  for (Augment augment : kVariants) {
    Matching m(g.node_count());
    m.match(g, 0);  // {0, 1}
    m.match(g, 6);  // {2, 3}
    AugmentStats stats = augment_matching(g, m, augment);
    EXPECT_TRUE(verify_perfect_matching(g, m).ok());
    EXPECT_EQ(stats.augmenting_paths, 3u);
  }
}

// A valid matching of a general graph: each matched node names an incident edge whose other end
// names it too.
bool is_valid_matching(const CsrGraph& g, const Matching& m) {
  for (NodeId v = 0; v < g.node_count(); ++v) {
    const EdgeId e = m.mate_edge[v];
    if (e == kNoEdge) continue;
    if (e >= g.edge_count()) return false;
    auto [a, b] = g.endpoints(e);
    if (a != v && b != v) return false;
    if (m.mate_edge[g.other_end(e, v)] != e) return false;
  }
  return true;
}

RC_GTEST_PROP(MaximumMatching, ReachesLemonAndBoostOnGeneralGraphs, ()) {
  const testing::EdgeListGraph input = *testing::general_graphs();
  CsrGraph g = CsrGraph::from_edges(input.node_count, input.edges);
  const std::uint32_t lemon = testing::lemon_matching_size(input.node_count, input.edges);
  RC_ASSERT(lemon == testing::boost_matching_size(input.node_count, input.edges));
  for (Augment augment : kVariants) {
    MaximumMatchingResult r = maximum_matching(g, augment);
    RC_ASSERT(is_valid_matching(g, r.matching));
    RC_ASSERT(r.size == lemon);
    const MatchingCheck certified = verify_maximum_matching(g, r.matching, r.tutte_set);
    RC_ASSERT(certified.ok());
    // One matched edge fewer: still a valid matching, no longer maximum, and the same witness
    // (or any other) cannot prove it.
    if (r.size > 0) {
      Matching smaller = r.matching;
      const NodeId v =
          static_cast<NodeId>(std::find_if(smaller.mate_edge.begin(), smaller.mate_edge.end(),
                                           [](EdgeId e) { return e != kNoEdge; }) -
                              smaller.mate_edge.begin());
      const EdgeId e = smaller.mate_edge[v];
      smaller.mate_edge[v] = smaller.mate_edge[g.other_end(e, v)] = kNoEdge;
      RC_ASSERT(verify_maximum_matching(g, smaller, r.tutte_set).problem ==
                MatchingCheck::Problem::not_maximum);
      RC_ASSERT(verify_maximum_matching(g, smaller, {}).problem ==
                MatchingCheck::Problem::not_maximum);
    }
    // The augmentation alone, from nothing.
    Matching empty(g.node_count());
    AugmentStats stats = augment_matching(g, empty, augment);
    RC_ASSERT(is_valid_matching(g, empty));
    RC_ASSERT(stats.augmenting_paths == lemon);
  }
}

// A star K1,3 plus an isolated node: the centre is the Tutte set (four odd components, one node
// each, minus one), so any maximum matching leaves three of the five nodes free.
TEST(MaximumMatching, TutteSetOfAStarIsItsCentre) {
  const std::vector<std::array<NodeId, 2>> edges{{0, 1}, {0, 2}, {0, 3}};
  CsrGraph g = CsrGraph::from_edges(5, edges);
  MaximumMatchingResult r = maximum_matching(g);
  EXPECT_EQ(r.size, 1u);
  EXPECT_EQ(r.tutte_set, std::vector<NodeId>{0});
  EXPECT_TRUE(verify_maximum_matching(g, r.matching, r.tutte_set).ok());
  const std::vector<NodeId> twice{0, 0}, far{7};
  EXPECT_EQ(verify_maximum_matching(g, r.matching, twice).problem,
            MatchingCheck::Problem::bad_witness);
  EXPECT_EQ(verify_maximum_matching(g, r.matching, far).problem,
            MatchingCheck::Problem::bad_witness);
  const std::vector<NodeId> leaf{1};
  EXPECT_EQ(verify_maximum_matching(g, r.matching, leaf).problem,
            MatchingCheck::Problem::not_maximum);
}

TEST(CsrGraph, RefusesLoopsAndEndpointsOutOfRange) {
  const std::vector<std::array<NodeId, 2>> loop{{0, 1}, {2, 2}};
  EXPECT_THROW(CsrGraph::from_edges(3, loop), GraphError);
  const std::vector<std::array<NodeId, 2>> far{{0, 3}};
  EXPECT_THROW(CsrGraph::from_edges(3, far), GraphError);
}

TEST(CsrGraph, ListsEachNodesEdgesInIdOrder) {
  const std::vector<std::array<NodeId, 2>> edges{{0, 1}, {1, 2}, {0, 1}, {3, 1}};
  CsrGraph g = CsrGraph::from_edges(5, edges);
  EXPECT_EQ(g.node_count(), 5u);
  EXPECT_EQ(g.edge_count(), 4u);
  const std::vector<EdgeId> at1(g.incident_edges(1).begin(), g.incident_edges(1).end());
  EXPECT_EQ(at1, (std::vector<EdgeId>{0, 1, 2, 3}));
  EXPECT_EQ(g.degree(4), 0u);
  EXPECT_EQ(g.other_end(3, 1), 3u);
}

}  // namespace
}  // namespace petersen
