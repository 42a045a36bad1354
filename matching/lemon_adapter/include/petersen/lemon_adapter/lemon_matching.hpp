#pragma once
// LEMON's maximum matching behind a plain interface. Debian's LEMON 1.3.1 headers do not compile
// as C++20, so this target alone is built as C++17 and no LEMON type crosses this header.

#include <array>
#include <cstdint>
#include <vector>

namespace petersen::lemon_adapter {

inline constexpr std::uint32_t kUnmatched = 0xFFFFFFFFu;

/// (The interface is C++17: no std::span.)
/// Maximum-cardinality matching of a general (multi)graph by LEMON's MaxMatching (Edmonds,
/// O(nm log n)). Writes, for each node v < node_count, the index in `edges` of its matched edge or
/// kUnmatched to mate_edge[v]: straight into the caller's array (a Matching's huge-page one),
/// without a copy. `greedy_start` runs LEMON's greedyInit() first, as MaxMatching::run() does.
void maximum_matching(std::uint32_t node_count,
                      const std::vector<std::array<std::uint32_t, 2>>& edges,
                      std::uint32_t* mate_edge, bool greedy_start = true);

/// Minimum-cost perfect matching by LEMON's MaxWeightedPerfectMatching on the negated costs
/// (O(n m log n)). Returns false when the graph has no perfect matching; otherwise writes the
/// matched edge's index per node to mate_edge and the matching's cost to total_cost.
bool min_cost_perfect_matching(std::uint32_t node_count,
                               const std::vector<std::array<std::uint32_t, 2>>& edges,
                               const std::vector<std::int64_t>& costs, std::uint32_t* mate_edge,
                               std::int64_t& total_cost);

}  // namespace petersen::lemon_adapter
