#include "reduction/ds_chooser.hpp"

namespace petersen::reduction {

DsChooser::DsChooser(const CubicGraph& graph, std::uint32_t edge_capacity)
    : connectivity_(graph.node_count(), edge_capacity), forest_(graph.node_count()) {
  // One bulk insertion, the same forest as inserting the edges one by one in id order: that
  // would be 12 % of ds on armadillo-sub2's dual, 2M connectivity queries and 0.7M links.
  connectivity_.insert_all(graph.edge_ends());
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    if (!connectivity_.is_tree_edge(e)) continue;
    const auto [a, b] = graph.endpoints(e);
    forest_.link(a, b);
  }
}

void DsChooser::insert(EdgeId e, NodeId a, NodeId b) {
  if (connectivity_.insert_edge(e, a, b)) forest_.link(a, b);
}

void DsChooser::remove(const ReductionGraph&, std::span<const EdgeId> edges) {
  for (EdgeId e : edges) {
    const DynamicConnectivity::Deletion d = connectivity_.delete_edge(e);
    if (!d.was_tree_edge) continue;
    forest_.cut(connectivity_.endpoint(e, 0), connectivity_.endpoint(e, 1));
    if (d.replacement != kNoEdge)
      forest_.link(connectivity_.endpoint(d.replacement, 0),
                   connectivity_.endpoint(d.replacement, 1));
  }
}

bool DsChooser::choose_h1(const ReductionGraph& graph, const Step& step) {
  const NodeId x1 = graph.other_end(step.a1, step.u), x2 = graph.other_end(step.a2, step.u);
  const NodeId x3 = graph.other_end(step.b3, step.v), x4 = graph.other_end(step.b4, step.v);
  // Rooted at x1, connectivity to x1 takes one access each instead of two.
  forest_.evert(x1);
  if (!forest_.in_tree_of(x1, x2)) return !forest_.in_tree_of(x1, x3);  // split 13|24 or 14|23
  // The quartet is 13|24 exactly when x2 and x4 meet below where x3 joins them. Each lca
  // starts at the node the previous one ended on (a second access of a node is a single splay
  // step): three full accesses, four when l23 == l34, against six.
  const NodeId l23 = forest_.lca(x2, x3), l34 = forest_.lca(x3, x4);
  if (l23 != l34) return true;
  return forest_.lca(x4, x2) == l23;
}

void DsChooser::add(const ReductionGraph& graph, std::span<const EdgeId> edges) {
  for (EdgeId e : edges) insert(e, graph.end(e, 0), graph.end(e, 1));
}

}  // namespace petersen::reduction
