// match_any_graph and the BGL adaptor on top of it: perfect matchings of cubic bridgeless graphs
// by every algorithm, maximum ones (Boost's size) of every other graph, with the reason noted;
// the adaptor's minimum-cost matching against LEMON's weighted optimum.

#include "petersen/matching/any_graph.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>
#include <boost/property_map/property_map.hpp>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>

#include "peers.hpp"
#include "petersen/adaptors/boost_graph.hpp"
#include "petersen/generators/graph_generators.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/testing/arbitrary.hpp"

namespace petersen {
namespace {

// The matching is one of `edges`: each matched node names an edge at it whose other end names it
// too. Returns the matched edge count, or -1.
std::int64_t checked_size(std::uint32_t n, const testing::EdgeList& edges,
                          const AnyGraphMatching& m) {
  if (m.mate_edge.size() != n) return -1;
  std::int64_t matched = 0;
  for (NodeId v = 0; v < n; ++v) {
    const EdgeId e = m.mate_edge[v];
    if (e == kNoEdge) continue;
    if (e >= edges.size() || (edges[e][0] != v && edges[e][1] != v)) return -1;
    if (m.mate_edge[edges[e][0] ^ edges[e][1] ^ v] != e || edges[e][0] == edges[e][1]) return -1;
    ++matched;
  }
  return matched / 2;
}

RC_GTEST_PROP(AnyGraph, CubicBridgelessGraphsGetPerfectMatchingsByEveryAlgorithm,
              (const CubicGraph& g)) {
  const testing::EdgeList edges = testing::edge_list(g);
  const Algorithm algorithm = *rc::gen::element(Algorithm::automatic, Algorithm::sg, Algorithm::ps,
                                                Algorithm::ds, Algorithm::gw);
  const AnyGraphMatching m = match_any_graph(g.node_count(), edges, {.algorithm = algorithm});
  RC_ASSERT(m.cubic_bridgeless && m.perfect && m.note.empty());
  RC_ASSERT(checked_size(g.node_count(), edges, m) == g.node_count() / 2);
}

RC_GTEST_PROP(AnyGraph, OtherGraphsGetMaximumMatchingsAndANote, ()) {
  testing::EdgeListGraph g = *testing::general_graphs();
  if (*rc::gen::arbitrary<bool>()) g.edges.push_back({0, 0});  // a loop is never matched
  const AnyGraphMatching m = match_any_graph(g.node_count, g.edges);
  std::vector<std::array<std::uint32_t, 2>> loop_free;
  for (auto [a, b] : g.edges)
    if (a != b) loop_free.push_back({a, b});
  const std::uint32_t maximum = testing::boost_matching_size(g.node_count, loop_free);
  RC_ASSERT(checked_size(g.node_count, g.edges, m) == maximum);
  RC_ASSERT(m.size == maximum);
  RC_ASSERT(m.perfect == (2 * maximum == g.node_count));
  if (!m.cubic_bridgeless) RC_ASSERT(!m.note.empty());
}

RC_GTEST_PROP(AnyGraph, APlantedBridgeIsNamed, ()) {
  const testing::GraphWithBridge input = *testing::cubic_graphs_with_a_bridge();
  const testing::EdgeList edges = testing::edge_list(input.graph);
  const AnyGraphMatching m = match_any_graph(input.graph.node_count(), edges);
  RC_ASSERT(!m.cubic_bridgeless);
  RC_ASSERT(m.note.find("edge " + std::to_string(input.bridge) + " ") == 0);
  RC_ASSERT(m.size == testing::boost_matching_size(input.graph.node_count(), edges));
}

TEST(AnyGraph, NamesAnEndpointOutOfRange) {
  EXPECT_THROW(match_any_graph(2, {{0, 1}, {1, 2}}), GraphError);
}

// The BGL adaptor fills Boost's mate map as edmonds_maximum_cardinality_matching does.
using BoostGraph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
using Vertex = boost::graph_traits<BoostGraph>::vertex_descriptor;

RC_GTEST_PROP(BoostAdaptor, MatchesLikeEdmondsOnAnyGraph, ()) {
  const bool cubic = *rc::gen::arbitrary<bool>();
  testing::EdgeListGraph g;
  if (cubic) {
    const CubicGraph c = *rc::gen::arbitrary<CubicGraph>();
    g = {c.node_count(), testing::edge_list(c)};
  } else {
    g = *testing::general_graphs();
  }
  BoostGraph bg(g.node_count);
  for (auto [a, b] : g.edges) boost::add_edge(a, b, bg);
  std::vector<Vertex> mate(g.node_count), edmonds(g.node_count);
  const bool perfect = perfect_matching(bg, &mate[0], {.algorithm = Algorithm::gw});
  boost::edmonds_maximum_cardinality_matching(bg, &edmonds[0]);
  RC_ASSERT(boost::is_a_matching(bg, &mate[0]));
  const auto size = boost::matching_size(bg, &mate[0]);
  RC_ASSERT(size == boost::matching_size(bg, &edmonds[0]));
  RC_ASSERT(perfect == (2 * size == g.node_count));
  if (cubic) RC_ASSERT(perfect);
}

// A graph whose vertex descriptors are not indices (listS), with an index map of the caller's.
TEST(BoostAdaptor, TakesTheCallersVertexIndexMap) {
  using ListGraph = boost::adjacency_list<boost::listS, boost::listS, boost::undirectedS,
                                          boost::property<boost::vertex_index_t, int>>;
  using ListVertex = boost::graph_traits<ListGraph>::vertex_descriptor;
  const CubicGraph c = petersen_graph();
  ListGraph g;
  std::vector<ListVertex> vertex;
  for (NodeId v = 0; v < c.node_count(); ++v) vertex.push_back(boost::add_vertex(int(v), g));
  for (EdgeId e = 0; e < c.edge_count(); ++e)
    boost::add_edge(vertex[c.endpoints(e)[0]], vertex[c.endpoints(e)[1]], g);
  std::map<ListVertex, ListVertex> mate_of;
  auto mate = boost::make_assoc_property_map(mate_of);
  EXPECT_TRUE(perfect_matching(g, mate, get(boost::vertex_index, g)));
  const auto index = get(boost::vertex_index, g);
  EXPECT_TRUE(boost::is_a_matching(g, mate, index));
  EXPECT_EQ(boost::matching_size(g, mate, index), 5u);
}

TEST(AnyGraphCheapest, SkipsLoopsAndRefusesBadInput) {
  // A loop, however cheap, is never matched; the path 0-1-2 then pairs at its cheaper edge.
  const testing::EdgeList edges = {{0, 0}, {0, 1}, {1, 2}};
  const AnyGraphCheapestMatching m = cheapest_matching_any_graph(3, edges, {-100, 7, 4});
  EXPECT_EQ(m.size, 1u);
  EXPECT_FALSE(m.perfect);
  EXPECT_EQ(m.total_cost, 4);
  EXPECT_EQ(m.mate_edge, (std::vector<std::uint32_t>{kNoEdge, 2, 2}));
  EXPECT_THROW(cheapest_matching_any_graph(3, {{0, 3}}, {1}), GraphError);
  EXPECT_THROW(cheapest_matching_any_graph(3, edges, {1, 2}), std::invalid_argument);
  EXPECT_THROW(cheapest_matching_any_graph(3, edges, {1, 2, kMaxCost + 1}), std::invalid_argument);
}

// Cubic and bridgeless graphs take the perfect solver straight away (Petersen's theorem); with a
// bridge or another degree, the maximum one: both cost what LEMON's optimum costs when there is a
// perfect matching, in the edge list's ids.
RC_GTEST_PROP(AnyGraphCheapest, CubicBridgelessOrNotEqualsLemon, ()) {
  const bool bridgeless = *rc::gen::arbitrary<bool>();
  const CubicGraph c = bridgeless ? *rc::gen::arbitrary<CubicGraph>()
                                  : (*testing::cubic_graphs_with_a_bridge()).graph;
  const testing::EdgeList edges = testing::edge_list(c);
  const std::vector<std::int64_t> costs = *rc::gen::container<std::vector<std::int64_t>>(
      edges.size(), rc::gen::inRange<std::int64_t>(-50, 500));
  const AnyGraphCheapestMatching m = cheapest_matching_any_graph(c.node_count(), edges, costs, 2);
  std::int64_t total = 0;
  for (NodeId v = 0; v < c.node_count(); ++v) {
    const std::uint32_t e = m.mate_edge[v];
    if (e == kNoEdge) continue;
    RC_ASSERT(edges[e][0] == v || edges[e][1] == v);
    RC_ASSERT(m.mate_edge[edges[e][0] == v ? edges[e][1] : edges[e][0]] == e);
    if (edges[e][0] == v) total += costs[e];
  }
  RC_ASSERT(total == m.total_cost);
  const std::optional<std::int64_t> lemon =
      testing::lemon_min_cost_perfect(c.node_count(), edges, costs);
  RC_ASSERT(m.perfect == lemon.has_value());
  if (lemon) RC_ASSERT(m.total_cost == *lemon);
  RC_TAG(bridgeless ? "bridgeless" : "a bridge", m.perfect ? "perfect" : "not perfect");
}

// The BGL adaptor's minimum-cost matching on a graph with an edge_weight property of integers:
// a maximum matching (Boost's size) whose cost, read back through the mate map, is LEMON's
// weighted optimum when the graph has a perfect matching, and the doubled-graph solver's
// otherwise.
RC_GTEST_PROP(BoostAdaptor, MinCostMatchingIsTheCheapestMaximumOne, ()) {
  using WeightedGraph =
      boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                            boost::property<boost::edge_weight_t, int>>;
  using WeightedVertex = boost::graph_traits<WeightedGraph>::vertex_descriptor;
  testing::EdgeListGraph g;
  if (*rc::gen::arbitrary<bool>()) {  // cubic bridgeless: perfect, LEMON's optimum to meet
    const CubicGraph c = *rc::gen::arbitrary<CubicGraph>();
    g = {c.node_count(), testing::edge_list(c)};
  } else {
    g = *testing::general_graphs();
  }
  WeightedGraph bg(g.node_count);
  std::vector<Cost> costs;
  for (auto [a, b] : g.edges) {
    costs.push_back(*rc::gen::inRange(-40, 200));
    boost::add_edge(a, b, static_cast<int>(costs.back()), bg);
  }
  std::vector<WeightedVertex> mate(g.node_count), edmonds(g.node_count);
  const Cost total = min_cost_matching(bg, get(boost::edge_weight, bg), &mate[0]);
  boost::edmonds_maximum_cardinality_matching(bg, &edmonds[0]);
  RC_ASSERT(boost::is_a_matching(bg, &mate[0]));
  const auto size = boost::matching_size(bg, &mate[0]);
  RC_ASSERT(size == boost::matching_size(bg, &edmonds[0]));
  // The cost of the matched pairs: each at its cheapest edge (an optimum takes that one of
  // parallel edges; a loop is never matched).
  std::map<std::pair<NodeId, NodeId>, Cost> cheapest;
  testing::EdgeList simple;
  std::vector<Cost> simple_costs;
  for (std::size_t e = 0; e < g.edges.size(); ++e) {
    const auto [a, b] = g.edges[e];
    if (a == b) continue;
    simple.push_back(g.edges[e]);
    simple_costs.push_back(costs[e]);
    const auto [at, inserted] =
        cheapest.emplace(std::pair{std::min(a, b), std::max(a, b)}, costs[e]);
    if (!inserted) at->second = std::min(at->second, costs[e]);
  }
  Cost written = 0;
  for (NodeId v = 0; v < g.node_count; ++v) {
    const auto w = static_cast<NodeId>(mate[v]);
    if (mate[v] != boost::graph_traits<WeightedGraph>::null_vertex() && v < w)
      written += cheapest.at({v, w});
  }
  RC_ASSERT(written == total);
  if (2 * size == g.node_count) {
    RC_ASSERT(testing::lemon_min_cost_perfect(g.node_count, simple, simple_costs) == total);
  } else {
    RC_ASSERT(min_cost_maximum_matching(CsrGraph::from_edges(g.node_count, simple), simple_costs)
                  .total_cost == total);
  }
  RC_TAG(2 * size == g.node_count ? "perfect" : "not perfect");
}

}  // namespace
}  // namespace petersen
