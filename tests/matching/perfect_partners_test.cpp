// perfect_partners, the lean PS on neighbour rows: the same pairs as perfect_matching's PS for the
// same seed (parallel edges included), and verify_perfect_partners naming each kind of problem.

#include "petersen/matching/perfect_partners.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <random>

#include "petersen/generators/graph_generators.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "petersen/testing/arbitrary.hpp"

namespace petersen {
namespace {

using Problem = MatchingCheck::Problem;

std::pmr::vector<NodeId> rows_of(CubicGraph g) {
  return std::move(g).into_neighbour_rows();
}

RC_GTEST_PROP(PerfectPartners, PairsAsPerfectMatchingsAutoAndPsDo, ()) {
  const CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  const std::pmr::vector<NodeId> rows = rows_of(g);
  const Algorithm algorithm = *rc::gen::element(Algorithm::automatic, Algorithm::ps);
  for (Augment augment : {Augment::local, Augment::faithful}) {
    const PerfectMatchingResult full = perfect_matching(
        g, {.algorithm = algorithm, .augment = augment, .seed = seed, .validate = false});
    const PartnerResult lean =
        perfect_partners(rows, {.algorithm = algorithm, .augment = augment, .seed = seed});
    RC_ASSERT(verify_perfect_partners(rows, lean.partner).ok());
    for (NodeId v = 0; v < g.node_count(); ++v)
      RC_ASSERT(lean.partner[v] == g.other_end(full.matching.mate_edge[v], v));
    RC_ASSERT(lean.stats.unpaired_after_initial == full.stats.unpaired_after_initial);
    RC_ASSERT(lean.stats.augmenting_paths == full.stats.augmenting_paths);
    RC_ASSERT(lean.stats.blossoms == full.stats.blossoms);
    RC_ASSERT(lean.stats.nodes_labelled == full.stats.nodes_labelled);
    RC_ASSERT(lean.stats.ordered_sweep == full.stats.ordered_sweep);
    RC_ASSERT(lean.stats.schrijver == full.stats.schrijver);
  }
}

// From a partial pairing (a greedy pass over edges in a random order), the same searches as
// augment_matching on the graph: the same pairs and counters.
RC_GTEST_PROP(AugmentPartners, GrowsAPairingAsAugmentMatchingDoes, ()) {
  const CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  const std::pmr::vector<NodeId> rows = rows_of(g);
  std::vector<EdgeId> order(g.edge_count());
  for (EdgeId e = 0; e < order.size(); ++e) order[e] = e;
  std::shuffle(order.begin(), order.end(), std::mt19937_64(*rc::gen::arbitrary<std::uint64_t>()));
  for (Augment augment : {Augment::local, Augment::faithful}) {
    Matching matching;
    matching.mate_edge.assign(g.node_count(), kNoEdge);
    std::pmr::vector<NodeId> partner(g.node_count(), kNoNode);
    for (EdgeId e : order) {
      const auto [a, b] = g.endpoints(e);
      if (matching.mate_edge[a] != kNoEdge || matching.mate_edge[b] != kNoEdge) continue;
      matching.mate_edge[a] = matching.mate_edge[b] = e;
      partner[a] = b;
      partner[b] = a;
    }
    const AugmentStats full = augment_matching(g, matching, augment);
    const AugmentStats lean = augment_partners(rows, partner, augment);
    RC_ASSERT(verify_perfect_partners(rows, partner).ok());
    for (NodeId v = 0; v < g.node_count(); ++v)
      RC_ASSERT(partner[v] == g.other_end(matching.mate_edge[v], v));
    RC_ASSERT(lean.augmenting_paths == full.augmenting_paths);
    RC_ASSERT(lean.blossoms == full.blossoms);
    RC_ASSERT(lean.nodes_labelled == full.nodes_labelled);
  }
}

TEST(AugmentPartners, RefusesAPartnerThatIsNoNeighbourOrDoesNotNameItBack) {
  const std::pmr::vector<NodeId> prism_rows =
      rows_of(prism(3));  // 0-1-2 and 3-4-5, i joined to i+3
  std::vector<NodeId> not_adjacent{4, kNoNode, kNoNode, kNoNode, 0, kNoNode};
  EXPECT_THROW(augment_partners(prism_rows, not_adjacent), std::invalid_argument);
  std::vector<NodeId> one_way{1, 2, kNoNode, kNoNode, kNoNode, kNoNode};
  EXPECT_THROW(augment_partners(prism_rows, one_way), std::invalid_argument);
  std::vector<NodeId> short_list{1, 0};
  EXPECT_THROW(augment_partners(prism_rows, short_list), std::invalid_argument);
  std::vector<NodeId> from_nothing(6, kNoNode);
  augment_partners(prism_rows, from_nothing);
  EXPECT_TRUE(verify_perfect_partners(prism_rows, from_nothing).ok());
}

TEST(PerfectPartners, MatchesLargeRandomGraphsPerfectly) {
  // Past the read-ahead distances and with many free nodes after PS, so augmenting paths run.
  for (std::uint64_t seed = 1; seed <= 4; ++seed) {
    const std::pmr::vector<NodeId> rows = rows_of(random_cubic_bridgeless(20000, seed));
    const PartnerResult r = perfect_partners(rows, {.seed = seed});
    EXPECT_TRUE(verify_perfect_partners(rows, r.partner).ok());
    EXPECT_EQ(r.stats.augmenting_paths * 2, r.stats.unpaired_after_initial);
  }
}

TEST(VerifyPerfectPartners, AcceptsAPerfectMatchingOfTheTheta) {
  // Three parallel edges: the partner is in the row three times.
  const std::pmr::vector<NodeId> rows = rows_of(theta_graph());
  EXPECT_TRUE(verify_perfect_partners(rows, std::vector<NodeId>{1, 0}).ok());
}

TEST(VerifyPerfectPartners, NamesEachProblemWithItsNode) {
  const std::pmr::vector<NodeId> rows = rows_of(complete_k4());  // every pair adjacent
  const std::pmr::vector<NodeId> prism_rows =
      rows_of(prism(3));  // 0-1-2 and 3-4-5, i joined to i+3
  auto problem = [](std::span<const NodeId> r, std::vector<NodeId> partner) {
    return verify_perfect_partners(r, partner);
  };
  EXPECT_EQ(problem(rows, {1, 0, 3}).problem, Problem::wrong_size);
  const MatchingCheck unmatched = problem(rows, {1, 0, kNoNode, 2});
  EXPECT_EQ(unmatched.problem, Problem::unmatched);
  EXPECT_EQ(unmatched.node, 2u);
  const MatchingCheck out_of_range = problem(rows, {1, 0, 4, 2});
  EXPECT_EQ(out_of_range.problem, Problem::edge_out_of_range);
  EXPECT_EQ(out_of_range.node, 2u);
  const MatchingCheck inconsistent = problem(rows, {1, 0, 1, 2});
  EXPECT_EQ(inconsistent.problem, Problem::inconsistent);
  EXPECT_EQ(inconsistent.node, 2u);
  EXPECT_EQ(problem(rows, {0, 1, 3, 2}).problem, Problem::not_incident);  // its own partner
  // In the prism, 0 and 4 are not adjacent.
  const MatchingCheck not_adjacent = problem(prism_rows, {4, 2, 1, 5, 0, 3});
  EXPECT_EQ(not_adjacent.problem, Problem::not_incident);
  EXPECT_EQ(not_adjacent.node, 0u);
  EXPECT_TRUE(problem(prism_rows, {3, 2, 1, 0, 5, 4}).ok());
}

}  // namespace
}  // namespace petersen
