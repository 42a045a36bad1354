#pragma once
// The project's disjoint sets (union-find), over dense node ids: the components of a graph given
// by its edge list (the pairable graph's closed components, a surface's genus with chosen cuts
// joined back, a triangulation's dual for LRS), or sets joined one pair at a time (unite).

#include <algorithm>
#include <cstdint>
#include <span>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/memory.hpp"

namespace petersen {

/// Disjoint sets of nodes 0..n-1: each node's parent, a root being its own, and every root the
/// smallest node of its set (a join hangs the larger root under the smaller), so that roots
/// come out in the order of the sets' first nodes. find halves the path it walks: O(log n)
/// amortised per find. On the default memory resource (a program's pool, where it sets one, hands
/// it memory the run freed rather than fresh pages; memory.hpp).
class ComponentForest {
 public:
  /// `node_count` singletons.
  explicit ComponentForest(std::uint32_t node_count) : parent_(node_count) {
    for (NodeId v = 0; v < node_count; ++v) parent_[v] = v;
  }
  /// The components of the graph on `node_count` nodes whose edge e joins edge_ends[2e] and
  /// edge_ends[2e + 1].
  ComponentForest(std::uint32_t node_count, std::span<const NodeId> edge_ends)
      : ComponentForest(node_count) {
    join(edge_ends);
  }
  /// Joins the ends of more edges, given the same way.
  void join(std::span<const NodeId> edge_ends) {
    for (std::size_t i = 0; i < edge_ends.size(); i += 2) unite(edge_ends[i], edge_ends[i + 1]);
  }
  /// Joins the sets of a and b; false when they were one set already.
  bool unite(NodeId a, NodeId b) {
    a = find(a), b = find(b);
    if (a == b) return false;
    parent_[std::max(a, b)] = std::min(a, b);
    return true;
  }
  /// The root of v's set: its smallest node.
  NodeId find(NodeId v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  /// The number of sets.
  std::uint32_t root_count() const {
    std::uint32_t roots = 0;
    for (NodeId v = 0; v < parent_.size(); ++v) roots += parent_[v] == v;
    return roots;
  }

 private:
  std::pmr::vector<NodeId> parent_;
};

}  // namespace petersen
