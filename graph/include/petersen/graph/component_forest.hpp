#pragma once
// Components of a graph given by its edge list, by disjoint sets: the pairable graph's (which
// closed components the algorithms match), a surface's (its genus, with chosen cuts joined back),
// a triangulation's dual (one component for LRS).

#include <algorithm>
#include <cstdint>
#include <span>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/huge_pages.hpp"

namespace petersen {

/// Disjoint sets over the graph's edges: each node's parent, a root being its own. On huge pages,
/// so that a run takes it from the pool's freed ranges rather than from fresh memory.
class ComponentForest {
 public:
  /// The forest of the graph on `node_count` nodes whose edge e joins edge_ends[2e] and
  /// edge_ends[2e + 1].
  ComponentForest(std::uint32_t node_count, std::span<const NodeId> edge_ends)
      : parent_(node_count) {
    for (NodeId v = 0; v < node_count; ++v) parent_[v] = v;
    join(edge_ends);
  }
  /// Joins the ends of more edges, given the same way.
  void join(std::span<const NodeId> edge_ends) {
    for (std::size_t i = 0; i < edge_ends.size(); i += 2) {
      const NodeId a = find(edge_ends[i]), b = find(edge_ends[i + 1]);
      if (a != b) parent_[std::max(a, b)] = std::min(a, b);
    }
  }
  NodeId find(NodeId v) {
    while (parent_[v] != v) v = parent_[v] = parent_[parent_[v]];
    return v;
  }
  std::uint32_t root_count() const {
    std::uint32_t roots = 0;
    for (NodeId v = 0; v < parent_.size(); ++v) roots += parent_[v] == v;
    return roots;
  }

 private:
  HugeVector<NodeId> parent_;
};

}  // namespace petersen
