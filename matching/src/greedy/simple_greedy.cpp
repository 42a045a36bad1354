// SG (paper §3.1). An edge is free exactly while both its nodes are unpaired, so the paper's
// free/locked marks are read off the matching itself rather than stored.

#include <vector>

#include "greedy.hpp"
#include "seeded_random.hpp"

namespace petersen {

void simple_greedy(const CubicGraph& graph, Matching& matching, std::uint64_t seed) {
  const std::uint32_t m = graph.edge_count();
  // The paper shuffles the edges so the order of the input file does not steer the pairing:
  // an inside-out Fisher–Yates shuffle builds the permutation in one pass.
  std::vector<EdgeId> order(m);
  SeededRandom random(seed);
  for (EdgeId i = 0; i < m; ++i) {
    const std::uint32_t j = random.below(i + 1);
    order[i] = order[j];
    order[j] = i;
  }
  std::vector<EdgeId>& mate = matching.mate_edge;
  for (EdgeId e : order) {
    auto [a, b] = graph.endpoints(e);
    if (mate[a] == kNoEdge && mate[b] == kNoEdge) mate[a] = mate[b] = e;
  }
}

}  // namespace petersen
