#pragma once
// Euler-tour trees (Henzinger and King, J. ACM 46, 1999) on splay trees in flat arrays: each tree
// of a forest is the cyclic sequence of its vertex nodes and of two arc nodes per edge. Used by
// dynamic connectivity, one forest per level, all in one node pool.

#include <cstdint>
#include <vector>

namespace petersen::detail {

using EttNode = std::uint32_t;
inline constexpr EttNode kNoEtt = 0xFFFFFFFFu;

class EulerTourForest {
 public:
  /// A new one-vertex tree; `owner` is returned by owner(). O(1). At most 2^27 - 1 vertex nodes
  /// (the vertex count has 27 bits); throws std::length_error past that.
  EttNode make_vertex(std::uint32_t owner);
  /// A new arc node, not yet in any tree (reuses freed arcs). O(1).
  EttNode make_arc(std::uint32_t owner);
  void free_arc(EttNode a) { free_.push_back(a); }
  /// Room for `nodes` vertex and arc nodes in all, so that making them moves nothing.
  void reserve(std::size_t nodes) {
    nodes_.reserve(nodes);
    owner_.reserve(nodes);
  }

  std::uint32_t owner(EttNode x) const { return owner_[x]; }
  /// The splay root of x's tree (x is splayed to it): a handle comparable while nothing changes.
  EttNode root(EttNode x);
  /// Whether x and y lie in one tree. O(log n) amortized.
  bool same_tree(EttNode x, EttNode y);
  /// Number of vertex nodes in the tree whose splay root is r.
  std::uint32_t vertex_count(EttNode r) const { return count(r); }
  /// Joins the trees of vertex nodes x and y (different trees) by the arcs xy and yx.
  void link(EttNode x, EttNode y, EttNode xy, EttNode yx);
  /// Makes one tree of `tour`, a sequence of nodes that are each alone in their tree (an Euler
  /// tour: each vertex node once, each edge's two arcs around the tour of the side it leads
  /// to), as a perfectly balanced splay tree; returns its root. O(length), iterative.
  EttNode build(const std::vector<EttNode>& tour);
  /// Removes the edge with arcs a and b (both in one tree); the arcs leave all trees.
  void cut(EttNode a, EttNode b);
  /// Sets or clears flag bit `bit` (0 or 1) of node x, and the aggregates above it.
  void set_flag(EttNode x, int bit, bool on);
  bool flag(EttNode x, int bit) const { return (own(x) >> bit) & 1; }
  /// Some node with flag `bit` in the tree whose splay root is r, or kNoEtt. O(log n) amortized.
  EttNode find_flagged(EttNode r, int bit);

 private:
  // One node in 16 bytes, four to a cache line: a splay step reads and writes x, its parent and
  // grandparent, and each would be up to seven cache lines apart were every field in its own
  // array (the ds chooser on armadillo-sub2's dual: splay and rotate would be most of the time,
  // stalled on those loads). meta = vertex count << 5 | aggregate flags << 3 | own bits (0, 1 the
  // flags, 2 vertex); the owner, read once per raised edge, keeps an array of its own.
  struct Node {
    EttNode child[2] = {kNoEtt, kNoEtt};  // left, right
    EttNode parent = kNoEtt;
    std::uint32_t meta = 0;
  };
  static constexpr std::uint32_t kOwnMask = 7, kAggregateShift = 3, kCountShift = 5;

  std::uint32_t count(EttNode x) const { return nodes_[x].meta >> kCountShift; }
  std::uint32_t own(EttNode x) const { return nodes_[x].meta & kOwnMask; }
  std::uint32_t aggregate(EttNode x) const { return (nodes_[x].meta >> kAggregateShift) & 3; }
  EttNode make_node(std::uint32_t owner, bool vertex);
  // Inline in splay: out of line, with a branch per child, it would cost ds 180M more
  // instructions of 2.1G (armadillo's dual).
  [[gnu::always_inline]] inline void update(EttNode x);
  void splay(EttNode x);
  EttNode join(EttNode a, EttNode b);  // roots (or kNoEtt) of two sequences; returns the root
  EttNode detach_left(EttNode x);      // x must be a root; returns its old left subtree's root
  EttNode detach_right(EttNode x);
  EttNode reroot(EttNode x);  // the tour starting at x, x the root with no left subtree; returns x

  std::vector<Node> nodes_;
  std::vector<std::uint32_t> owner_;
  std::vector<EttNode> free_;
  std::uint32_t vertices_ = 0;
};

}  // namespace petersen::detail
