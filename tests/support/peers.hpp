#pragma once
// Maximum matchings by the peers petersen is tested against, on plain edge lists.

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/matching/matching.hpp"

namespace petersen::testing {

using EdgeList = std::vector<std::array<std::uint32_t, 2>>;

/// The edges of a cubic graph, in id order.
inline EdgeList edge_list(const CubicGraph& g) {
  EdgeList edges(g.edge_count());
  for (EdgeId e = 0; e < g.edge_count(); ++e) edges[e] = g.endpoints(e);
  return edges;
}

/// Size of a maximum matching by Boost's edmonds_maximum_cardinality_matching.
std::uint32_t boost_matching_size(std::uint32_t node_count,
                                  std::span<const std::array<std::uint32_t, 2>> edges);
/// A maximum matching of `g` by LEMON's MaxMatching, on its edge ids (perfect when g is cubic and
/// bridgeless): an independent matching to check what consumes one, or to verify.
Matching lemon_matching(const CubicGraph& g);
/// Size of a maximum matching by LEMON's MaxMatching.
std::uint32_t lemon_matching_size(std::uint32_t node_count,
                                  std::span<const std::array<std::uint32_t, 2>> edges);

/// The cost of a minimum-cost perfect matching by LEMON's MaxWeightedPerfectMatching (on the
/// negated costs), or nullopt when the graph has none.
std::optional<std::int64_t> lemon_min_cost_perfect(
    std::uint32_t node_count, std::span<const std::array<std::uint32_t, 2>> edges,
    std::span<const std::int64_t> costs);

}  // namespace petersen::testing
