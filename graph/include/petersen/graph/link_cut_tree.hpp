#pragma once
// Link-cut trees (Sleator and Tarjan, J. Comput. Syst. Sci. 26, 1983): a forest of rooted trees
// under link, cut and evert, with roots and lowest common ancestors, all O(log n) amortized.

#include <cstdint>
#include <utility>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/link_cut_splay.hpp"

namespace petersen {

/// A dynamic forest on nodes 0..n-1 (n < 2^30 - 1) in flat arrays: splay trees over preferred paths
/// with a reversal bit for evert. Splaying is iterative. Every operation is O(log n) amortized.
class LinkCutTree {
 public:
  explicit LinkCutTree(std::uint32_t node_count);

  std::uint32_t node_count() const { return static_cast<std::uint32_t>(nodes_.size()); }
  /// Makes u the root of its tree.
  void evert(NodeId u);
  /// Adds the edge {u, v}; u and v must be in different trees. u becomes a child of v.
  void link(NodeId u, NodeId v);
  /// Removes the edge {u, v}, which must be in the forest. The part that held the root keeps it;
  /// the other is rooted at its end of the edge. One access and a splay.
  void cut(NodeId u, NodeId v);
  /// The root of u's tree.
  NodeId find_root(NodeId u);
  bool connected(NodeId u, NodeId v) { return find_root(u) == find_root(v); }
  /// Whether u lies in the tree of r, which must be its tree's root (as after evert(r)). One
  /// access, and no splay of the root as find_root(u) == r has.
  bool in_tree_of(NodeId r, NodeId u);
  /// The lowest common ancestor of u and v under the current roots; they must be connected.
  NodeId lca(NodeId u, NodeId v);

 private:
  // The splay core and 16-byte records are the cover forest's (link_cut_splay.hpp); this tree's
  // only lazy flag is the reversal.
  struct Push {
    [[gnu::always_inline]] void operator()(detail::LinkCutNode* t, std::uint32_t x) const;
  };
  void push(NodeId x) { Push{}(nodes_.data(), x); }
  void splay(NodeId x) { core_.splay(nodes_.data(), x); }
  NodeId access(NodeId x) { return core_.access(nodes_.data(), x); }

  std::vector<detail::LinkCutNode> nodes_;
  detail::LinkCutSplay<Push> core_;
};

inline void LinkCutTree::Push::operator()(detail::LinkCutNode* t, std::uint32_t x) const {
  detail::LinkCutNode& n = t[x];
  if (!(n.up & detail::kLinkCutReversed)) return;
  std::swap(n.child[0], n.child[1]);
  for (std::uint32_t c : n.child)
    if (c != detail::kLinkCutNil) t[c].up ^= detail::kLinkCutReversed;
  n.up &= detail::kLinkCutIdMask;
}

}  // namespace petersen
