#pragma once
// A cubic graph's working copy for the pairing and augmentation passes (paper §3.1): each node's
// three neighbours side by side, in the order of its incident edges. A CubicGraph reaches a
// neighbour through the incident edge and then that edge's ends, two dependent loads at random
// places; here it is one load from the line that holds the node's other two neighbours. Built in
// one pass whose random loads (the edges' ends) are prefetched ahead, so PS and the augmenting
// searches, which visit about every node once each, pay for the indirection once instead of at
// every scan.
//
// The table is also a graph for the alternating forest (augment/alternating_forest.hpp), whose
// edges are half-edges: h = 3v + i is v's i-th edge, seen from v, and its far end is at [h]. An
// edge has two half-edges; the forest never compares edges, it only follows them, so either does.
// graph_edge(h) names the CubicGraph edge behind h, for writing the matching back.

#include <array>
#include <span>
#include <stdexcept>
#include <string>

#include "huge_pages.hpp"
#include "petersen/graph/cubic_graph.hpp"

namespace petersen {

class NeighbourTable {
 public:
  explicit NeighbourTable(const CubicGraph& graph)
      : graph_(graph), next_(make_huge_array<NodeId>(3 * std::size_t{graph.node_count()})) {
    // Half-edge ids 0..3n-1 must stay below kNoEdge.
    if (graph.node_count() > kNoEdge / 3)
      throw std::length_error("NeighbourTable: more than " + std::to_string(kNoEdge / 3) +
                              " nodes");
    constexpr NodeId kReadAhead = 16;
    const NodeId n = graph.node_count();
    for (NodeId v = 0; v < n; ++v) {
      if (v + kReadAhead < n) {
        for (EdgeId e : graph.incident_edges(v + kReadAhead))
          __builtin_prefetch(&graph.edge_ends()[2 * std::size_t{e}]);
      }
      const std::span<const EdgeId, 3> edges = graph.incident_edges(v);
      for (int i = 0; i < 3; ++i) next_[3 * std::size_t{v} + i] = graph.other_end(edges[i], v);
    }
  }

  const CubicGraph& graph() const { return graph_; }
  std::uint32_t node_count() const { return graph_.node_count(); }

  /// v's neighbours, the i-th across v's i-th incident edge.
  std::span<const NodeId, 3> neighbours(NodeId v) const {
    return std::span<const NodeId, 3>(&next_[3 * std::size_t{v}], 3);
  }

  // The half-edge graph.
  std::array<EdgeId, 3> incident_edges(NodeId v) const { return {3 * v, 3 * v + 1, 3 * v + 2}; }
  NodeId other_end(EdgeId h, NodeId v) const { return h / 3 == v ? next_[h] : h / 3; }
  /// The far end of h seen from its own node, h / 3.
  NodeId far_end(EdgeId h) const { return next_[h]; }
  std::array<NodeId, 2> endpoints(EdgeId h) const { return {h / 3, next_[h]}; }
  EdgeId graph_edge(EdgeId h) const { return graph_.incident_edges(h / 3)[h % 3]; }
  /// v's mate across the graph edge `mate_edge`: a look at v's own incidence list, not at the
  /// edge's ends elsewhere in memory.
  NodeId mate_node(NodeId v, EdgeId mate_edge) const {
    const std::span<const EdgeId, 3> edges = graph_.incident_edges(v);
    const int i = edges[0] == mate_edge ? 0 : edges[1] == mate_edge ? 1 : 2;
    return next_[3 * std::size_t{v} + i];
  }

 private:
  const CubicGraph& graph_;
  HugeArray<NodeId> next_;
};

}  // namespace petersen
