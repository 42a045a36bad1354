#include "petersen/graph/cubic_graph.hpp"

#include "check_edge_ends.hpp"
#include "petersen/graph/parallel.hpp"

namespace petersen {

CubicGraph CubicGraph::from_edges(std::uint32_t node_count,
                                  std::span<const std::array<NodeId, 2>> edges) {
  // Degrees are checked edge by edge, so the error names the first node that is not cubic
  // (a wrong edge count always shows as such a node).
  CubicGraph g;
  g.edge_ends_.resize(2 * edges.size());
  g.node_edges_.assign(3 * std::size_t{node_count}, kNoEdge);
  std::vector<std::uint8_t> degree(node_count, 0);
  for (EdgeId e = 0; e < edges.size(); ++e) {
    auto [a, b] = edges[e];
    graph_detail::check_edge_ends(e, a, b, node_count);
    for (NodeId v : {a, b}) {
      if (degree[v] == 3) {
        throw GraphError("node " + std::to_string(v) + " has degree > 3 (edge " +
                         std::to_string(e) + ")");
      }
      g.node_edges_[3 * std::size_t{v} + degree[v]++] = e;
    }
    g.edge_ends_[2 * e] = a;
    g.edge_ends_[2 * e + 1] = b;
  }
  for (NodeId v = 0; v < node_count; ++v) {
    if (degree[v] != 3) {
      throw GraphError("node " + std::to_string(v) + " has degree " + std::to_string(degree[v]) +
                       ", not 3");
    }
  }
  return g;
}

CubicGraph CubicGraph::from_incidence(std::pmr::vector<EdgeId> node_edges,
                                      std::pmr::vector<NodeId> edge_ends) {
  if (node_edges.size() % 3 != 0 || edge_ends.size() != node_edges.size()) {
    throw GraphError(
        "a cubic graph has 3 edge slots per node and as many edge ends (3n/2 edges); got " +
        std::to_string(node_edges.size()) + " slots and " + std::to_string(edge_ends.size()) +
        " ends");
  }
  const std::size_t node_count = node_edges.size() / 3, edge_count = edge_ends.size() / 2;
  // seen[e] bit i: end i of edge e has been met in a slot of that node.
  std::vector<std::uint8_t> seen(edge_count, 0);
  for (EdgeId e = 0; e < edge_count; ++e) {
    graph_detail::check_edge_ends(e, edge_ends[2 * e], edge_ends[2 * e + 1], node_count);
  }
  for (std::size_t slot = 0; slot < node_edges.size(); ++slot) {
    const NodeId v = static_cast<NodeId>(slot / 3);
    const EdgeId e = node_edges[slot];
    const int end = e >= edge_count             ? -1
                    : edge_ends[2 * e] == v     ? 0
                    : edge_ends[2 * e + 1] == v ? 1
                                                : -1;
    if (end < 0 || (seen[e] >> end & 1)) {
      throw GraphError("node " + std::to_string(v) + " lists edge " + std::to_string(e) +
                       (end < 0 ? ", which is out of range or not incident to it"
                                : " twice, or an edge whose end there is listed already"));
    }
    seen[e] |= static_cast<std::uint8_t>(1 << end);
  }
  // Every slot matched a distinct edge end and there are exactly 2·edge_count slots, so every
  // end of every edge is listed once.
  return CubicGraph(std::move(node_edges), std::move(edge_ends));
}

void CubicGraph::write_neighbour_rows(NodeId* rows) const {
  // Each slot reads its edge's ends at random: the ends of the slots kReadAhead nodes on are
  // fetched ahead, so the misses overlap. Slot 3v + k is read before it is written and the
  // read-ahead looks only past v, so `rows` may be the incidence lists themselves.
  constexpr std::size_t kReadAhead = 16;
  const EdgeId* edges = node_edges_.data();
  const std::size_t n = node_edges_.size() / 3;
  for (std::size_t v = 0; v < n; ++v) {
    if (v + kReadAhead < n) {
      for (std::size_t k = 0; k < 3; ++k)
        __builtin_prefetch(&edge_ends_[2 * std::size_t{edges[3 * (v + kReadAhead) + k]}]);
    }
    for (std::size_t k = 0; k < 3; ++k) {
      const EdgeId e = edges[3 * v + k];
      rows[3 * v + k] = edge_ends_[2 * std::size_t{e}] ^ edge_ends_[2 * std::size_t{e} + 1] ^
                        static_cast<NodeId>(v);
    }
  }
}

std::pmr::vector<NodeId> CubicGraph::into_neighbour_rows() && {
  write_neighbour_rows(node_edges_.data());
  free_storage(edge_ends_);  // `= {}` would keep the capacity
  return std::move(node_edges_);
}

std::pmr::vector<NodeId> CubicGraph::into_neighbour_rows(
    std::uint32_t threads, const std::function<void(std::span<const NodeId>)>& beside) && {
  // The rows only read edge_ends_ and write node_edges_, so `beside` may read the edges meanwhile.
  run_parallel(threads, 2, [&](std::uint32_t task) {
    if (task == 0) {
      write_neighbour_rows(node_edges_.data());
    } else {
      beside(edge_ends_);
    }
  });
  free_storage(edge_ends_);
  return std::move(node_edges_);
}

}  // namespace petersen
