#include "petersen/graph/link_cut_tree.hpp"

#include <utility>

namespace petersen {

LinkCutTree::LinkCutTree(std::uint32_t node_count)
    : child_(2 * std::size_t{node_count}, kNoNode),
      parent_(node_count, kNoNode),
      reversed_(node_count, 0) {}

bool LinkCutTree::is_splay_root(NodeId x) const {
  const NodeId p = parent_[x];
  return p == kNoNode || (child_[2 * std::size_t{p}] != x && child_[2 * std::size_t{p} + 1] != x);
}

void LinkCutTree::push(NodeId x) {
  if (!reversed_[x]) return;
  std::swap(child_[2 * std::size_t{x}], child_[2 * std::size_t{x} + 1]);
  for (int k = 0; k < 2; ++k)
    if (NodeId c = child_[2 * std::size_t{x} + k]; c != kNoNode) reversed_[c] ^= 1;
  reversed_[x] = 0;
}

void LinkCutTree::rotate(NodeId x) {
  const NodeId y = parent_[x], z = parent_[y];
  const int side = child_[2 * std::size_t{y} + 1] == x ? 1 : 0;
  if (!is_splay_root(y)) child_[2 * std::size_t{z} + (child_[2 * std::size_t{z} + 1] == y)] = x;
  parent_[x] = z;
  const NodeId moved = child_[2 * std::size_t{x} + 1 - side];
  child_[2 * std::size_t{y} + side] = moved;
  if (moved != kNoNode) parent_[moved] = y;
  child_[2 * std::size_t{x} + 1 - side] = y;
  parent_[y] = x;
}

void LinkCutTree::splay(NodeId x) {
  path_.clear();
  for (NodeId y = x;; y = parent_[y]) {
    path_.push_back(y);
    if (is_splay_root(y)) break;
  }
  for (auto it = path_.rbegin(); it != path_.rend(); ++it) push(*it);
  while (!is_splay_root(x)) {
    const NodeId y = parent_[x];
    if (!is_splay_root(y)) {
      const NodeId z = parent_[y];
      const bool zigzig = (child_[2 * std::size_t{y}] == x) == (child_[2 * std::size_t{z}] == y);
      rotate(zigzig ? y : x);
    }
    rotate(x);
  }
}

NodeId LinkCutTree::access(NodeId x) {
  NodeId last = kNoNode;
  for (NodeId y = x; y != kNoNode; y = parent_[y]) {
    splay(y);
    child_[2 * std::size_t{y} + 1] = last;
    last = y;
  }
  splay(x);
  return last;
}

void LinkCutTree::evert(NodeId u) {
  access(u);
  reversed_[u] ^= 1;
}

void LinkCutTree::link(NodeId u, NodeId v) {
  evert(u);
  parent_[u] = v;
}

void LinkCutTree::cut(NodeId u, NodeId v) {
  evert(u);
  access(v);
  // The path is u–v alone: u is v's left child, with no children of its own on the path.
  const NodeId left = child_[2 * std::size_t{v}];
  child_[2 * std::size_t{v}] = kNoNode;
  parent_[left] = kNoNode;
}

NodeId LinkCutTree::find_root(NodeId u) {
  access(u);
  NodeId x = u;
  for (push(x); child_[2 * std::size_t{x}] != kNoNode; push(x)) x = child_[2 * std::size_t{x}];
  splay(x);
  return x;
}

NodeId LinkCutTree::lca(NodeId u, NodeId v) {
  access(u);
  return access(v);
}

}  // namespace petersen
