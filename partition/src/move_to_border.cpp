#include "move_to_border.hpp"

#include <algorithm>
#include <vector>

namespace petersen::partition_detail {

namespace {

// One search's state over all nodes: a node y is labelled when stamp[y] is the search's number,
// and reached by the unmatched edge parent_edge[y] into its mate (kNoEdge for the root).
struct Search {
  std::vector<std::uint32_t> stamp;
  std::vector<EdgeId> parent_edge;
  std::vector<NodeId> queue, path;
  std::uint32_t number = 0;
};

// The alternating path from the root to y, as the even nodes y, ..., root, if no node repeats.
bool trace(const CsrGraph& graph, const Matching& matching, Search& search, NodeId y) {
  search.path.clear();
  for (NodeId even = y;;) {
    search.path.push_back(even);
    const EdgeId in = search.parent_edge[even];
    if (in == kNoEdge) break;
    const NodeId x = graph.other_end(matching.mate_edge[even], even);
    search.path.push_back(x);
    even = graph.other_end(in, x);
  }
  std::vector<NodeId> sorted = search.path;
  std::sort(sorted.begin(), sorted.end());
  return std::adjacent_find(sorted.begin(), sorted.end()) == sorted.end();
}

// Flips the traced path: each odd node x takes the unmatched edge to the even node before it.
void flip(Matching& matching, const Search& search) {
  const std::vector<NodeId>& path = search.path;  // y, x_k, e_{k-1}, x_{k-1}, ..., root
  matching.mate_edge[path.front()] = kNoEdge;
  for (std::size_t i = 1; i + 1 < path.size(); i += 2) {
    const NodeId x = path[i], even = path[i + 1];
    const EdgeId e = search.parent_edge[path[i - 1]];
    matching.mate_edge[x] = matching.mate_edge[even] = e;
  }
}

// One search from `root`, taking its labels from `budget`.
bool search_from(const CsrGraph& graph, Matching& matching, std::span<const std::uint8_t> on_border,
                 std::uint64_t& budget, NodeId root, Search& search) {
  ++search.number;
  search.queue.assign(1, root);
  search.stamp[root] = search.number;
  search.parent_edge[root] = kNoEdge;
  for (std::size_t head = 0; head < search.queue.size() && budget > 0; ++head) {
    const NodeId even = search.queue[head];
    for (EdgeId e : graph.incident_edges(even)) {
      const NodeId x = graph.other_end(e, even);
      if (e == matching.mate_edge[even] || !matching.is_matched(x)) continue;
      const NodeId y = graph.other_end(matching.mate_edge[x], x);
      if (search.stamp[y] == search.number) continue;
      search.stamp[y] = search.number;
      search.parent_edge[y] = e;
      --budget;
      if (on_border[y] && trace(graph, matching, search, y)) {
        flip(matching, search);
        return true;
      }
      search.queue.push_back(y);
    }
  }
  return false;
}

}  // namespace

MoveStats move_to_border(const CsrGraph& graph, Matching& matching,
                         std::span<const std::uint8_t> on_border, std::uint64_t budget) {
  MoveStats stats;
  Search search;
  for (NodeId u = 0; u < graph.node_count(); ++u) {
    if (matching.is_matched(u) || on_border[u]) continue;
    if (search.stamp.empty()) {
      search.stamp.assign(graph.node_count(), 0);
      search.parent_edge.assign(graph.node_count(), kNoEdge);
    }
    if (budget > 0 && search_from(graph, matching, on_border, budget, u, search)) {
      ++stats.moved;
    } else {
      ++stats.stranded;
    }
  }
  return stats;
}

}  // namespace petersen::partition_detail
