#include "reduction/match_by_reductions.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "petersen/graph/connectivity.hpp"
#include "petersen/graph/memory.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "reduction/ds_chooser.hpp"
#include "reduction/engine.hpp"
#include "reduction/frink_chooser.hpp"
#include "reduction/gw_chooser.hpp"
#include "reduction/reduction_graph.hpp"

namespace petersen::reduction {

namespace {

// The graph renumbered in depth-first order (nodes in preorder, edges as first traversed), each
// node's edges kept in their order, so a depth-first search of the copy follows the same tree. A
// tree path is then mostly a run of consecutive ids, which the choosers' link-cut trees and the
// reduction graph walk with few cache misses whatever the input order was. One pass, O(n); the
// components come out as runs of ids. The same pass finds what gw's set-up needs, the depth-first
// tree and each tree edge's cover (the back edge reaching highest from below it, by low points:
// a node's preorder number is its new id). A depth-first pass of gw's own over the copy would
// follow the same tree; doing it here saves 16 % of gw's set-up instructions and 14 % of its D1
// read misses (fertility-sub3's dual; see bench/RESULTS.md).
//
// The copy's arrays become the reduction graph's own (its edge ends reserved with room for the
// edges the reductions add) instead of being copied: 24 bytes per node less fresh memory (gw's
// peak on armadillo-sub2's dual 192 MiB against 224) and 9 % fewer LL misses.
struct DepthFirstCopy {
  std::pmr::vector<EdgeId> node_edges;  // as CubicGraph::node_edges()
  std::pmr::vector<NodeId> edge_ends;  // as CubicGraph::edge_ends(), with capacity for n more edges
  std::pmr::vector<NodeId> old_node;   // by new id
  std::pmr::vector<EdgeId> old_edge;   // by new id
  std::pmr::vector<std::uint32_t> component;  // by new id
  std::uint32_t components = 0;
  std::pmr::vector<EdgeId>
      tree_edge;                   // by new id: the new id of the edge to the parent, or kNoEdge
  std::pmr::vector<EdgeId> cover;  // by new id: the cover of tree_edge
};

DepthFirstCopy depth_first_copy(const CubicGraph& graph, bool check) {
  const std::uint32_t n = graph.node_count(), m = graph.edge_count();
  std::pmr::vector<NodeId> new_node(n, kNoNode);
  std::pmr::vector<EdgeId> new_edge(m, kNoEdge);
  DepthFirstCopy copy;
  std::pmr::vector<EdgeId>& node_edges = copy.node_edges;
  std::pmr::vector<NodeId>& edge_ends = copy.edge_ends;
  node_edges.resize(3 * std::size_t{n});
  // A reduction adds at most two edges per two nodes. Edge ids are given in the order the ends
  // are written, so they are appended, as is `low`: zero-filling the two first (9.2 MB on
  // fertility-sub3's dual) would be 4.6 % of gw's LL misses there (with a 32 MiB LL).
  edge_ends.reserve(2 * (std::size_t{m} + n));
  copy.old_node.reserve(n);
  copy.old_edge.reserve(m);
  copy.component.reserve(n);
  copy.tree_edge.reserve(n);
  copy.cover.assign(n, kNoEdge);
  std::pmr::vector<NodeId> low;  // by new id: the smallest preorder number a back edge reaches
  low.reserve(n);
  const auto visit = [&](NodeId v, EdgeId tree_edge) {
    const auto id = static_cast<NodeId>(copy.old_node.size());
    new_node[v] = id;
    low.push_back(id);
    copy.old_node.push_back(v);
    copy.component.push_back(copy.components);
    copy.tree_edge.push_back(tree_edge);
  };
  // Old id, next slot. Reserved at its bound, n entries: only the pages the depth reaches are
  // touched, where a growing vector copied itself into fresh memory at each doubling.
  std::pmr::vector<std::pair<NodeId, int>> stack;
  stack.reserve(n);
  for (NodeId root = 0; root < n; ++root) {
    if (new_node[root] != kNoNode) continue;
    visit(root, kNoEdge);
    stack.push_back({root, 0});
    while (!stack.empty()) {
      auto& [v, k] = stack.back();
      if (k == 3) {
        const NodeId w = new_node[v];
        stack.pop_back();
        if (stack.empty()) break;
        const NodeId p = new_node[stack.back().first];
        if (low[w] < low[p]) low[p] = low[w], copy.cover[p] = copy.cover[w];
        continue;
      }
      const EdgeId e = graph.incident_edge(v, k);
      EdgeId& id = node_edges[3 * std::size_t{new_node[v]} + k++];
      if (new_edge[e] != kNoEdge) {  // the edge to v's parent, or a back edge from below
        id = new_edge[e];
        continue;
      }
      id = new_edge[e] = static_cast<EdgeId>(copy.old_edge.size());
      copy.old_edge.push_back(e);
      const auto [a, b] = graph.endpoints(e);
      const NodeId w = a ^ b ^ v;
      const bool tree_edge = new_node[w] == kNoNode;
      if (tree_edge) {
        visit(w, id);
      } else if (const NodeId nv = new_node[v]; new_node[w] < low[nv]) {
        low[nv] = new_node[w];  // a back edge to an ancestor
        copy.cover[nv] = id;
      }
      edge_ends.push_back(new_node[a]);
      edge_ends.push_back(new_node[b]);
      if (tree_edge) stack.push_back({w, 0});  // after the last use of the reference v
    }
    ++copy.components;
  }
  // A renumbering of a valid graph is valid: from_incidence's checks (a random read per slot,
  // 1.7 % of gw's instructions and 4.8 % of its D1 read misses on fertility-sub3's dual) run, on
  // a copy of the arrays, only when each step is checked, as in the tests.
  if (check) static_cast<void>(CubicGraph::from_incidence(node_edges, edge_ends));
  return copy;
}

}  // namespace

ReductionResult match_by_reductions(const CubicGraph& graph, EdgeId forbidden,
                                    const ReductionOptions& options) {
  ReductionResult result;
  Stopwatch setup;
  // Only gw runs on the depth-first copy. ds on it (its spanning forest then the depth-first
  // tree) took 52 s on armadillo-sub2's dual against 31 s on the input order.
  std::optional<DepthFirstCopy> copy;
  std::pmr::vector<std::uint32_t> component;
  std::uint32_t components = 0;
  if (options.chooser == ReductionChooser::gw) {
    copy = depth_first_copy(graph, options.check_each_step);
    if (forbidden != kNoEdge)
      forbidden =
          static_cast<EdgeId>(std::find(copy->old_edge.begin(), copy->old_edge.end(), forbidden) -
                              copy->old_edge.begin());
    component = std::move(copy->component);
    components = copy->components;
  } else {
    const std::vector<std::uint32_t> ids = component_ids(graph);
    component.assign(ids.begin(), ids.end());
    components = ids.empty() ? 0 : *std::max_element(ids.begin(), ids.end()) + 1;
  }
  // A reduction adds at most two edges and removes two nodes. gw's reduction graph takes over
  // the copy's arrays before its chooser reads them; the others copy the input after their
  // chooser is built, as before (ds's cache misses changed by 2.5 % with the order swapped).
  std::optional<ReductionGraph> reduced;
  if (copy)
    reduced.emplace(std::move(copy->node_edges), std::move(copy->edge_ends), graph.node_count());
  std::unique_ptr<Chooser> chooser;
  switch (options.chooser) {
    case ReductionChooser::frink:
      chooser = std::make_unique<FrinkChooser>(components);
      break;
    case ReductionChooser::ds:
      chooser = std::make_unique<DsChooser>(graph, graph.edge_count() + graph.node_count());
      break;
    case ReductionChooser::gw:
      chooser = std::make_unique<GwChooser>(*reduced, graph.edge_count() + graph.node_count(),
                                            copy->tree_edge, copy->cover);
      break;
  }
  if (!copy) reduced.emplace(graph, graph.node_count());
  result.stats.setup_seconds = setup.seconds();
  Matching matching = reduce_and_lift(std::move(*reduced), component, components, forbidden,
                                      *chooser, options.check_each_step, result.stats);
  if (!copy) {
    result.matching = std::move(matching);
    return result;
  }
  Stopwatch back;
  result.matching = Matching(graph.node_count());
  for (NodeId v = 0; v < graph.node_count(); ++v)
    result.matching.mate_edge[copy->old_node[v]] = copy->old_edge[matching.mate_edge[v]];
  result.stats.lift_seconds += back.seconds();
  return result;
}

}  // namespace petersen::reduction
