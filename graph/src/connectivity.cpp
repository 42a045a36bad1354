#include "petersen/graph/connectivity.hpp"

#include <string>

namespace petersen {

std::vector<std::uint32_t> component_ids(const CubicGraph& graph) {
  const std::uint32_t n = graph.node_count();
  std::vector<std::uint32_t> component(n, kNoNode);
  std::vector<NodeId> stack;
  std::uint32_t count = 0;
  for (NodeId root = 0; root < n; ++root) {
    if (component[root] != kNoNode) continue;
    component[root] = count;
    stack.push_back(root);
    while (!stack.empty()) {
      NodeId v = stack.back();
      stack.pop_back();
      for (EdgeId e : graph.incident_edges(v)) {
        NodeId w = graph.other_end(e, v);
        if (component[w] == kNoNode) {
          component[w] = count;
          stack.push_back(w);
        }
      }
    }
    ++count;
  }
  return component;
}

std::uint32_t count_components(const CubicGraph& graph) {
  std::uint32_t count = 0;
  for (std::uint32_t c : component_ids(graph)) count = std::max(count, c + 1);
  return count;
}

// Tarjan's low-link bridge test, depth-first with an explicit stack of (node, next incident slot).
// The tree edge into a node is skipped by edge id, not by parent node, so a parallel copy of it
// counts as a back edge and parallel edges are never reported.
std::optional<EdgeId> find_bridge(const CubicGraph& graph) {
  const std::uint32_t n = graph.node_count();
  std::vector<std::uint32_t> order(n, kNoNode), low(n);
  std::vector<EdgeId> parent_edge(n, kNoEdge);
  struct Frame {
    NodeId node;
    std::uint32_t slot;
  };
  std::vector<Frame> stack;
  std::uint32_t time = 0;
  for (NodeId root = 0; root < n; ++root) {
    if (order[root] != kNoNode) continue;
    order[root] = low[root] = time++;
    stack.push_back({root, 0});
    while (!stack.empty()) {
      Frame& top = stack.back();
      NodeId v = top.node;
      if (top.slot < 3) {
        EdgeId e = graph.incident_edge(v, static_cast<int>(top.slot++));
        if (e == parent_edge[v]) continue;
        NodeId w = graph.other_end(e, v);
        if (order[w] == kNoNode) {
          order[w] = low[w] = time++;
          parent_edge[w] = e;
          stack.push_back({w, 0});
        } else {
          low[v] = std::min(low[v], order[w]);
        }
        continue;
      }
      stack.pop_back();
      if (parent_edge[v] != kNoEdge) {
        NodeId parent = graph.other_end(parent_edge[v], v);
        if (low[v] > order[parent]) return parent_edge[v];
        low[parent] = std::min(low[parent], low[v]);
      }
    }
  }
  return std::nullopt;
}

void validate_bridgeless(const CubicGraph& graph) {
  if (auto bridge = find_bridge(graph)) {
    auto [a, b] = graph.endpoints(*bridge);
    throw GraphError("edge " + std::to_string(*bridge) + " (" + std::to_string(a) + "-" +
                     std::to_string(b) + ") is a bridge");
  }
}

void validate_connected_bridgeless(const CubicGraph& graph) {
  if (std::uint32_t c = count_components(graph); c > 1) {
    throw GraphError("the graph is disconnected: " + std::to_string(c) + " components");
  }
  validate_bridgeless(graph);
}

}  // namespace petersen
