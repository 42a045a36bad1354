#include "petersen/lemon_adapter/lemon_matching.hpp"

#include <lemon/matching.h>
#include <lemon/smart_graph.h>

#include <cstdint>

namespace petersen::lemon_adapter {

void maximum_matching(std::uint32_t node_count,
                      const std::vector<std::array<std::uint32_t, 2>>& edges,
                      std::uint32_t* mate_edge, bool greedy_start) {
  lemon::SmartGraph graph;
  graph.reserveNode(static_cast<int>(node_count));
  graph.reserveEdge(static_cast<int>(edges.size()));
  for (std::uint32_t v = 0; v < node_count; ++v) graph.addNode();
  // SmartGraph numbers nodes and edges in insertion order, so ids are our indices.
  for (auto [a, b] : edges) {
    graph.addEdge(graph.nodeFromId(static_cast<int>(a)), graph.nodeFromId(static_cast<int>(b)));
  }
  lemon::MaxMatching<lemon::SmartGraph> matcher(graph);
  if (greedy_start) {
    matcher.greedyInit();
  } else {
    matcher.init();
  }
  matcher.startSparse();
  for (std::uint32_t v = 0; v < node_count; ++v) {
    auto arc = matcher.matching(graph.nodeFromId(static_cast<int>(v)));
    mate_edge[v] = arc == lemon::INVALID
                       ? kUnmatched
                       : static_cast<std::uint32_t>(graph.id(lemon::SmartGraph::Edge(arc)));
  }
}

bool min_cost_perfect_matching(std::uint32_t node_count,
                               const std::vector<std::array<std::uint32_t, 2>>& edges,
                               const std::vector<std::int64_t>& costs, std::uint32_t* mate_edge,
                               std::int64_t& total_cost) {
  lemon::SmartGraph graph;
  graph.reserveNode(static_cast<int>(node_count));
  graph.reserveEdge(static_cast<int>(edges.size()));
  for (std::uint32_t v = 0; v < node_count; ++v) graph.addNode();
  for (auto [a, b] : edges) {
    graph.addEdge(graph.nodeFromId(static_cast<int>(a)), graph.nodeFromId(static_cast<int>(b)));
  }
  lemon::SmartGraph::EdgeMap<long long> weight(graph);
  for (std::size_t e = 0; e < edges.size(); ++e) {
    weight[graph.edgeFromId(static_cast<int>(e))] = -static_cast<long long>(costs[e]);
  }
  lemon::MaxWeightedPerfectMatching<lemon::SmartGraph, lemon::SmartGraph::EdgeMap<long long>>
      matcher(graph, weight);
  if (!matcher.run()) return false;
  for (std::uint32_t v = 0; v < node_count; ++v) {
    auto arc = matcher.matching(graph.nodeFromId(static_cast<int>(v)));
    mate_edge[v] = static_cast<std::uint32_t>(graph.id(lemon::SmartGraph::Edge(arc)));
  }
  total_cost = -static_cast<std::int64_t>(matcher.matchingWeight());
  return true;
}

}  // namespace petersen::lemon_adapter
