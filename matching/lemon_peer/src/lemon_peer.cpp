#include "petersen/lemon_peer/lemon_peer.hpp"

#include <lemon/matching.h>
#include <lemon/smart_graph.h>

namespace petersen::lemon_peer {

namespace {

// The graph of the flat edge-end array. SmartGraph numbers nodes and edges in insertion order, so
// its ids are our indices.
void fill(lemon::SmartGraph& graph, std::uint32_t node_count, const std::uint32_t* edge_ends,
          std::uint32_t edge_count) {
  graph.reserveNode(static_cast<int>(node_count));
  graph.reserveEdge(static_cast<int>(edge_count));
  for (std::uint32_t v = 0; v < node_count; ++v) graph.addNode();
  for (std::uint32_t e = 0; e < edge_count; ++e) {
    graph.addEdge(graph.nodeFromId(static_cast<int>(edge_ends[2 * std::size_t{e}])),
                  graph.nodeFromId(static_cast<int>(edge_ends[2 * std::size_t{e} + 1])));
  }
}

}  // namespace

void maximum_matching(std::uint32_t node_count, const std::uint32_t* edge_ends,
                      std::uint32_t edge_count, std::uint32_t* mate_edge) {
  lemon::SmartGraph graph;
  fill(graph, node_count, edge_ends, edge_count);
  lemon::MaxMatching<lemon::SmartGraph> matcher(graph);
  // run() would switch to init() + startDense() on graphs with m >= 2n; the peer keeps one
  // procedure on every input.
  matcher.greedyInit();
  matcher.startSparse();
  for (std::uint32_t v = 0; v < node_count; ++v) {
    auto arc = matcher.matching(graph.nodeFromId(static_cast<int>(v)));
    mate_edge[v] = arc == lemon::INVALID
                       ? 0xFFFFFFFFu
                       : static_cast<std::uint32_t>(graph.id(lemon::SmartGraph::Edge(arc)));
  }
}

bool min_cost_perfect_matching(std::uint32_t node_count, const std::uint32_t* edge_ends,
                               std::uint32_t edge_count, const std::int64_t* costs,
                               std::uint32_t* mate_edge, std::int64_t& total_cost) {
  lemon::SmartGraph graph;
  fill(graph, node_count, edge_ends, edge_count);
  lemon::SmartGraph::EdgeMap<long long> weight(graph);
  for (std::uint32_t e = 0; e < edge_count; ++e) {
    weight[graph.edgeFromId(static_cast<int>(e))] = -static_cast<long long>(costs[e]);
  }
  lemon::MaxWeightedPerfectMatching<lemon::SmartGraph, lemon::SmartGraph::EdgeMap<long long>>
      matcher(graph, weight);
  if (!matcher.run()) return false;
  for (std::uint32_t v = 0; v < node_count; ++v) {
    const auto arc = matcher.matching(graph.nodeFromId(static_cast<int>(v)));
    mate_edge[v] = static_cast<std::uint32_t>(graph.id(lemon::SmartGraph::Edge(arc)));
  }
  total_cost = -static_cast<std::int64_t>(matcher.matchingWeight());
  return true;
}

}  // namespace petersen::lemon_peer
