#pragma once
// Link-cut trees (Sleator and Tarjan, J. Comput. Syst. Sci. 26, 1983): a forest of rooted trees
// under link, cut and evert, with roots and lowest common ancestors, all O(log n) amortized.

#include <cstdint>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"

namespace petersen {

/// A dynamic forest on nodes 0..n-1 in flat arrays: splay trees over preferred paths with a
/// reversal bit for evert. Splaying is iterative. Every operation is O(log n) amortized.
class LinkCutTree {
 public:
  explicit LinkCutTree(std::uint32_t node_count);

  std::uint32_t node_count() const { return static_cast<std::uint32_t>(nodes_.size()); }
  /// Makes u the root of its tree.
  void evert(NodeId u);
  /// Adds the edge {u, v}; u and v must be in different trees. u becomes a child of v.
  void link(NodeId u, NodeId v);
  /// Removes the edge {u, v}, which must be in the forest.
  void cut(NodeId u, NodeId v);
  /// The root of u's tree.
  NodeId find_root(NodeId u);
  bool connected(NodeId u, NodeId v) { return find_root(u) == find_root(v); }
  /// The lowest common ancestor of u and v under the current roots; they must be connected.
  NodeId lca(NodeId u, NodeId v);

 private:
  // A node's children, parent and reversal bit in one 16-byte record, four to a cache line: a
  // splay step reads x, its parent and grandparent, one line each (they were three or four lines
  // each in separate arrays).
  struct Node {
    NodeId child[2] = {kNoNode, kNoNode};  // left (toward the root), right
    NodeId parent = kNoNode;               // splay parent, or path parent for a splay root
    std::uint32_t reversed = 0;
  };
  bool is_splay_root(NodeId x) const;
  void push(NodeId x);
  void rotate(NodeId x, bool parent_is_root);  // x's parent and grandparent are pushed
  void splay(NodeId x);
  NodeId access(NodeId x);  // returns the last node where the path to the root was switched

  std::vector<Node> nodes_;
  std::vector<NodeId> path_;  // scratch for splay's top-down push
};

}  // namespace petersen
