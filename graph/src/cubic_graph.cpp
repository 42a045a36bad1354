#include "petersen/graph/cubic_graph.hpp"

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
    if (a >= node_count || b >= node_count) {
      throw GraphError("edge " + std::to_string(e) + " has an endpoint out of range (" +
                       std::to_string(a) + ", " + std::to_string(b) + "; " +
                       std::to_string(node_count) + " nodes)");
    }
    if (a == b) throw GraphError("edge " + std::to_string(e) + " is a loop at node " + std::to_string(a));
    for (NodeId v : {a, b}) {
      if (degree[v] == 3) {
        throw GraphError("node " + std::to_string(v) + " has degree > 3 (edge " + std::to_string(e) + ")");
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

}  // namespace petersen
