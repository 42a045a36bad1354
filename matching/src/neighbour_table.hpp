#pragma once
// A cubic graph's working copy for the pairing and augmentation passes (paper §3.1): each node's
// three neighbours side by side, in the order of its incident edges, and the node's search state
// for the augmentation (augment/search_slot.hpp).
//
// Why: a CubicGraph reaches a neighbour through the incident edge and then that edge's ends, two
// dependent loads at random places; here it is one load from the line that holds the node's
// other neighbours. PS and the augmenting searches visit about every node once each, so the
// indirection is paid once, in one pass whose random loads (the edges' ends) are prefetched
// ahead. The search state lives here so that PS writes it in the sequential pass in which it
// writes the matching, instead of the forest reading the matching again in a pass of its own.
// (Neighbours and state in one 32-byte record, one line per scanned node, made the searches
// 15 % faster and PS, at the wider stride, as much slower: measured on armadillo-sub2's dual.)
//
// The table is also a graph for the alternating forest (augment/alternating_forest.hpp), whose
// edges are half-edges: h = 3v + i is v's i-th edge, seen from v, and its far end is at [h]. An
// edge has two half-edges; the forest never compares edges, it only follows them, so either does.
// graph_edge(h) names the CubicGraph edge behind h, for writing the matching back.
//
// A table built over neighbour rows the caller holds (perfect_partners) has no CubicGraph behind
// it: it reads the rows in place, and the matching lives in the search state only (each slot's
// mate). That is the lean form for a caller that needs only who is paired with whom: 12 bytes per
// node of rows plus the 16 of the state, where a graph and its table take 24 + 28.

#include <array>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "augment/search_slot.hpp"
#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/memory.hpp"

namespace petersen {

class NeighbourTable {
 public:
  /// With `mate` (a mate edge per node, kNoEdge when free), the search state starts from that
  /// matching; without it, it is left for start_search() to write, node by node.
  /// The table's arrays are allocated from `memory`.
  explicit NeighbourTable(const CubicGraph& graph, const std::pmr::vector<EdgeId>* mate = nullptr,
                          std::pmr::memory_resource* memory = std::pmr::get_default_resource())
      : graph_(&graph),
        node_count_(graph.node_count()),
        own_rows_(make_raw_array<NodeId>(3 * std::size_t{graph.node_count()}, memory)),
        next_(own_rows_.get()),
        slots_(make_raw_array<augment_detail::Slot>(graph.node_count(), memory)) {
    check_size(graph.node_count());
    graph.write_neighbour_rows(own_rows_.get());
    if (mate == nullptr) return;
    for (NodeId v = 0; v < graph.node_count(); ++v) {
      const EdgeId e = (*mate)[v];
      start_search(v, e == kNoEdge ? -1 : graph.edge_index(v, e));
    }
  }

  /// Over neighbour rows (CubicGraph::into_neighbour_rows) that the caller keeps alive and
  /// unchanged while the table lives; the search state is left for start_search() to write.
  explicit NeighbourTable(std::span<const NodeId> rows,
                          std::pmr::memory_resource* memory = std::pmr::get_default_resource())
      : node_count_(static_cast<std::uint32_t>(check_size(rows.size() / 3))),
        next_(rows.data()),
        slots_(make_raw_array<augment_detail::Slot>(node_count_, memory)) {}

  /// The graph behind the table; nullptr for a table over rows.
  const CubicGraph* graph() const { return graph_; }
  std::uint32_t node_count() const { return node_count_; }

  /// v's neighbours, the i-th across v's i-th incident edge.
  std::span<const NodeId, 3> neighbours(NodeId v) const {
    return std::span<const NodeId, 3>(&next_[3 * std::size_t{v}], 3);
  }
  /// The index, among u's three edges, of the edge that v's i-th edge names (u its neighbour
  /// there): the one place in u's row that holds v, except across parallel edges, where the edge
  /// ids decide when `exact` (mate edges are to be written); otherwise any copy does, each leading
  /// to the same node. The greedy pairings keep it for their final pass (start_searches).
  int index_across(NodeId v, int i, NodeId u, bool exact) const {
    const std::span<const NodeId, 3> row = neighbours(u);
    if ((row[0] == v) + (row[1] == v) + (row[2] == v) == 1 || !exact) {
      return row[0] == v ? 0 : row[1] == v ? 1 : 2;
    }
    return graph_->edge_index(u, graph_->incident_edge(v, i));
  }

  /// A greedy pairing's last pass, in one sequential sweep: each node v paired across its edge
  /// paired_index(v) (free when < 0) gets its fresh search state and, with `mate`, its mate edge
  /// (looked up at pairing time, v's incidence list would be a cache miss of its own on every
  /// pairing). Returns the number of nodes left free.
  template <class PairedIndex>
  std::uint32_t start_searches(PairedIndex paired_index, std::pmr::vector<EdgeId>* mate) {
    std::uint32_t unpaired = 0;
    for (NodeId v = 0; v < node_count_; ++v) {
      const int i = paired_index(v);
      if (i >= 0 && mate != nullptr) (*mate)[v] = graph_->incident_edge(v, i);
      unpaired += i < 0;
      start_search(v, i);
    }
    return unpaired;
  }

  /// Writes v's fresh search state, v matched to its i-th neighbour (free when i < 0).
  void start_search(NodeId v, int i) {
    slots_[v] = {i < 0 ? kNoNode : next_[3 * std::size_t{v} + i], 0, augment_detail::kNone, v};
  }
  /// v's search state: the forest's scratch, not the graph, so a const table hands it out.
  augment_detail::Slot& slot(NodeId v) const { return slots_[v]; }

  // The half-edge graph.
  std::array<EdgeId, 3> incident_edges(NodeId v) const { return {3 * v, 3 * v + 1, 3 * v + 2}; }
  NodeId other_end(EdgeId h, NodeId v) const { return h / 3 == v ? next_[h] : h / 3; }
  /// The far end of h seen from its own node, h / 3.
  NodeId far_end(EdgeId h) const { return next_[h]; }
  std::array<NodeId, 2> endpoints(EdgeId h) const { return {h / 3, next_[h]}; }
  /// The CubicGraph edge behind h; only for a table built from a graph.
  EdgeId graph_edge(EdgeId h) const { return graph_->incident_edges(h / 3)[h % 3]; }

 private:
  // Half-edge ids 3v + i must stay below kNoEdge. Returns `nodes`.
  static std::size_t check_size(std::size_t nodes) {
    if (nodes > kNoEdge / 3)
      throw std::length_error("NeighbourTable: more than " + std::to_string(kNoEdge / 3) +
                              " nodes");
    return nodes;
  }

  const CubicGraph* graph_ = nullptr;
  std::uint32_t node_count_;
  RawArray<NodeId> own_rows_;  // the rows, when built from a graph
  const NodeId* next_;
  RawArray<augment_detail::Slot> slots_;
};

}  // namespace petersen
