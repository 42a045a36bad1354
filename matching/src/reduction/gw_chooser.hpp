#pragma once
// Gawrychowski and Wasylkiewicz's chooser (ESA 2024, arXiv 2405.03856): Frink's reductions with
// one link-cut forest and no connectivity structure, O(n log n) in all. The forest T spans the
// current graph; each tree edge t carries a cover, a non-tree edge whose fundamental cycle
// passes through t (one exists exactly because t is no bridge). The derivation below is ours,
// written from the paper's idea; every step is checked against brute force in the tests.
//
// Swap(c, t), for c covering t: T − t + c is again a spanning forest; the edges of T that c
// covered now lie on t's fundamental cycle, so that path is relabelled t. Covers of other edges
// stay valid (cycle space: only cycles through t change, by adding c's cycle).
//
// Removing u, v (Frink step on e = {u, v}; the four attachments are u's and v's other edges):
//  0. If no edge between u and v is in T, swap e in for the tree edge at u on T's u–v path.
//  1. Let the pieces be the subtrees of T − {u, v}; each hangs from u or v by one tree
//     attachment. While some tree attachment t has a cover c that is not one of the step's
//     edges, c joins t's piece to another piece (its cycle passes u or v): swap(c, t). Each swap
//     merges two pieces; at most three happen.
//  2. Cut u and v out. Now every remaining tree attachment's cover is a non-tree attachment into
//     the same piece (no other edge at u or v covers it), so each piece holds two or more of the
//     four attachments: there are one or two pieces, and for two, each piece's attachments are
//     its tree attachment and that one's cover (no connectivity query needed). Cutting the tree
//     attachments (one evert of u or v, then a splay each) frees the pieces; the tree left on u
//     and v is never visited again.
// Choosing: one piece spans H' = H − {u, v}, and the Diks–Stańczyk quartet rule of ds_chooser.hpp
// applies. Two pieces holding {xa, xb} and {xc, xd}: whether or not H' joins them, a spanning
// tree of H' (or forest) has quartet or split ab|cd, so H2 iff {a, b} = {1, 3}, as in ds; the
// chosen pairing always joins the two pieces.
// Adding: a new edge that joins two trees is linked; every other new edge relabels its path. Why
// every cover is valid again: a cover that was one of the removed edges, or whose cycle passed u
// or v, left its label only on tree paths between attachment ends xi, xj in one piece, and the
// chosen pairing's new cycles cover every such path (a pairing leaves a Steiner-tree edge of
// x1..x4 uncovered only when it pairs the two sides of that edge: the quartet it avoids).
//
// Each reduction costs O(1) link-cut operations, so O(log n) amortized; set-up is O(n).
//
// Digon steps (u and v joined twice, attachments a1 and b3) go through the same three stages and
// end with one piece holding x1 and x3; the new edge x1x3 relabels their path.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "petersen/graph/memory.hpp"
#include "reduction/chooser.hpp"
#include "reduction/cover_forest.hpp"

namespace petersen::reduction {

class GwChooser final : public Chooser {
 public:
  /// The spanning forest given by each node's `tree_edge` to its parent (kNoEdge at a root),
  /// each tree edge labelled with `cover[node]`, a non-tree edge whose fundamental cycle passes
  /// through it (for a depth-first forest, the back edge that reaches highest from below it);
  /// O(n). `edge_capacity` bounds the ids of edges added later.
  GwChooser(const ReductionGraph& graph, std::uint32_t edge_capacity,
            std::span<const EdgeId> tree_edge, std::span<const EdgeId> cover);
  void remove(const ReductionGraph& graph, std::span<const EdgeId> edges) override;
  bool choose_h1(const ReductionGraph& graph, const Step& step) override;
  void add(const ReductionGraph& graph, std::span<const EdgeId> edges) override;
  /// Swaps of a cover into the forest (stage 0 and 1 above).
  std::uint64_t cover_swaps() const override { return swaps_; }
  /// Brute force: T is a spanning forest of the live graph and every cover is valid.
  void verify(const ReductionGraph& graph) override;

 private:
  // Swaps in = {a, b} into the forest for out; a is everted (free when it is the root).
  void swap(EdgeId in, NodeId a, NodeId b, EdgeId out);

  CoverForest forest_;
  std::pmr::vector<std::uint8_t> in_tree_;
  // After remove(): the pieces left (1 or 2) and, for two, each one's tree attachment and cover.
  std::uint32_t pieces_ = 0;
  std::array<std::array<EdgeId, 2>, 2> piece_{};
  std::uint64_t swaps_ = 0;
};

}  // namespace petersen::reduction
