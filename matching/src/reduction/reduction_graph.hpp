#pragma once
// The cubic multigraph that Frink's reductions (paper Appendix A) shrink in place: flat arrays of
// edge ends and node slots, new edges appended, removed nodes marked dead.

#include <array>
#include <cstdint>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/memory.hpp"

namespace petersen::reduction {

/// One reduction as it is undone. Frink step on e = {u, v}: u's other edges a1 = {u, x1},
/// a2 = {u, x2}, v's other edges b3 = {v, x3}, b4 = {v, x4}, ordered so that the new edge n13
/// joins x1 and x3 and n24 joins x2 and x4; a1 is the forbidden edge, so n13 is the next one.
/// Digon step (u has f = a1 and a digon {e, a2} to v, whose third edge is b3): the new edge n13
/// joins the far ends of a1 and b3, and b4 = n24 = kNoEdge.
struct Step {
  NodeId u, v;
  EdgeId e, a1, a2, b3, b4, n13, n24;
};

class ReductionGraph {
 public:
  /// Copies `graph`, with room for `extra_edges` new edges.
  ReductionGraph(const CubicGraph& graph, std::uint32_t extra_edges);
  /// Takes over the arrays of a cubic graph (as CubicGraph::node_edges() and edge_ends() lay
  /// them out), with room for `extra_edges` new edges: no copy, and no reallocation when
  /// `edge_ends` already has the capacity.
  ReductionGraph(std::pmr::vector<EdgeId> node_edges, std::pmr::vector<NodeId> edge_ends,
                 std::uint32_t extra_edges);

  std::uint32_t node_count() const { return static_cast<std::uint32_t>(slots_.size() / 3); }
  std::uint32_t edge_count() const { return static_cast<std::uint32_t>(ends_.size() / 2); }
  NodeId end(EdgeId e, int k) const { return ends_[2 * std::size_t{e} + k]; }
  NodeId other_end(EdgeId e, NodeId v) const { return end(e, 0) ^ end(e, 1) ^ v; }
  EdgeId slot(NodeId v, int k) const { return slots_[3 * std::size_t{v} + k]; }
  bool alive(NodeId v) const { return alive_[v] != 0; }

  /// Applies a Frink or digon step whose n13/n24 are still unset; fills them in. O(1).
  void apply(Step& step);

 private:
  EdgeId add_edge(NodeId a, NodeId b);
  void replace_slot(NodeId v, EdgeId old_edge, EdgeId new_edge);

  std::pmr::vector<NodeId> ends_;
  std::pmr::vector<EdgeId> slots_;
  std::pmr::vector<std::uint8_t> alive_;
};

}  // namespace petersen::reduction
