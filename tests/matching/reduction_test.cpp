// Frink's reductions under the forbidden-edge rule (paper §3.2, Appendix A): every chooser's
// matching is perfect, avoids the forbidden edge, keeps every intermediate graph bridgeless (debug
// mode), and has the size LEMON and Boost find.

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <vector>

#include "peers.hpp"
#include "petersen/graph/connectivity.hpp"
#include "petersen/matching/avoiding.hpp"
#include "petersen/testing/arbitrary.hpp"

namespace petersen {
namespace {

using testing::edge_list;

constexpr ReductionChooser kChoosers[] = {ReductionChooser::frink, ReductionChooser::ds,
                                          ReductionChooser::gw};

// A ring of k random cubic graphs, each with one edge cut open and its ends joined to the
// neighbouring graphs: every pair of ring edges is a 2-edge cut.
CubicGraph ring_of_blobs(std::uint32_t k, std::uint32_t blob_nodes, std::uint64_t seed) {
  std::vector<std::array<NodeId, 2>> edges;
  std::vector<std::array<NodeId, 2>> open;  // the ends of each blob's removed edge
  NodeId base = 0;
  for (std::uint32_t i = 0; i < k; ++i) {
    const CubicGraph blob = random_cubic_bridgeless(blob_nodes, seed + i);
    for (EdgeId e = 1; e < blob.edge_count(); ++e)
      edges.push_back({base + blob.endpoints(e)[0], base + blob.endpoints(e)[1]});
    open.push_back({base + blob.endpoints(0)[0], base + blob.endpoints(0)[1]});
    base += blob_nodes;
  }
  for (std::uint32_t i = 0; i < k; ++i) edges.push_back({open[i][1], open[(i + 1) % k][0]});
  return CubicGraph::from_edges(base, edges);
}

// Two graphs side by side: a disconnected input, matched component by component.
CubicGraph disjoint_union(const CubicGraph& a, const CubicGraph& b) {
  auto edges = edge_list(a);
  for (auto [x, y] : edge_list(b)) edges.push_back({a.node_count() + x, a.node_count() + y});
  return CubicGraph::from_edges(a.node_count() + b.node_count(), edges);
}

CubicGraph any_test_graph() {
  switch (*rc::gen::inRange(0, 4)) {
    case 0:
      return ring_of_blobs(*rc::gen::inRange<std::uint32_t>(1, 12),
                           2 * *rc::gen::inRange<std::uint32_t>(2, 8),
                           *rc::gen::arbitrary<std::uint64_t>());
    case 1:
      return disjoint_union(*rc::gen::arbitrary<CubicGraph>(), *rc::gen::arbitrary<CubicGraph>());
    default:
      return *rc::gen::arbitrary<CubicGraph>();
  }
}

void check_avoiding(const CubicGraph& g, EdgeId forbidden, ReductionChooser chooser) {
  const bool small = g.node_count() <= 400;
  ReductionResult r =
      perfect_matching_avoiding(g, forbidden, {.chooser = chooser, .check_each_step = small});
  const MatchingCheck check = verify_perfect_matching(g, r.matching);
  RC_ASSERT(check.ok());
  if (forbidden != kNoEdge) {
    for (NodeId v : g.endpoints(forbidden)) RC_ASSERT(r.matching.mate_edge[v] != forbidden);
  }
  RC_ASSERT(2 * (r.stats.reductions + r.stats.digon_reductions) + 2 * count_components(g) ==
            g.node_count());
  RC_ASSERT(r.stats.lift_cases[0] + r.stats.lift_cases[1] + r.stats.lift_cases[2] ==
            r.stats.reductions + r.stats.digon_reductions);
}

RC_GTEST_PROP(Reductions, PerfectAvoidingTheForbiddenEdgeAndAsLargeAsLemonAndBoost, ()) {
  const CubicGraph g = any_test_graph();
  const EdgeId forbidden = *rc::gen::inRange<EdgeId>(0, g.edge_count());
  const auto edges = edge_list(g);
  RC_ASSERT(testing::lemon_matching_size(g.node_count(), edges) == g.node_count() / 2);
  RC_ASSERT(testing::boost_matching_size(g.node_count(), edges) == g.node_count() / 2);
  for (ReductionChooser chooser : kChoosers) check_avoiding(g, forbidden, chooser);
}

TEST(Reductions, EveryEdgeOfTheSmallFamiliesCanBeForbidden) {
  std::uint64_t digons = 0;
  for (const CubicGraph& g : {theta_graph(), complete_k4(), complete_k33(), petersen_graph(),
                              prism(2), prism(7), necklace(1), necklace(5)}) {
    for (EdgeId f = 0; f < g.edge_count(); ++f)
      for (ReductionChooser chooser : kChoosers) {
        ReductionResult r =
            perfect_matching_avoiding(g, f, {.chooser = chooser, .check_each_step = true});
        ASSERT_TRUE(verify_perfect_matching(g, r.matching).ok());
        for (NodeId v : g.endpoints(f)) ASSERT_NE(r.matching.mate_edge[v], f);
        digons += r.stats.digon_reductions;
      }
  }
  EXPECT_GT(digons, 0u);  // the digon contraction was exercised
}

TEST(Reductions, FrontDoorMatchesDisconnectedGraphs) {
  const CubicGraph g = disjoint_union(petersen_graph(), necklace(3));
  for (Algorithm algorithm : {Algorithm::frink, Algorithm::ds, Algorithm::gw}) {
    PerfectMatchingResult r = perfect_matching(g, {.algorithm = algorithm});
    EXPECT_TRUE(verify_perfect_matching(g, r.matching).ok());
    EXPECT_EQ(r.stats.reductions, (g.node_count() - 4) / 2);
  }
}

TEST(Reductions, RefusesForbiddenEdgesOutOfRange) {
  const CubicGraph g = petersen_graph();
  EXPECT_THROW(perfect_matching_avoiding(g, g.edge_count()), GraphError);
}

}  // namespace
}  // namespace petersen
