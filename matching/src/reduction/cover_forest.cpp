#include "reduction/cover_forest.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace petersen::reduction {

CoverForest::CoverForest(std::uint32_t node_count, std::uint32_t edge_capacity)
    : base_(node_count) {
  if (std::uint64_t{node_count} + edge_capacity >= kNil)
    throw std::length_error("CoverForest: more than 2^30 nodes and edges");
  // An edge's node is written when the edge enters the forest (hang, link, swap) and not read
  // before: the pages of edges that never do are never touched.
  const std::size_t size = std::size_t{node_count} + edge_capacity;
  nodes_ = make_huge_array<Node>(size);
  std::fill_n(nodes_.get(), node_count, Node{{kNil, kNil}, kNil, kNoEdge});
}

void CoverForest::hang(NodeId child, EdgeId e, NodeId parent, EdgeId cover) {
  // Path-parent pointers alone are a valid link-cut forest: every splay tree a single node.
  nodes_[child].up = edge_node(e);
  nodes_[edge_node(e)] = Node{{kNil, kNil}, parent, cover};
}

bool CoverForest::is_splay_root(std::uint32_t x) const {
  const std::uint32_t p = parent(x);
  return p == kNil || (nodes_[p].child[0] != x && nodes_[p].child[1] != x);
}

void CoverForest::give_label(std::uint32_t x, EdgeId label) {
  nodes_[x].label = label;
  nodes_[x].up |= kPending;
}

void CoverForest::push(std::uint32_t x) {
  Node& n = nodes_[x];
  if (n.up & kReversed) {
    std::swap(n.child[0], n.child[1]);
    for (std::uint32_t c : n.child)
      if (c != kNil) nodes_[c].up ^= kReversed;
  }
  if (n.up & kPending) {
    for (std::uint32_t c : n.child)
      if (c != kNil) give_label(c, n.label);
  }
  n.up &= kIdMask;
}

void CoverForest::rotate(std::uint32_t x, bool parent_is_root) {
  // x, its parent y and y's parent z were pushed by splay: their flags are clear.
  const std::uint32_t y = parent(x), z = parent(y);
  const int side = nodes_[y].child[1] == x ? 1 : 0;
  if (!parent_is_root) nodes_[z].child[nodes_[z].child[1] == y ? 1 : 0] = x;
  nodes_[x].up = z;
  const std::uint32_t moved = nodes_[x].child[1 - side];
  nodes_[y].child[side] = moved;
  if (moved != kNil) set_parent(moved, y);
  nodes_[x].child[1 - side] = y;
  nodes_[y].up = x;
}

void CoverForest::splay(std::uint32_t x) {
  path_.clear();
  for (std::uint32_t y = x;; y = parent(y)) {
    path_.push_back(y);
    if (is_splay_root(y)) break;
  }
  for (auto it = path_.rbegin(); it != path_.rend(); ++it) push(*it);
  // x's depth in its splay tree is known, so no step asks again where the root is.
  std::size_t depth = path_.size() - 1;
  for (; depth >= 2; depth -= 2) {
    const std::uint32_t y = parent(x), z = parent(y);
    const bool zigzig = (nodes_[y].child[0] == x) == (nodes_[z].child[0] == y);
    if (zigzig)
      rotate(y, depth == 2);
    else
      rotate(x, false);
    rotate(x, depth == 2);
  }
  if (depth == 1) rotate(x, true);
}

std::uint32_t CoverForest::access(std::uint32_t x) {
  std::uint32_t last = kNil;
  for (std::uint32_t y = x; y != kNil; y = parent(y)) {
    splay(y);
    nodes_[y].child[1] = last;
    last = y;
  }
  splay(x);
  accessed_ = x;
  return last;
}

void CoverForest::evert(NodeId a) {
  if (a == root_) return;
  access(a);
  nodes_[a].up ^= kReversed;
  root_ = a;
  accessed_ = kNil;  // the path from the root to a is a alone now
}

void CoverForest::link(EdgeId e, NodeId a, NodeId b) {
  const std::uint32_t m = edge_node(e);
  nodes_[m] = Node{{kNil, kNil}, b, kNoEdge};  // m below b
  access(a);
  nodes_[a].up ^= kReversed;  // a is the root of its tree, and alone in its splay tree
  set_parent(a, m);           // a's tree below m
  root_ = accessed_ = kNil;
}

void CoverForest::swap(EdgeId in, NodeId a, NodeId b, EdgeId out) {
  // Label the path a..b first, then split it at out's node: the part from a (the root) hangs
  // below in's node, which hangs below b.
  evert(a);
  access(b);
  give_label(b, out);
  const std::uint32_t m = edge_node(out);
  splay(m);
  const std::uint32_t above = nodes_[m].child[0];
  set_parent(above, edge_node(in));
  set_parent(nodes_[m].child[1], kNil);
  nodes_[m].child[0] = nodes_[m].child[1] = kNil;
  nodes_[edge_node(in)] = Node{{kNil, kNil}, b, out};
  root_ = accessed_ = kNil;
}

void CoverForest::cut_below_root(EdgeId e) {
  // e's node m is a child of the root r. Either m shares r's preferred path, which starts at r:
  // after splaying m, r alone is left of it; or m tops its own path, whose path parent r is then
  // held by m as its splay root. An access (splaying r, switching r's path, splaying m again)
  // is not needed for either.
  const std::uint32_t m = edge_node(e);
  splay(m);
  if (const std::uint32_t above = nodes_[m].child[0]; above != kNil) {
    set_parent(above, kNil);
    nodes_[m].child[0] = kNil;
  } else {
    set_parent(m, kNil);
  }
  accessed_ = kNil;
}

EdgeId CoverForest::parent_edge(NodeId x) {
  // After the access, the path from the root to x is x's splay tree, x at its root: the parent
  // edge's node is x's predecessor on it, the last node of x's left subtree. Splaying it pays
  // for the walk down.
  access(x);
  std::uint32_t y = nodes_[x].child[0];
  push(y);
  while (nodes_[y].child[1] != kNil) {
    y = nodes_[y].child[1];
    push(y);
  }
  splay(y);
  return y - base_;
}

NodeId CoverForest::lca(NodeId a, NodeId b) {
  access(a);
  return access(b);
}

NodeId CoverForest::lca_after(NodeId b) {
  return access(b);
}

bool CoverForest::on_root_path(NodeId x) {
  // Only the preferred path from the root has no path parent above its splay tree.
  splay(x);
  return parent(x) == kNil;
}

void CoverForest::cover_path(NodeId a, NodeId b, EdgeId cover) {
  evert(a);
  if (accessed_ == b)
    splay(b);  // b's splay tree holds the path from the root a to b, and no more
  else
    access(b);
  give_label(b, cover);
}

EdgeId CoverForest::cover(EdgeId e) {
  // A pending label reaches only the splay tree it was given in (one preferred path; a path
  // parent is no child), so splaying e's node within its splay tree pushes down every label
  // that applies to it: the climb along path parents an access would add is not needed. That was
  // a quarter of cover's splays on armadillo-sub2's dual (1.4M covers, 3.4 splays per access).
  splay(edge_node(e));
  return nodes_[edge_node(e)].label;
}

}  // namespace petersen::reduction
