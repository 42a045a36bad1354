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

/// The breadth-first search both row builders run (this one and doubled_order.hpp's), component
/// by component from the smallest unvisited id. A node seen first gets number[v] = step · (its
/// place in the visiting order) (number starts all kNoNode); visit(place, v) then runs for each
/// node in that order, its neighbours numbered by then, so that a builder writes the node's row
/// from the edges the search has just read. O(n + m), iterative.
template <class Graph, class Visit>
void breadth_first_search(const Graph& graph, std::span<const Cost> costs, std::span<NodeId> number,
                          std::uint32_t step, std::pmr::memory_resource* memory, Visit visit) {
  const std::uint32_t n = graph.node_count();
  std::pmr::vector<NodeId> old_node(n, memory);  // by place: the visiting order, the queue
  std::uint32_t visited = 0;
  constexpr std::uint32_t kAhead = 8;
  for (NodeId root = 0; root < n; ++root) {
    if (number[root] != kNoNode) continue;
    number[root] = step * visited;
    old_node[visited++] = root;
    for (std::uint32_t head = visited - 1; head < visited; ++head) {
      // The node kAhead places ahead in the queue has its costs and its neighbours' numbers
      // requested now, which the visit below would otherwise wait for one cache miss at a time
      // (the queue's nodes are scattered over the input's arrays); a few places ahead is enough.
      if (head + kAhead < visited) {
        const NodeId ahead = old_node[head + kAhead];
        for (EdgeId e : graph.incident_edges(ahead)) {
          __builtin_prefetch(&costs[e]);
          __builtin_prefetch(&number[graph.other_end(e, ahead)]);
        }
      }
      const NodeId v = old_node[head];
      for (EdgeId e : graph.incident_edges(v)) {
        const NodeId w = graph.other_end(e, v);
        if (number[w] == kNoNode) {
          number[w] = step * visited;
          old_node[visited++] = w;
        }
      }
      visit(head, v);
    }
  }
}

/// A node's slots sorted by edge id, in place (a node has a handful). O(d²).
inline void sort_by_edge(Slot* first, Slot* last) {
  for (Slot* at = first + 1; at < last; ++at) {
    for (Slot* back = at; back != first && back[-1].edge > back->edge; --back)
      std::swap(back[-1], *back);
  }
}

/// Renumbers the nodes of `graph` in breadth-first order (breadth_first_search) and builds the
/// rows with `costs` (by edge id). O(n + m), iterative. Throws GraphError, naming the input's
/// node, when a node has no edge: no perfect matching.
template <class Graph>
BreadthFirstAdjacency breadth_first_adjacency(const Graph& graph, std::span<const Cost> costs,
                                              std::pmr::memory_resource* memory) {
  const std::uint32_t n = graph.node_count();
  BreadthFirstAdjacency order{.new_node = std::pmr::vector<NodeId>(n, kNoNode, memory),
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
  Slot* last = order.slots.data();
  breadth_first_search(graph, costs, order.new_node, 1, memory, [&](NodeId head, NodeId v) {
    if (order.uniform_degree == 0) order.first_slot[head] = last - order.slots.data();
    Slot* const first = last;
    for (EdgeId e : graph.incident_edges(v)) {
      *last++ = {2 * costs[e], e, order.new_node[graph.other_end(e, v)]};
    }
    sort_by_edge(first, last);
  });
  if (order.uniform_degree == 0) order.first_slot[n] = slot_count;
  return order;
}

}  // namespace petersen::weighted_detail
