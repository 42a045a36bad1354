#pragma once
// LEMON's matchings, the comparison peer of the bench and the tests. Debian's LEMON 1.3.1 headers
// do not compile as C++20, so this target alone is built as C++17 and no LEMON type crosses this
// header. No production target (the libraries, the CLI, the Python module) links it.

#include <cstdint>

namespace petersen::lemon_peer {

/// Maximum-cardinality matching of a general (multi)graph by LEMON's MaxMatching (Edmonds,
/// O(nm log n)): greedyInit() then startSparse(), as MaxMatching::run() does on sparse graphs. Edge
/// e joins edge_ends[2e] and edge_ends[2e + 1]; writes, for each node v < node_count, the index of
/// its matched edge or 0xFFFFFFFF to mate_edge[v], straight into the caller's array (for a
/// CubicGraph g, g.edge_ends() and Matching::mate_edge: checkable by verify_perfect_matching).
void maximum_matching(std::uint32_t node_count, const std::uint32_t* edge_ends,
                      std::uint32_t edge_count, std::uint32_t* mate_edge);

/// Minimum-cost perfect matching by LEMON's MaxWeightedPerfectMatching on the negated costs
/// (O(n m log n)), the peer of min_cost_perfect_matching. Returns false when the graph has no
/// perfect matching; otherwise writes the matched edge's index per node to mate_edge and the
/// matching's cost to total_cost.
bool min_cost_perfect_matching(std::uint32_t node_count, const std::uint32_t* edge_ends,
                               std::uint32_t edge_count, const std::int64_t* costs,
                               std::uint32_t* mate_edge, std::int64_t& total_cost);

}  // namespace petersen::lemon_peer
