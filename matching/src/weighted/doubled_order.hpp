#pragma once
// The solver's rows (breadth_first_order.hpp) of the doubled graph of min_cost_matching and
// min_cost_maximum_matching (min_cost_matching.hpp: G, its copy G' and an edge v–v' per node),
// made straight from G. Node v of G becomes 2·σ(v) and its twin n + v becomes 2·σ(v) + 1, where σ
// is G's breadth-first order: each node sits beside its twin, and G' keeps G's locality. Edge ids
// are the doubled graph's: e, m + e and 2m + v. Making the doubled graph itself first, to copy it
// into these rows, would first-touch its edge list, its costs and its CsrGraph (about 40 bytes per
// doubled edge beside the rows' 32) only to free them: fresh pages, whose faulting in is what
// the doubled solve spends most on, on virtual machines above all.

#include <cstdint>
#include <span>
#include <utility>

#include "breadth_first_order.hpp"
#include "petersen/graph/csr_graph.hpp"

namespace petersen::weighted_detail {

/// The rows of the doubled graph (see the top) with `costs` by G's edge id and `pair_costs[v]`
/// for the edge v–v'. G's breadth-first order is taken component by component from the smallest
/// unvisited id (a node without edges is a component of its own), and the rows are written as the
/// search visits each node, as breadth_first_adjacency's are (it has just read the node's edges),
/// sorted by edge id: a node's edges of G (or G') in G's edge order, then its twin's edge, whose
/// id is the largest. O(n + m), iterative.
inline BreadthFirstAdjacency doubled_breadth_first_adjacency(const CsrGraph& graph,
                                                             std::span<const Cost> costs,
                                                             std::span<const Cost> pair_costs,
                                                             std::pmr::memory_resource* memory) {
  const std::uint32_t n = graph.node_count(), m = graph.edge_count();
  BreadthFirstAdjacency order{
      .new_node = std::pmr::vector<NodeId>(2 * std::size_t{n}, kNoNode, memory),
      .slots = std::pmr::vector<Slot>(memory),
      .first_slot = std::pmr::vector<std::size_t>(memory)};
  bool uniform = true;
  for (NodeId v = 0; v < n; ++v) uniform = uniform && graph.degree(v) == graph.degree(0);
  order.uniform_degree = uniform && n > 0 ? graph.degree(0) + 1 : 0;
  order.slots.resize(2 * (std::size_t{m} * 2 + n));
  if (order.uniform_degree == 0) order.first_slot.resize(2 * std::size_t{n} + 1);
  // G's search numbers v with 2·σ(v); its twin's number, one more, is set after.
  Slot* last = order.slots.data();
  const std::span<NodeId> number(order.new_node.data(), n);
  breadth_first_search(graph, costs, number, 2, memory, [&](NodeId head, NodeId v) {
    Slot* const own = last;
    for (EdgeId e : graph.incident_edges(v)) {
      *last++ = {2 * costs[e], e, order.new_node[graph.other_end(e, v)]};
    }
    sort_by_edge(own, last);
    const std::size_t degree = last - own;
    *last++ = {2 * pair_costs[v], 2 * m + v, 2 * head + 1};
    // The twin's row: the same edges in G', then the same edge v–v'.
    for (std::size_t k = 0; k < degree; ++k) {
      *last++ = {own[k].cost2, m + own[k].edge, own[k].other + 1};
    }
    *last++ = {2 * pair_costs[v], 2 * m + v, 2 * head};
    if (order.uniform_degree == 0) {
      order.first_slot[2 * head] = own - order.slots.data();
      order.first_slot[2 * head + 1] = own - order.slots.data() + degree + 1;
    }
  });
  for (NodeId v = 0; v < n; ++v) order.new_node[n + v] = order.new_node[v] + 1;
  if (order.uniform_degree == 0) order.first_slot[2 * std::size_t{n}] = order.slots.size();
  return order;
}

}  // namespace petersen::weighted_detail
