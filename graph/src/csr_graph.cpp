#include "petersen/graph/csr_graph.hpp"

#include <string>

#include "check_edge_ends.hpp"

namespace petersen {

CsrGraph CsrGraph::from_edges(std::uint32_t node_count,
                              std::span<const std::array<NodeId, 2>> edges,
                              std::pmr::memory_resource* memory) {
  CsrGraph g(memory);
  g.offsets_.assign(std::size_t{node_count} + 1, 0);
  g.edge_ends_.resize(2 * edges.size());
  for (EdgeId e = 0; e < edges.size(); ++e) {
    auto [a, b] = edges[e];
    graph_detail::check_edge_ends(e, a, b, node_count);
    ++g.offsets_[a + 1];
    ++g.offsets_[b + 1];
    g.edge_ends_[2 * e] = a;
    g.edge_ends_[2 * e + 1] = b;
  }
  for (NodeId v = 0; v < node_count; ++v) g.offsets_[v + 1] += g.offsets_[v];
  // Counting sort by endpoint: each node's edges end up in edge-id order.
  g.node_edges_.resize(2 * edges.size());
  std::pmr::vector<std::uint32_t> next(g.offsets_.begin(), g.offsets_.end() - 1);
  for (EdgeId e = 0; e < edges.size(); ++e) {
    g.node_edges_[next[edges[e][0]]++] = e;
    g.node_edges_[next[edges[e][1]]++] = e;
  }
  return g;
}

}  // namespace petersen
