#include "petersen/lemon_adapter/lemon_matching.hpp"

#include <lemon/matching.h>
#include <lemon/smart_graph.h>

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

}  // namespace petersen::lemon_adapter
