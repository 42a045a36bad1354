#include "reduction/brute_force.hpp"

#include <array>
#include <vector>

#include "petersen/graph/connectivity.hpp"

namespace petersen::reduction {

bool is_connected_bridgeless(const ReductionGraph& graph, std::uint32_t components,
                             const Step* step, bool h1) {
  std::vector<NodeId> local(graph.node_count(), kNoNode);
  std::uint32_t n = 0;
  for (NodeId v = 0; v < graph.node_count(); ++v)
    if (graph.alive(v) && (!step || (v != step->u && v != step->v))) local[v] = n++;
  std::vector<std::array<NodeId, 2>> edges;
  for (NodeId v = 0; v < graph.node_count(); ++v) {
    if (local[v] == kNoNode) continue;
    for (int k = 0; k < 3; ++k) {
      const EdgeId e = graph.slot(v, k);
      const NodeId w = graph.other_end(e, v);
      if (w == v) return false;  // a loop leaves its node a bridge
      if (graph.end(e, 0) == v && local[w] != kNoNode) edges.push_back({local[v], local[w]});
    }
  }
  if (step) {
    const NodeId x1 = graph.other_end(step->a1, step->u), x2 = graph.other_end(step->a2, step->u);
    const NodeId x3 = graph.other_end(step->b3, step->v), x4 = graph.other_end(step->b4, step->v);
    const std::array<NodeId, 2> p = h1 ? std::array{x3, x4} : std::array{x4, x3};
    if (x1 == p[0] || x2 == p[1]) return false;  // a loop leaves its node a bridge
    edges.push_back({local[x1], local[p[0]]});
    edges.push_back({local[x2], local[p[1]]});
  }
  const CubicGraph h = CubicGraph::from_edges(n, edges);
  return count_components(h) == components && !find_bridge(h);
}

}  // namespace petersen::reduction
