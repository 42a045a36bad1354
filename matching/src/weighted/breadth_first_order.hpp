#pragma once
// The graph renumbered in breadth-first order, as the weighted solver's own adjacency. Meshes
// bring no locality of their own: in fertility-sub3's dual the median gap between the ids of two
// adjacent nodes is 144,000 (a quarter of the faces: subdivision writes each child of every face
// in a block), so every neighbour the solver scans is a cache and TLB miss. In breadth-first
// order two adjacent nodes are at most two layers apart, and the region an alternating tree
// covers is a few runs of ids. Edge ids are kept (costs stay indexed by them); only node ids
// change.
//
// The rows are written as the search visits each node: it has just read the node's edges and
// their far ends (at random places of the input, whatever the order), so the rows cost only the
// edges' costs more. Built after the search instead, in the new order, they would read all of it
// again at random: set-up to the first greedy step (petersen_weighted_speed, medians of nine
// solves) takes 0.30 s on armadillo-sub2's dual against 0.41, 0.23 s on rocker-arm-sub3's
// against 0.34.

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <string>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/memory.hpp"
#include "petersen/matching/min_cost_matching.hpp"

namespace petersen::weighted_detail {

/// An edge as its end scans it: the doubled cost (the solver's duals are on 2·cost, see
/// blossom_solver.hpp), the edge's id and the far end, in one record, so that a scan reads one
/// run of memory per node instead of an edge id, then the edge's ends, then its cost, at three
/// random places.
struct Slot {
  Cost cost2;
  EdgeId edge;
  NodeId other;
};

struct BreadthFirstAdjacency {
  std::pmr::vector<NodeId> new_node;  // by the input's id
  /// New node v's slots, sorted by edge id (the order scans meet ties in then does not depend on
  /// the order the input lists a node's edges in): [first_slot[v], first_slot[v + 1]), or
  /// [d·v, d·v + d) when every node has degree d = uniform_degree (the dual of a closed mesh), and
  /// then first_slot is empty: the offset would be a cache miss before every scan's slots, a
  /// third of the even scans' samples on armadillo-sub2's dual.
  std::pmr::vector<Slot> slots;
  std::pmr::vector<std::size_t> first_slot;
  std::uint32_t uniform_degree = 0;

  std::uint32_t node_count() const { return static_cast<std::uint32_t>(new_node.size()); }
  std::span<const Slot> slots_of(NodeId v) const {
    if (uniform_degree != 0) [[likely]]
      return {slots.data() + std::size_t{v} * uniform_degree, uniform_degree};
    return {slots.data() + first_slot[v], slots.data() + first_slot[v + 1]};
  }
};

/// Renumbers the nodes of `graph` in breadth-first order, component by component from the
/// smallest unvisited id, and builds the rows with `costs` (by edge id). O(n + m), iterative.
/// Throws GraphError, naming the input's node, when a node has no edge: no perfect matching.
template <class Graph>
BreadthFirstAdjacency breadth_first_adjacency(const Graph& graph, std::span<const Cost> costs,
                                              std::pmr::memory_resource* memory) {
  const std::uint32_t n = graph.node_count();
  BreadthFirstAdjacency order{.new_node = std::pmr::vector<NodeId>(memory),
                              .slots = std::pmr::vector<Slot>(memory),
                              .first_slot = std::pmr::vector<std::size_t>(memory)};
  std::size_t slot_count = 0;
  bool uniform = true;
  for (NodeId v = 0; v < n; ++v) {
    const std::size_t degree = graph.incident_edges(v).size();
    if (degree == 0) {
      throw GraphError("node " + std::to_string(v) + " has no edge: no perfect matching");
    }
    uniform = uniform && (v == 0 || degree == slot_count / v);
    slot_count += degree;
  }
  order.uniform_degree = uniform && n > 0 ? static_cast<std::uint32_t>(slot_count / n) : 0;
  if (order.uniform_degree == 0) order.first_slot.resize(std::size_t{n} + 1);
  order.slots.resize(slot_count);
  order.new_node.assign(n, kNoNode);
  std::pmr::vector<NodeId> old_node(n,
                                    memory);  // by new id: the visiting order, the search's queue
  std::uint32_t visited = 0;
  constexpr std::uint32_t kAhead = 8;
  Slot* last = order.slots.data();
  for (NodeId root = 0; root < n; ++root) {
    if (order.new_node[root] != kNoNode) continue;
    order.new_node[root] = visited;
    old_node[visited++] = root;
    for (NodeId head = order.new_node[root]; head < visited; ++head) {
      // The node 8 places ahead in the queue has its costs and its neighbours' new ids
      // requested now, which the visit below would otherwise wait for one miss at a time:
      // the search takes 0.077 s on rocker-arm-sub3's dual against 0.095 without, 4.5 ms on
      // armadillo's against 5.5 (medians of five; 4, 16 and 32 places ahead do about as well).
      if (head + kAhead < visited) {
        const NodeId ahead = old_node[head + kAhead];
        for (EdgeId e : graph.incident_edges(ahead)) {
          __builtin_prefetch(&costs[e]);
          __builtin_prefetch(&order.new_node[graph.other_end(e, ahead)]);
        }
      }
      const NodeId v = old_node[head];
      if (order.uniform_degree == 0) order.first_slot[head] = last - order.slots.data();
      Slot* const first = last;
      for (EdgeId e : graph.incident_edges(v)) {
        const NodeId w = graph.other_end(e, v);
        if (order.new_node[w] == kNoNode) {
          order.new_node[w] = visited;
          old_node[visited++] = w;
        }
        *last++ = {2 * costs[e], e, order.new_node[w]};
        for (Slot* at = last - 1; at != first && at[-1].edge > at->edge; --at)
          std::swap(at[-1], *at);
      }
    }
  }
  if (order.uniform_degree == 0) order.first_slot[n] = slot_count;
  return order;
}

}  // namespace petersen::weighted_detail
