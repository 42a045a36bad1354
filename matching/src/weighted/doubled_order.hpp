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

#include "breadth_first_order.hpp"
#include "petersen/graph/csr_graph.hpp"

namespace petersen::weighted_detail {

/// G's breadth-first order, component by component from the smallest unvisited id (a node
/// without edges is a component of its own): the old id of each new id. O(n + m), iterative.
inline std::pmr::vector<NodeId> breadth_first_visit(const CsrGraph& graph,
                                                    std::pmr::memory_resource* memory) {
  const std::uint32_t n = graph.node_count();
  std::pmr::vector<NodeId> old_node(n, memory);
  std::pmr::vector<std::uint8_t> seen(n, 0, memory);
  std::uint32_t visited = 0;
  for (NodeId root = 0; root < n; ++root) {
    if (seen[root]) continue;
    seen[root] = 1;
    old_node[visited++] = root;
    for (std::uint32_t head = visited - 1; head < visited; ++head) {
      const NodeId v = old_node[head];
      for (EdgeId e : graph.incident_edges(v)) {
        const NodeId w = graph.other_end(e, v);
        if (!seen[w]) {
          seen[w] = 1;
          old_node[visited++] = w;
        }
      }
    }
  }
  return old_node;
}

/// The rows of the doubled graph (see the top) with `costs` by G's edge id and `pair_costs[v]`
/// for the edge v–v'. Rows sorted by edge id, as breadth_first_adjacency's: a node's edges of G
/// (or G') in G's edge order, then its twin's edge, whose id is the largest. O(n + m).
inline BreadthFirstAdjacency doubled_breadth_first_adjacency(const CsrGraph& graph,
                                                             std::span<const Cost> costs,
                                                             std::span<const Cost> pair_costs,
                                                             std::pmr::memory_resource* memory) {
  const std::uint32_t n = graph.node_count(), m = graph.edge_count();
  BreadthFirstAdjacency order{.new_node = std::pmr::vector<NodeId>(2 * std::size_t{n}, memory),
                              .slots = std::pmr::vector<Slot>(memory),
                              .first_slot = std::pmr::vector<std::size_t>(memory)};
  const std::pmr::vector<NodeId> old_node = breadth_first_visit(graph, memory);
  bool uniform = true;
  for (NodeId v = 0; v < n; ++v) uniform = uniform && graph.degree(v) == graph.degree(0);
  order.uniform_degree = uniform && n > 0 ? graph.degree(0) + 1 : 0;
  for (std::uint32_t i = 0; i < n; ++i) {
    order.new_node[old_node[i]] = 2 * i;
    order.new_node[n + old_node[i]] = 2 * i + 1;
  }
  order.slots.resize(2 * (std::size_t{m} * 2 + n));
  if (order.uniform_degree == 0) order.first_slot.resize(2 * std::size_t{n} + 1);
  Slot* last = order.slots.data();
  for (std::uint32_t i = 0; i < n; ++i) {
    const NodeId v = old_node[i];
    const std::span<const EdgeId> edges = graph.incident_edges(v);
    for (NodeId twin = 0; twin < 2; ++twin) {
      if (order.uniform_degree == 0) order.first_slot[2 * i + twin] = last - order.slots.data();
      Slot* const first = last;
      for (EdgeId e : edges) {
        const NodeId w = order.new_node[graph.other_end(e, v)] + twin;
        *last++ = {2 * costs[e], twin == 0 ? e : m + e, w};
        for (Slot* at = last - 1; at != first && at[-1].edge > at->edge; --at)
          std::swap(at[-1], *at);
      }
      *last++ = {2 * pair_costs[v], 2 * m + v, 2 * i + 1 - twin};
    }
  }
  if (order.uniform_degree == 0) order.first_slot[2 * std::size_t{n}] = order.slots.size();
  return order;
}

}  // namespace petersen::weighted_detail
