#pragma once
// The floor every speed ratio in bench/ is measured against: one plain breadth-first search over
// every component of the graph. It allocates its own arrays, as every algorithm run through
// petersen's front door (or a peer's) does, so both sides of a ratio pay for their memory.

#include <cstdint>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"

namespace petersen::bench {

/// Visits every node and edge once; returns the number of nodes reached (all of them).
inline std::uint32_t bfs_floor(const CubicGraph& graph) {
  std::vector<std::uint8_t> seen(graph.node_count(), 0);
  std::vector<NodeId> queue(graph.node_count());
  std::uint32_t tail = 0;
  for (NodeId root = 0; root < graph.node_count(); ++root) {
    if (seen[root]) continue;
    seen[root] = 1;
    std::uint32_t head = tail;
    queue[tail++] = root;
    while (head < tail) {
      const NodeId v = queue[head++];
      for (EdgeId e : graph.incident_edges(v)) {
        const NodeId w = graph.other_end(e, v);
        if (!seen[w]) {
          seen[w] = 1;
          queue[tail++] = w;
        }
      }
    }
  }
  return tail;
}

}  // namespace petersen::bench
