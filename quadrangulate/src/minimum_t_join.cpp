#include "minimum_t_join.hpp"

#include <span>
#include <stdexcept>
#include <string>

#include "petersen/graph/component_forest.hpp"
#include "petersen/graph/csr_graph.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/matching/verify_min_cost.hpp"

namespace petersen::quad_detail {

namespace {

// A node with more ports than this is drawn out into a path first: K4 is the largest clique.
constexpr std::size_t kMaxPorts = 4;

// The matching instance of the reduction, built node by node.
class Gadget {
 public:
  NodeId add_node() { return node_count_++; }

  EdgeId add_edge(NodeId a, NodeId b, Cost cost) {
    edges_.push_back({a, b});
    costs_.push_back(cost);
    return static_cast<EdgeId>(edges_.size() - 1);
  }

  // One node of the T-join graph, given its ports: they are matched among themselves (and with a
  // dummy) so that an odd number of them is left to their cost-1 edges exactly when `odd`.
  void join_ports(std::span<const NodeId> ports, bool odd) {
    if (ports.size() > kMaxPorts) return join_ports_along_path(ports, odd);
    for (std::size_t i = 0; i < ports.size(); ++i)
      for (std::size_t j = i + 1; j < ports.size(); ++j) add_edge(ports[i], ports[j], 0);
    if ((ports.size() + odd) % 2 == 1) {
      const NodeId dummy = add_node();
      for (NodeId port : ports) add_edge(dummy, port, 0);
    }
  }

  std::uint32_t node_count() const { return node_count_; }
  const std::vector<std::array<NodeId, 2>>& edges() const { return edges_; }
  const std::vector<Cost>& costs() const { return costs_; }

 private:
  // A node of d > 4 ports as a path of d − 2 nodes of three ports each: the first takes ports 0
  // and 1, the middle ones one port each, the last the final two; consecutive ones are joined by
  // a link (two ports and an edge of cost 0), which any parity may use for free. Only the first
  // carries the node's parity, so the path's parity is the node's.
  void join_ports_along_path(std::span<const NodeId> ports, bool odd) {
    const std::size_t d = ports.size();
    NodeId link_in = kNoNode;
    for (std::size_t piece = 0; piece + 2 < d; ++piece) {
      std::array<NodeId, 3> own{};
      std::size_t n = 0;
      if (link_in != kNoNode) own[n++] = link_in;
      if (piece == 0) own[n++] = ports[0];
      own[n++] = ports[piece + 1];
      if (piece + 3 == d) {
        own[n++] = ports[d - 1];
      } else {
        const NodeId out = add_node();
        link_in = add_node();
        add_edge(out, link_in, 0);
        own[n++] = out;
      }
      join_ports(std::span<const NodeId>(own.data(), n), piece == 0 && odd);
    }
  }

  std::uint32_t node_count_ = 0;
  std::vector<std::array<NodeId, 2>> edges_;
  std::vector<Cost> costs_;
};

// Each component of the graph must hold an even number of T nodes.
void check_parity(const TJoinGraph& graph) {
  ComponentForest forest(graph.node_count);
  for (const auto& [a, b] : graph.edges) forest.unite(a, b);
  std::vector<std::uint8_t> parity(graph.node_count, 0);
  for (NodeId v = 0; v < graph.node_count; ++v) parity[forest.find(v)] ^= graph.odd[v];
  for (NodeId v = 0; v < graph.node_count; ++v) {
    if (parity[v]) {
      throw std::invalid_argument("minimum_t_join: the component of node " + std::to_string(v) +
                                  " holds an odd number of T nodes");
    }
  }
}

}  // namespace

TJoinResult minimum_t_join(const TJoinGraph& graph, std::uint32_t threads) {
  check_parity(graph);
  TJoinResult result;
  result.certified = graph.edges.empty();  // no T nodes: the empty join, trivially least
  if (graph.edges.empty()) return result;
  Gadget gadget;
  // Ports grouped by node (counting sort): ports of node v at port_of[start[v]..start[v+1]).
  std::vector<std::uint32_t> start(graph.node_count + 1, 0);
  for (const auto& [a, b] : graph.edges) ++start[a + 1], ++start[b + 1];
  for (NodeId v = 0; v < graph.node_count; ++v) start[v + 1] += start[v];
  std::vector<NodeId> port_of(start.back());
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  std::vector<EdgeId> split_edge(graph.edges.size());
  std::vector<NodeId> first_port(graph.edges.size());
  for (EdgeId e = 0; e < graph.edges.size(); ++e) {
    const auto [a, b] = graph.edges[e];
    const NodeId pa = gadget.add_node(), pb = gadget.add_node();
    split_edge[e] = gadget.add_edge(pa, pb, 1);
    first_port[e] = pa;
    port_of[next[a]++] = pa;
    port_of[next[b]++] = pb;
  }
  for (NodeId v = 0; v < graph.node_count; ++v) {
    gadget.join_ports(std::span<const NodeId>(port_of.data() + start[v], start[v + 1] - start[v]),
                      graph.odd[v] != 0);
  }

  const CsrGraph matched_graph = CsrGraph::from_edges(gadget.node_count(), gadget.edges());
  const MinCostResult solved =
      min_cost_perfect_matching(matched_graph, gadget.costs(), {.threads = threads});
  const CertificateCheck check = verify_min_cost_perfect_matching(
      gadget.node_count(), matched_graph.edge_ends(), gadget.costs(), solved.matching,
      solved.total_cost, solved.certificate);
  if (!check.ok()) throw std::logic_error("minimum_t_join: certificate: " + check.problem);

  for (EdgeId e = 0; e < graph.edges.size(); ++e) {
    if (solved.matching.mate_edge[first_port[e]] == split_edge[e]) result.join.push_back(e);
  }
  if (Cost(result.join.size()) != solved.total_cost) {
    throw std::logic_error("minimum_t_join: the join's size differs from the matching's cost");
  }
  result.gadget_nodes = gadget.node_count();
  result.gadget_edges = gadget.edges().size();
  result.certified = true;
  return result;
}

}  // namespace petersen::quad_detail
