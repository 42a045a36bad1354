#pragma once
// The graph renumbered in breadth-first order, for the weighted solver. Meshes bring no locality
// of their own: in fertility-sub3's dual the median gap between the ids of two adjacent nodes is
// 144,000 (a quarter of the faces: subdivision writes each child of every face in a block), so
// every neighbour the solver scans is a cache and TLB miss. In breadth-first order two adjacent
// nodes are at most two layers apart, and the region an alternating tree covers is a few runs
// of ids. Edge ids are kept (costs stay indexed by them); only node ids change.
//
// The renumbered graph is a view, not a copy: the solver builds its own adjacency from it once
// and reads it elsewhere only at set-up, so a copy would be ~200 MB of fresh memory on
// armadillo-sub2's dual (the copy's arrays and the edge list it was built from) for nothing.

#include <array>
#include <cstdint>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/huge_pages.hpp"

namespace petersen::weighted_detail {

struct BreadthFirstOrder {
  HugeVector<NodeId> new_node;  // by old id
  HugeVector<NodeId> old_node;  // by new id: the visiting order
};

/// Renumbers the nodes of `graph` in breadth-first order, component by component from the
/// smallest unvisited id. O(n + m), iterative.
template <class Graph>
BreadthFirstOrder breadth_first_order(const Graph& graph) {
  const std::uint32_t n = graph.node_count();
  BreadthFirstOrder order;
  order.new_node.assign(n, kNoNode);
  order.old_node.resize(n);
  std::uint32_t visited = 0;
  for (NodeId root = 0; root < n; ++root) {
    if (order.new_node[root] != kNoNode) continue;
    order.new_node[root] = visited;
    order.old_node[visited++] = root;
    for (std::uint32_t head = order.new_node[root]; head < visited; ++head) {
      const NodeId v = order.old_node[head];
      for (EdgeId e : graph.incident_edges(v)) {
        const NodeId w = graph.other_end(e, v);
        if (order.new_node[w] != kNoNode) continue;
        order.new_node[w] = visited;
        order.old_node[visited++] = w;
      }
    }
  }
  return order;
}

/// `graph` with node v standing for order.old_node[v]; edge e keeps its id. Both must outlive it.
template <class Graph>
class RenumberedGraph {
 public:
  RenumberedGraph(const Graph& graph, const BreadthFirstOrder& order)
      : graph_(graph), order_(order) {}

  std::uint32_t node_count() const { return graph_.node_count(); }
  std::uint32_t edge_count() const { return graph_.edge_count(); }
  std::array<NodeId, 2> endpoints(EdgeId e) const {
    const auto [a, b] = graph_.endpoints(e);
    return {order_.new_node[a], order_.new_node[b]};
  }
  NodeId other_end(EdgeId e, NodeId v) const {
    return order_.new_node[graph_.other_end(e, order_.old_node[v])];
  }
  /// In the input's order at that node, which need not be by edge id.
  auto incident_edges(NodeId v) const { return graph_.incident_edges(order_.old_node[v]); }

 private:
  const Graph& graph_;
  const BreadthFirstOrder& order_;
};

}  // namespace petersen::weighted_detail
