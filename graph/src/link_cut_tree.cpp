#include "petersen/graph/link_cut_tree.hpp"

#include <utility>

namespace petersen {

LinkCutTree::LinkCutTree(std::uint32_t node_count) : nodes_(node_count) {}

bool LinkCutTree::is_splay_root(NodeId x) const {
  const NodeId p = nodes_[x].parent;
  return p == kNoNode || (nodes_[p].child[0] != x && nodes_[p].child[1] != x);
}

void LinkCutTree::push(NodeId x) {
  Node& n = nodes_[x];
  if (!n.reversed) return;
  std::swap(n.child[0], n.child[1]);
  for (NodeId c : n.child)
    if (c != kNoNode) nodes_[c].reversed ^= 1;
  n.reversed = 0;
}

void LinkCutTree::rotate(NodeId x, bool parent_is_root) {
  const NodeId y = nodes_[x].parent, z = nodes_[y].parent;
  const int side = nodes_[y].child[1] == x ? 1 : 0;
  if (!parent_is_root) nodes_[z].child[nodes_[z].child[1] == y ? 1 : 0] = x;
  nodes_[x].parent = z;
  const NodeId moved = nodes_[x].child[1 - side];
  nodes_[y].child[side] = moved;
  if (moved != kNoNode) nodes_[moved].parent = y;
  nodes_[x].child[1 - side] = y;
  nodes_[y].parent = x;
}

void LinkCutTree::splay(NodeId x) {
  path_.clear();
  for (NodeId y = x;; y = nodes_[y].parent) {
    path_.push_back(y);
    if (is_splay_root(y)) break;
  }
  for (auto it = path_.rbegin(); it != path_.rend(); ++it) push(*it);
  // x's depth in its splay tree is known from the climb, so no rotation asks again where the
  // splay root is (two is_splay_root reads of a parent's children per step before; the ds
  // chooser's F_0 mirror was 13 % of its instructions, Callgrind on armadillo's dual).
  std::size_t depth = path_.size() - 1;
  for (; depth >= 2; depth -= 2) {
    const NodeId y = nodes_[x].parent, z = nodes_[y].parent;
    const bool zigzig = (nodes_[y].child[0] == x) == (nodes_[z].child[0] == y);
    if (zigzig)
      rotate(y, depth == 2);
    else
      rotate(x, false);
    rotate(x, depth == 2);
  }
  if (depth == 1) rotate(x, true);
}

NodeId LinkCutTree::access(NodeId x) {
  NodeId last = kNoNode;
  for (NodeId y = x; y != kNoNode; y = nodes_[y].parent) {
    splay(y);
    nodes_[y].child[1] = last;
    last = y;
  }
  splay(x);
  return last;
}

void LinkCutTree::evert(NodeId u) {
  access(u);
  nodes_[u].reversed ^= 1;
}

void LinkCutTree::link(NodeId u, NodeId v) {
  evert(u);
  nodes_[u].parent = v;
}

void LinkCutTree::cut(NodeId u, NodeId v) {
  evert(u);
  access(v);
  // The path is u–v alone: u is v's left child, with no children of its own on the path.
  const NodeId left = nodes_[v].child[0];
  nodes_[v].child[0] = kNoNode;
  nodes_[left].parent = kNoNode;
}

NodeId LinkCutTree::find_root(NodeId u) {
  access(u);
  NodeId x = u;
  for (push(x); nodes_[x].child[0] != kNoNode; push(x)) x = nodes_[x].child[0];
  splay(x);
  return x;
}

NodeId LinkCutTree::lca(NodeId u, NodeId v) {
  access(u);
  return access(v);
}

}  // namespace petersen
