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
  /// The note's subject and predicate apart, for a caller that names nodes and edges in its own
  /// numbering (a file's 1-based ids, an edge by its line): the node or the edge the note names
  /// (0xFFFFFFFF for none) and what it says of it ("has degree 1", "is a loop", "is a bridge").
  std::uint32_t note_node = 0xFFFFFFFFu, note_edge = 0xFFFFFFFFu;
  std::string note_predicate;
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
/// a bug). Throws GraphError naming the first edge with an endpoint out of range. O(n + m) plus
/// the algorithm.
AnyGraphMatching match_any_graph(std::uint32_t node_count,
                                 const std::vector<std::array<std::uint32_t, 2>>& edges,
                                 const PerfectMatchingOptions& options = {});

/// The matchings cheapest_matching_any_graph chooses among.
enum class CostObjective {
  maximum,   ///< the maximum-cardinality ones (the perfect ones when there are)
  any_size,  ///< all of them: with costs = −weight, a maximum-weight matching of any size
  perfect,   ///< the perfect ones; when there is none, a maximum matching and its Tutte–Berge set
};

/// What cheapest_matching_any_graph found, in the edge list's own ids.
struct AnyGraphCheapestMatching {
  /// The index in the edge list of each node's matched edge, or 0xFFFFFFFF when it is free.
  std::vector<std::uint32_t> mate_edge;
  std::uint32_t size = 0;       ///< matched edges
  bool perfect = false;         ///< every node matched
  std::int64_t total_cost = 0;  ///< the least among the matchings the objective allows
  /// CostObjective::perfect on a graph without a perfect matching: `mate_edge` is a maximum
  /// matching (total_cost 0) and this set A proves it so, and that no perfect matching exists:
  /// odd(G − A) − |A| > 0 nodes stay free in every matching (verify_maximum_matching).
  std::vector<std::uint32_t> tutte_set;
};

/// The matching of least total cost among those `objective` allows, of any graph given as an
/// edge list, with one integer cost per edge (at most 2^40 in absolute value): the common core
/// of `petersen match --objective cost|weight|perfect`, Python's matching functions and the
/// adaptors. Loops, which no matching has, are left out. maximum: cheapest_maximum_matching;
/// any_size: min_cost_matching at price 0; perfect: match_any_graph tells whether a perfect
/// matching exists (its Tutte–Berge witness checked), then min_cost_perfect_matching (all in
/// min_cost_matching.hpp). Every answer's dual solution goes through the independent verifier
/// before it returns (std::logic_error if it fails: a bug). `threads` as MinCostOptions::threads
/// (0: every core; the answer does not depend on it). Throws GraphError naming the first edge
/// with an endpoint out of range, std::invalid_argument for a cost out of range or a count of
/// costs other than of edges.
AnyGraphCheapestMatching cheapest_matching_any_graph(
    std::uint32_t node_count, const std::vector<std::array<std::uint32_t, 2>>& edges,
    const std::vector<std::int64_t>& costs, std::uint32_t threads = 1,
    CostObjective objective = CostObjective::maximum);

}  // namespace petersen
