#pragma once
// Matchings of any graph given as an edge list: the common core of `petersen match` and the BGL
// and LEMON adaptors. C++17, like everything it includes, so that the LEMON adaptor can use it.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "petersen/matching/options.hpp"

namespace petersen {

/// What match_any_graph found, in the edge list's own ids.
struct AnyGraphMatching {
  /// The index in the edge list of each node's matched edge, or 0xFFFFFFFF when it is free.
  std::vector<std::uint32_t> mate_edge;
  std::uint32_t size = 0;  ///< matched edges
  bool perfect = false;    ///< every node matched
  /// The graph is cubic and bridgeless (Petersen's theorem), so PerfectMatchingOptions::algorithm
  /// found a perfect matching. Otherwise the matching is a maximum one and `note` says why.
  bool cubic_bridgeless = false;
  /// Why the graph is not cubic and bridgeless: its first node whose degree is not 3 (a loop
  /// counts twice), its first loop, or a bridge. Empty when it is.
  std::string note;
  /// The proof of maximality when the graph is not cubic bridgeless: a Tutte–Berge set A (node
  /// ids) for which the matching leaves exactly odd(G − A) − |A| nodes free
  /// (verify_maximum_matching, tutte_berge.hpp). Empty for a cubic bridgeless graph.
  std::vector<std::uint32_t> tutte_set;
  /// Of PerfectMatchingOptions::algorithm on a cubic bridgeless graph. On any other graph
  /// augment_seconds is the whole maximum matching (its greedy start included) and the counts are
  /// the augmentation's.
  PerfectMatchingStats stats;
};

/// A perfect matching by `options.algorithm` when the (multi)graph is cubic and bridgeless, and
/// otherwise a maximum matching (a greedy pass over the edges, then Tarjan's augmenting paths,
/// augment_matching on a CsrGraph) with its Tutte–Berge witness. Edge e joins edges[e][0] and
/// edges[e][1]; parallel edges and loops are allowed (a loop is never matched). Every answer
/// goes through the verifier before it is returned (std::logic_error if it fails, which would be
/// a bug). Throws GraphError naming the first edge with an endpoint out of range, and what
/// perfect_matching throws for `options` (lrs, or lemon without a peer). O(n + m) plus the
/// algorithm.
AnyGraphMatching match_any_graph(std::uint32_t node_count,
                                 const std::vector<std::array<std::uint32_t, 2>>& edges,
                                 const PerfectMatchingOptions& options = {});

/// What cheapest_matching_any_graph found, in the edge list's own ids.
struct AnyGraphCheapestMatching {
  /// The index in the edge list of each node's matched edge, or 0xFFFFFFFF when it is free.
  std::vector<std::uint32_t> mate_edge;
  std::uint32_t size = 0;       ///< matched edges: the maximum
  bool perfect = false;         ///< every node matched
  std::int64_t total_cost = 0;  ///< the least among matchings of that size
};

/// The matching of least total cost among the maximum matchings of any graph given as an edge
/// list, with one integer cost per edge (at most 2^40 in absolute value): the common core of
/// `petersen match --objective cost`, Python's min_cost_matching and the adaptors. Loops, which
/// no matching has, are left out; the rest goes to cheapest_maximum_matching
/// (min_cost_matching.hpp), which checks the answer's dual solution by the independent verifier
/// before it returns. `threads` as MinCostOptions::threads (0: every core; the answer does not
/// depend on it). Throws GraphError naming the first edge with an endpoint out of range,
/// std::invalid_argument for a cost out of range or a count of costs other than of edges.
AnyGraphCheapestMatching cheapest_matching_any_graph(
    std::uint32_t node_count, const std::vector<std::array<std::uint32_t, 2>>& edges,
    const std::vector<std::int64_t>& costs, std::uint32_t threads = 1);

}  // namespace petersen
