// The two drivers of Tarjan's procedure (paper §3.1) over the shared alternating forest, for
// cubic and general graphs, and the general maximum-matching fallback.

#include <algorithm>
#include <stdexcept>

#include "alternating_forest.hpp"
#include "augment_cubic.hpp"
#include "petersen/matching/augment.hpp"

namespace petersen {

namespace {

// Runs the searches on a forest set up from the matching; `stats` is the forest's.
template <class Graph>
void grow(augment_detail::AlternatingForest<Graph>& forest, AugmentStats& stats, Augment variant) {
  const std::vector<NodeId>& free_nodes = forest.free_nodes();
  if (free_nodes.size() < 2) return;
  if (variant == Augment::faithful) {
    // The paper's: one search per free node, each after a full reset. A node whose search fails
    // can never be matched later (Edmonds), so one pass suffices.
    for (NodeId r : free_nodes) {
      if (!forest.is_free(r)) continue;  // matched by an earlier path
      forest.clear_all();
      forest.add_root(r);
      ++stats.searches;
      forest.grow(/*stop_at_first=*/true);
    }
  } else {
    // Local: all free nodes grow their trees at once, breadth-first, so the nearest pairs meet
    // first, every tree stops as soon as it augments, and a tree blocked by another resumes when
    // that one dies. One growth is a complete Edmonds search, and it resets only what it labelled.
    for (NodeId r : free_nodes) forest.add_root(r);
    stats.searches = free_nodes.size();
    forest.grow(/*stop_at_first=*/false);
  }
}

template <class Graph>
AugmentStats augment(const Graph& graph, Matching& matching, Augment variant) {
  AugmentStats stats;
  augment_detail::AlternatingForest<Graph> forest(graph, matching.mate_edge, stats);
  grow(forest, stats, variant);
  return stats;
}

}  // namespace

AugmentStats augment_matching(const NeighbourTable& graph, Matching& matching, Augment variant) {
  return augment(graph, matching, variant);
}

AugmentStats augment_on_rows(const NeighbourTable& table, Augment variant) {
  AugmentStats stats;
  augment_detail::AlternatingForest<NeighbourTable> forest(table, stats);
  grow(forest, stats, variant);
  return stats;
}

// Straight on the graph: a table costs a pass over the nodes, which pays only when the searches
// label about every node (as after a greedy pairing; perfect_matching builds one then). LRS's
// expansion leaves a few free nodes and short searches.
AugmentStats augment_matching(const CubicGraph& graph, Matching& matching, Augment variant) {
  return augment(graph, matching, variant);
}

AugmentStats augment_matching(const CsrGraph& graph, Matching& matching, Augment variant) {
  return augment(graph, matching, variant);
}

MaximumMatchingResult maximum_matching(const CsrGraph& graph, Augment variant) {
  Matching greedy(graph.node_count());
  std::pmr::vector<EdgeId>& mate = greedy.mate_edge;
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    auto [a, b] = graph.endpoints(e);
    if (mate[a] == kNoEdge && mate[b] == kNoEdge) mate[a] = mate[b] = e;
  }
  return maximum_matching(graph, std::move(greedy), variant);
}

MaximumMatchingResult maximum_matching(const CsrGraph& graph, Matching initial, Augment variant) {
  MaximumMatchingResult result{std::move(initial), 0, {}, {}};
  result.stats = augment_matching(graph, result.matching, variant);
  // The witness: one more complete growth from the free nodes finds no path (the matching is
  // maximum) and leaves the Gallai–Edmonds forest, whose odd nodes are the Tutte set. Its cost
  // follows the region the free nodes reach, like the local searches themselves.
  AugmentStats witness_stats;
  augment_detail::AlternatingForest<CsrGraph> forest(graph, result.matching.mate_edge,
                                                     witness_stats);
  for (NodeId r : forest.free_nodes()) forest.add_root(r);
  if (forest.free_nodes().size() >= 2 && forest.grow(/*stop_at_first=*/false) != 0) {
    throw std::logic_error("maximum_matching: an augmenting path survived the augmentation");
  }
  result.tutte_set = forest.odd_nodes();
  result.size = (graph.node_count() - result.matching.unmatched_count()) / 2;
  return result;
}

}  // namespace petersen
