#pragma once
// A general multigraph in compressed sparse rows: the input of the maximum-matching fallback.

#include <array>
#include <cstdint>
#include <span>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/memory.hpp"

namespace petersen {

/// A multigraph of any degrees: nodes 0..n-1, edges 0..m-1, parallel edges allowed, no loops.
/// Endpoints of edge e are at edge_ends[2e], edge_ends[2e+1]; the edges of node v are
/// node_edges[offsets[v]..offsets[v+1]), in edge-id order. Construction is O(n + m).
class CsrGraph {
 public:
  CsrGraph() = default;

  /// Builds the graph from an edge list; throws GraphError naming the first loop or the first
  /// endpoint out of range. The graph's arrays are allocated from `memory`.
  static CsrGraph from_edges(std::uint32_t node_count, std::span<const std::array<NodeId, 2>> edges,
                             std::pmr::memory_resource* memory = std::pmr::get_default_resource());

  std::uint32_t node_count() const { return static_cast<std::uint32_t>(offsets_.size() - 1); }
  std::uint32_t edge_count() const { return static_cast<std::uint32_t>(edge_ends_.size() / 2); }

  std::array<NodeId, 2> endpoints(EdgeId e) const {
    return {edge_ends_[2 * e], edge_ends_[2 * e + 1]};
  }
  /// The endpoint of e that is not v (v must be an endpoint of e).
  NodeId other_end(EdgeId e, NodeId v) const {
    return edge_ends_[2 * e] ^ edge_ends_[2 * e + 1] ^ v;
  }
  /// The edges at v; a parallel edge appears once per copy.
  std::span<const NodeId> edge_ends() const { return edge_ends_; }
  std::span<const EdgeId> incident_edges(NodeId v) const {
    return std::span<const EdgeId>(node_edges_.data() + offsets_[v], offsets_[v + 1] - offsets_[v]);
  }
  std::uint32_t degree(NodeId v) const { return offsets_[v + 1] - offsets_[v]; }

 private:
  explicit CsrGraph(std::pmr::memory_resource* memory)
      : offsets_(1, 0, memory), node_edges_(memory), edge_ends_(memory) {}

  // On the caller's resource (memory.hpp): a caller building graphs of millions of nodes one after
  // the other (the out-of-core parts) may hand in one that reuses their pages.
  std::pmr::vector<std::uint32_t> offsets_ = std::pmr::vector<std::uint32_t>(1, 0);
  std::pmr::vector<EdgeId> node_edges_;
  std::pmr::vector<NodeId> edge_ends_;
};

}  // namespace petersen
