// SG (paper §3.1). An edge is free exactly while both its nodes are unpaired, so the paper's
// free/locked marks are read off the matching itself rather than stored.
//
// Both passes touch memory at random (the shuffle's swap partner, then each edge's ends and their
// mates), so each is read ahead: the shuffle draws its random numbers kAhead steps early (the same
// sequence of draws, so the same permutation) and prefetches the slot it will swap with; the
// pairing pass prefetches the ends of the edge kAhead places on, and the mates of the edge half
// as far on.

#include <array>
#include <span>
#include <vector>

#include "greedy.hpp"
#include "petersen/graph/seeded_random.hpp"

namespace petersen {

void simple_greedy(const CubicGraph& graph, Matching& matching, std::uint64_t seed) {
  constexpr std::uint32_t kAhead = 16;
  const std::uint32_t m = graph.edge_count();
  // The paper shuffles the edges so the order of the input file does not steer the pairing:
  // an inside-out Fisher–Yates shuffle builds the permutation in one pass; step i swaps with a
  // slot drawn uniformly from [0, i].
  std::vector<EdgeId> order(m);
  SeededRandom random(seed);
  std::array<std::uint32_t, kAhead> drawn;  // drawn[i % kAhead]: the slot step i swaps with
  for (EdgeId i = 0; i < m && i < kAhead; ++i) drawn[i] = random.below(i + 1);
  for (EdgeId i = 0; i < m; ++i) {
    const std::uint32_t j = drawn[i % kAhead];
    if (i + kAhead < m) {
      const std::uint32_t later = random.below(i + kAhead + 1);
      drawn[i % kAhead] = later;
      __builtin_prefetch(&order[later]);
    }
    order[i] = order[j];
    order[j] = i;
  }
  std::pmr::vector<EdgeId>& mate = matching.mate_edge;
  const std::span<const NodeId> ends = graph.edge_ends();
  for (std::uint32_t k = 0; k < m; ++k) {
    if (k + kAhead < m) __builtin_prefetch(&ends[2 * std::size_t{order[k + kAhead]}]);
    if (k + kAhead / 2 < m) {
      auto [a, b] = graph.endpoints(order[k + kAhead / 2]);
      __builtin_prefetch(&mate[a]);
      __builtin_prefetch(&mate[b]);
    }
    auto [a, b] = graph.endpoints(order[k]);
    if (mate[a] == kNoEdge && mate[b] == kNoEdge) mate[a] = mate[b] = order[k];
  }
}

}  // namespace petersen
