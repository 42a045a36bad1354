#pragma once
// Tarjan's augmenting-path procedure (paper §3.1, reference [21]): grows any matching to a maximum
// one with Edmonds' blossoms, shrunk through a disjoint-set structure, searched breadth-first.

#include <cstdint>
#include <vector>

#include "petersen/graph/csr_graph.hpp"
#include "petersen/matching/matching.hpp"
#include "petersen/matching/perfect_matching.hpp"

namespace petersen {

/// What one augmentation run did.
struct AugmentStats {
  std::uint64_t augmenting_paths = 0;  ///< matched-edge count gained
  std::uint64_t blossoms = 0;          ///< blossoms shrunk
  std::uint64_t nodes_labelled = 0;    ///< even/odd labels given, over all searches
  std::uint64_t searches = 0;          ///< alternating trees grown
};

/// Grows `matching` to a maximum matching of `graph`; on a cubic bridgeless graph the result is
/// perfect. `faithful` is the paper's procedure: one breadth-first search per free node, each
/// after an O(n) reset, O(k·n) for k free nodes. `local` grows the alternating trees of all free
/// nodes at once, so the nearest free nodes meet first; its cost follows the region it labels
/// (plus one pass setting up 16 bytes of search state per node). Iterative, O(n) extra memory.
AugmentStats augment_matching(const CubicGraph& graph, Matching& matching,
                              Augment variant = Augment::local);

/// The same procedure on a general graph: grows `matching` (mate_edge per node, kNoEdge when
/// free) to a maximum matching of `graph`. O(k·(n + m)) for k augmentations, usually far less.
AugmentStats augment_matching(const CsrGraph& graph, Matching& matching,
                              Augment variant = Augment::local);

struct MaximumMatchingResult {
  Matching matching;
  std::uint32_t size = 0;  ///< matched edges
  AugmentStats stats;
  /// The proof of maximality: the odd nodes of the final Edmonds forest (the Gallai–Edmonds set
  /// A). verify_maximum_matching (tutte_berge.hpp) checks it. Sorted by node id.
  std::vector<NodeId> tutte_set;
};

/// A maximum matching of a general graph with its Tutte–Berge witness: a greedy pass over the
/// edges in id order, then augment_matching, then one more complete growth from the free nodes
/// for the witness. The library's maximum-matching fallback. O(n + m) plus the augmentation.
MaximumMatchingResult maximum_matching(const CsrGraph& graph, Augment variant = Augment::local);

/// The same from a given (valid) initial matching instead of the greedy pass.
MaximumMatchingResult maximum_matching(const CsrGraph& graph, Matching initial,
                                       Augment variant = Augment::local);

}  // namespace petersen
