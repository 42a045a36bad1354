#include "petersen/graph/connectivity.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include "petersen/generators/graph_generators.hpp"

namespace petersen {
namespace {

// Brute force: e is a bridge iff removing it raises the component count.
bool is_bridge_brute_force(const CubicGraph& g, EdgeId removed) {
  std::vector<int> seen(g.node_count(), 0);
  auto [a, b] = g.endpoints(removed);
  std::vector<NodeId> stack = {a};
  seen[a] = 1;
  while (!stack.empty()) {
    NodeId v = stack.back();
    stack.pop_back();
    for (EdgeId e : g.incident_edges(v)) {
      if (e == removed) continue;
      NodeId w = g.other_end(e, v);
      if (!seen[w]) seen[w] = 1, stack.push_back(w);
    }
  }
  return !seen[b];
}

// Two copies of K4 minus an edge, joined by a bridge between the two degree-2 nodes... made cubic:
// each side is K4 with one edge subdivided, the subdivision nodes joined by the bridge.
CubicGraph two_blobs_with_bridge() {
  std::vector<std::array<NodeId, 2>> edges;
  for (NodeId base : {0u, 5u}) {
    NodeId a = base, b = base + 1, c = base + 2, d = base + 3, s = base + 4;
    edges.insert(edges.end(), {{a, b}, {a, c}, {a, d}, {b, c}, {b, d}, {c, s}, {s, d}});
  }
  edges.push_back({4, 9});
  return CubicGraph::from_edges(10, edges);
}

TEST(Connectivity, FindsTheBridge) {
  CubicGraph g = two_blobs_with_bridge();
  auto bridge = find_bridge(g);
  ASSERT_TRUE(bridge.has_value());
  EXPECT_EQ(g.endpoints(*bridge), (std::array<NodeId, 2>{4, 9}));
  try {
    validate_connected_bridgeless(g);
    FAIL() << "a bridge was accepted";
  } catch (const GraphError& e) {
    EXPECT_NE(std::string(e.what()).find("(4-9) is a bridge"), std::string::npos) << e.what();
  }
}

TEST(Connectivity, ParallelEdgesAreNotBridges) {
  EXPECT_FALSE(find_bridge(theta_graph()).has_value());
  EXPECT_FALSE(find_bridge(prism(2)).has_value());
  EXPECT_FALSE(find_bridge(necklace(5)).has_value());
}

TEST(Connectivity, CountsComponents) {
  std::vector<std::array<NodeId, 2>> edges = {{0, 1}, {0, 1}, {0, 1}, {2, 3}, {2, 3}, {2, 3}};
  CubicGraph g = CubicGraph::from_edges(4, edges);
  EXPECT_EQ(count_components(g), 2u);
  EXPECT_THROW(validate_connected_bridgeless(g), GraphError);
  EXPECT_NO_THROW(validate_bridgeless(g));
}

TEST(Connectivity, DeepGraphDoesNotOverflowTheStack) {
  // A necklace of 2^20 diamonds: DFS depth ~4M, far beyond any call stack.
  CubicGraph g = necklace(1u << 20);
  EXPECT_NO_THROW(validate_connected_bridgeless(g));
}

RC_GTEST_PROP(Connectivity, FindBridgeAgreesWithBruteForce, ()) {
  // Random cubic multigraphs glued by a possible bridge: two random halves joined by one edge
  // after splitting an edge on each side.
  const auto n1 = *rc::gen::inRange<std::uint32_t>(1, 8) * 2;
  const auto n2 = *rc::gen::inRange<std::uint32_t>(1, 8) * 2;
  const bool join = *rc::gen::arbitrary<bool>();
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  CubicGraph a = random_cubic_bridgeless(n1, seed), b = random_cubic_bridgeless(n2, seed + 1);
  std::vector<std::array<NodeId, 2>> edges;
  for (EdgeId e = 0; e < a.edge_count(); ++e) edges.push_back(a.endpoints(e));
  for (EdgeId e = 0; e < b.edge_count(); ++e) {
    auto [x, y] = b.endpoints(e);
    edges.push_back({x + n1, y + n1});
  }
  std::uint32_t n = n1 + n2;
  if (join) {
    // Subdivide edge 0 of each side with nodes s, t and join s-t: a bridge.
    NodeId s = n, t = n + 1;
    auto [x, y] = edges[0];
    edges[0] = {x, s};
    edges.push_back({s, y});
    auto [p, q] = edges[a.edge_count()];
    edges[a.edge_count()] = {p, t};
    edges.push_back({t, q});
    edges.push_back({s, t});
    n += 2;
  }
  CubicGraph g = CubicGraph::from_edges(n, edges);
  bool any_bridge = false;
  for (EdgeId e = 0; e < g.edge_count(); ++e) any_bridge |= is_bridge_brute_force(g, e);
  auto found = find_bridge(g);
  RC_ASSERT(found.has_value() == any_bridge);
  if (found) RC_ASSERT(is_bridge_brute_force(g, *found));
  RC_ASSERT(count_components(g) == (join ? 1u : 2u));
}

}  // namespace
}  // namespace petersen
