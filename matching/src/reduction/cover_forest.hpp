#pragma once
// A spanning forest in link-cut trees (Sleator and Tarjan, J. Comput. Syst. Sci. 26, 1983) whose
// tree edges carry a label, its cover: the gw chooser's one data structure. Every graph edge is a
// node of its own between its two endpoints, so a label sits on the edge and survives evert; a
// whole tree path is relabelled at once by a lazy assignment.

#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/link_cut_splay.hpp"
#include "petersen/graph/memory.hpp"

namespace petersen::reduction {

/// Nodes 0..n-1 stand for the graph's nodes, n + e for edge e (e < edge_capacity), fewer than
/// 2^30 in all. Every operation but hang() is O(log n) amortized; splaying is iterative.
class CoverForest {
 public:
  CoverForest(std::uint32_t node_count, std::uint32_t edge_capacity);

  /// Set-up in O(1): hangs the tree rooted at `child` below `parent` by edge e labelled `cover`.
  /// Only before any other operation, and `child` must not have been hung before.
  void hang(NodeId child, EdgeId e, NodeId parent, EdgeId cover);

  /// Adds edge e = {a, b} to the forest; a and b must be in different trees.
  void link(EdgeId e, NodeId a, NodeId b);
  /// Puts non-tree edge in = {a, b} into the forest in place of tree edge out, which must lie on
  /// the tree path between a and b; that path's other edges and in are labelled out (out's
  /// fundamental cycle after the swap). Two accesses, one when cover_path(a, b, ·) would need
  /// one (after parent_edge(b) under the root a, for instance).
  void swap(EdgeId in, NodeId a, NodeId b, EdgeId out);
  /// Cuts tree edge e from its end that is its tree's root (the node last everted): e's node
  /// becomes the root of the other end's tree (a leaf there after the next evert; its label is
  /// never read again). One splay, no access.
  void cut_below_root(EdgeId e);
  /// Makes a the root of its tree; free when a is the node last everted and no link or swap came
  /// since.
  void evert(NodeId a);
  /// The tree edge from x to its parent under the current root (x must not be the root). One
  /// access.
  EdgeId parent_edge(NodeId x);
  /// The lowest common ancestor of a and b under the current roots; they must be connected.
  NodeId lca(NodeId a, NodeId b);
  /// lca(a, b) when the last call was lca(·, a) or lca_after(a): saves one access.
  NodeId lca_after(NodeId b);
  /// Whether x lies on the tree path from the root to b, when the last call was lca(·, b) or
  /// lca_after(b) (only splay-only calls, cover() and this, since). One splay.
  bool on_root_path(NodeId x);
  /// Labels every edge of the tree path between a and b (connected) with `cover`. No access when
  /// a is the root and the last call was lca(·, b) or lca_after(b) (or cover() and
  /// on_root_path() since): the path is then the preferred one.
  void cover_path(NodeId a, NodeId b, EdgeId cover);
  /// The label of tree edge e.
  EdgeId cover(EdgeId e);

 private:
  // Node.data: edge nodes, the cover; graph nodes, the pending label. The user flag of `up` marks
  // a pending label for the subtree's children: it equals an edge node's own label, and graph
  // nodes have none of their own, so one field holds both.
  using Node = detail::LinkCutNode;
  static constexpr std::uint32_t kReversed = detail::kLinkCutReversed;
  static constexpr std::uint32_t kPending = detail::kLinkCutUserFlag;
  static constexpr std::uint32_t kIdMask = detail::kLinkCutIdMask, kNil = detail::kLinkCutNil;
  static constexpr std::uint32_t kLongClimb = 8;  // cover() splays past this depth
  struct Push {
    [[gnu::always_inline]] void operator()(Node* t, std::uint32_t x) const;
  };
  std::uint32_t parent(std::uint32_t x) const { return nodes_[x].up & kIdMask; }
  void set_parent(std::uint32_t x, std::uint32_t p) {
    nodes_[x].up = (nodes_[x].up & ~kIdMask) | p;
  }
  std::uint32_t edge_node(EdgeId e) const { return base_ + e; }
  void give_label(std::uint32_t x, EdgeId label);
  void push(std::uint32_t x) { Push{}(nodes_.get(), x); }
  void splay(std::uint32_t x) { core_.splay(nodes_.get(), x); }
  std::uint32_t access(std::uint32_t x);  // returns the last node where the path was switched

  RawArray<Node> nodes_;
  std::uint32_t base_;  // the node of edge 0
  detail::LinkCutSplay<Push> core_;
  std::uint32_t root_ = kNil;  // the node last everted while it is still its tree's root
  // The node last accessed while the preferred path from the root to it is unchanged: set by
  // access(), cleared by every operation that changes paths after it.
  std::uint32_t accessed_ = kNil;
};

inline void CoverForest::Push::operator()(Node* t, std::uint32_t x) const {
  Node& n = t[x];
  if (!(n.up & (kReversed | kPending))) return;
  if (n.up & kReversed) {
    std::swap(n.child[0], n.child[1]);
    for (std::uint32_t c : n.child)
      if (c != kNil) t[c].up ^= kReversed;
  }
  if (n.up & kPending) {
    for (std::uint32_t c : n.child)
      if (c != kNil) t[c].data = n.data, t[c].up |= kPending;
  }
  n.up &= kIdMask;
}

}  // namespace petersen::reduction
