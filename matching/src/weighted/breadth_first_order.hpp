#pragma once
// The graph renumbered in breadth-first order, for the weighted solver. Meshes bring no locality
// of their own: in fertility-sub3's dual the median gap between the ids of two adjacent nodes is
// 144,000 (a quarter of the faces: subdivision writes each child of every face in a block), so
// every neighbour the solver scans is a cache and TLB miss. In breadth-first order two adjacent
// nodes are at most two layers apart, and the region an alternating tree covers is a few runs
// of ids. Edge ids are kept (costs stay indexed by them); only node ids change.

#include <array>
#include <cstdint>
#include <vector>

#include "petersen/graph/csr_graph.hpp"
#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/huge_pages.hpp"

namespace petersen::weighted_detail {

struct BreadthFirstCopy {
  CsrGraph graph;               // node new_node[v] is v; edge e keeps its id
  HugeVector<NodeId> new_node;  // by old id
};

/// Renumbers the nodes of `graph` in breadth-first order, component by component from the
/// smallest unvisited id. O(n + m), iterative.
template <class Graph>
BreadthFirstCopy breadth_first_copy(const Graph& graph) {
  const std::uint32_t n = graph.node_count(), m = graph.edge_count();
  BreadthFirstCopy copy;
  copy.new_node.assign(n, kNoNode);
  HugeVector<NodeId> queue(n);  // old ids in visiting order
  std::uint32_t visited = 0;
  for (NodeId root = 0; root < n; ++root) {
    if (copy.new_node[root] != kNoNode) continue;
    copy.new_node[root] = visited;
    queue[visited++] = root;
    for (std::uint32_t head = copy.new_node[root]; head < visited; ++head) {
      const NodeId v = queue[head];
      for (EdgeId e : graph.incident_edges(v)) {
        const NodeId w = graph.other_end(e, v);
        if (copy.new_node[w] != kNoNode) continue;
        copy.new_node[w] = visited;
        queue[visited++] = w;
      }
    }
  }
  std::vector<std::array<NodeId, 2>> ends(m);
  for (EdgeId e = 0; e < m; ++e) {
    const auto [a, b] = graph.endpoints(e);
    ends[e] = {copy.new_node[a], copy.new_node[b]};
  }
  copy.graph = CsrGraph::from_edges(n, ends);
  return copy;
}

}  // namespace petersen::weighted_detail
