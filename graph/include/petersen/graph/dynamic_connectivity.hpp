#pragma once
// Fully dynamic connectivity (Holm, de Lichtenberg and Thorup, J. ACM 48, 2001): a spanning forest
// kept under edge insertions and deletions, O(log^2 n) amortized per update, O(log n) per query.

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"

namespace petersen {

namespace detail {
class EulerTourForest;
}

/// Multigraph on nodes 0..n-1 whose edges carry caller-chosen dense ids below `edge_capacity`.
/// Every edge has a level; the forests F_i of tree edges of level >= i are Euler-tour trees, and
/// a deleted tree edge is replaced by a non-tree edge of the highest level that reconnects,
/// raising the levels of what the search looked at (HDT's amortization). The caller learns each
/// change of the spanning forest F_0 from the return values.
class DynamicConnectivity {
 public:
  DynamicConnectivity(std::uint32_t node_count, std::uint32_t edge_capacity);
  ~DynamicConnectivity();
  DynamicConnectivity(DynamicConnectivity&&) noexcept;
  DynamicConnectivity& operator=(DynamicConnectivity&&) noexcept;

  /// Inserts edge e = {u, v} (e absent, e < edge_capacity; loops and parallel edges allowed).
  /// Returns true when e joined two trees, i.e. became a spanning-forest edge.
  bool insert_edge(EdgeId e, NodeId u, NodeId v);

  /// Inserts edges 0..k-1, edge e = {ends[2e], ends[2e + 1]}, into a structure that has no edge
  /// yet: the same spanning forest as k calls of insert_edge in id order (an edge is a tree edge
  /// exactly when it joins two trees; read it back with is_tree_edge), built in O(n + k) near
  /// linear time: union-find chooses the forest, and each tree's Euler tour becomes one balanced
  /// splay tree at once instead of k connectivity queries and links.
  void insert_all(std::span<const NodeId> ends);

  /// What a deletion did to the spanning forest: nothing (a non-tree edge), a split, or a split
  /// healed by `replacement` (now a spanning-forest edge).
  struct Deletion {
    bool was_tree_edge = false;
    EdgeId replacement = kNoEdge;
  };
  /// Deletes edge e, which must be present.
  Deletion delete_edge(EdgeId e);

  bool connected(NodeId u, NodeId v);
  bool contains(EdgeId e) const { return state_[e] != State::absent; }
  bool is_tree_edge(EdgeId e) const { return state_[e] == State::tree; }
  NodeId endpoint(EdgeId e, int k) const { return ends_[2 * std::size_t{e} + k]; }
  /// Tree-edge deletions that searched for a replacement.
  std::uint64_t replacement_searches() const { return replacement_searches_; }

 private:
  enum class State : std::uint8_t { absent, non_tree, tree };
  std::uint32_t vertex_node(NodeId v, int level);  // creates it on first use
  std::uint32_t& arc(EdgeId e, int level, int direction);
  void link_tree_edge(EdgeId e, int level);  // into F_level only
  void add_non_tree(EdgeId e);               // at its level, in both endpoints' lists
  void remove_non_tree(EdgeId e);
  EdgeId replace(NodeId u, NodeId v, int level);  // HDT's search at one level, or kNoEdge

  std::unique_ptr<detail::EulerTourForest> ett_;
  std::vector<NodeId> ends_;
  std::vector<std::uint8_t> level_;
  std::vector<State> state_;
  // Non-tree edges of a level at a vertex: a doubly linked list of half-edges 2e + side, headed
  // at the vertex's node of that level.
  std::vector<std::uint32_t> next_, prev_, head_;
  // Per vertex its nodes at levels 0..k, per edge its arcs at levels 0..level: blocks in a pool.
  // A block's start and size side by side: one cache miss per lookup instead of two (with
  // separate arrays the vertex lookups have 13 % of ds's D1 read misses on armadillo's dual).
  struct Block {
    std::uint32_t base = 0, capacity = 0;
  };
  std::vector<Block> vertex_block_, arc_block_;
  std::vector<std::uint32_t> pool_;
  std::array<std::vector<std::uint32_t>, 32> free_blocks_;  // bases of free blocks of size 2^i
  // Room for index i, moving the block if not. The check inline, the move not: a call per arc
  // and vertex lookup would be 3 % of ds's instructions (armadillo's dual).
  void reserve_block(Block& block, std::uint32_t i) {
    if (i >= block.capacity) [[unlikely]]
      grow_block(block, i);
  }
  void grow_block(Block& block, std::uint32_t i);
  void release_block(Block& block);
  std::uint64_t replacement_searches_ = 0;
};

}  // namespace petersen
