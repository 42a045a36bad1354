#include "reduction/reduction_graph.hpp"

#include <utility>

namespace petersen::reduction {

ReductionGraph::ReductionGraph(const CubicGraph& graph, std::uint32_t extra_edges)
    : slots_(graph.node_edges().begin(), graph.node_edges().end()), alive_(graph.node_count(), 1) {
  ends_.reserve(2 * (std::size_t{graph.edge_count()} + extra_edges));
  ends_.assign(graph.edge_ends().begin(), graph.edge_ends().end());
}

ReductionGraph::ReductionGraph(std::pmr::vector<EdgeId> node_edges,
                               std::pmr::vector<NodeId> edge_ends, std::uint32_t extra_edges)
    : ends_(std::move(edge_ends)), slots_(std::move(node_edges)), alive_(node_count(), 1) {
  ends_.reserve(ends_.size() + 2 * std::size_t{extra_edges});
}

EdgeId ReductionGraph::add_edge(NodeId a, NodeId b) {
  ends_.push_back(a);
  ends_.push_back(b);
  return edge_count() - 1;
}

void ReductionGraph::replace_slot(NodeId v, EdgeId old_edge, EdgeId new_edge) {
  EdgeId* s = slots_.data() + 3 * std::size_t{v};
  s[s[0] == old_edge ? 0 : s[1] == old_edge ? 1 : 2] = new_edge;
}

void ReductionGraph::apply(Step& step) {
  const NodeId x1 = other_end(step.a1, step.u), x3 = other_end(step.b3, step.v);
  step.n13 = add_edge(x1, x3);
  replace_slot(x1, step.a1, step.n13);
  replace_slot(x3, step.b3, step.n13);
  if (step.b4 != kNoEdge) {
    const NodeId x2 = other_end(step.a2, step.u), x4 = other_end(step.b4, step.v);
    step.n24 = add_edge(x2, x4);
    replace_slot(x2, step.a2, step.n24);
    replace_slot(x4, step.b4, step.n24);
  } else {
    step.n24 = kNoEdge;
  }
  alive_[step.u] = alive_[step.v] = 0;
}

}  // namespace petersen::reduction
