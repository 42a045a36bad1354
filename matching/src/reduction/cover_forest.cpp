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
  nodes_ = make_raw_array<Node>(size);
  std::fill_n(nodes_.get(), node_count, Node{{kNil, kNil}, kNil, kNoEdge});
}

void CoverForest::hang(NodeId child, EdgeId e, NodeId parent, EdgeId cover) {
  // Path-parent pointers alone are a valid link-cut forest: every splay tree a single node.
  nodes_[child].up = edge_node(e);
  nodes_[edge_node(e)] = Node{{kNil, kNil}, parent, cover};
}

void CoverForest::give_label(std::uint32_t x, EdgeId label) {
  nodes_[x].data = label;
  nodes_[x].up |= kPending;
}

std::uint32_t CoverForest::access(std::uint32_t x) {
  accessed_ = x;
  return core_.access(nodes_.get(), x);
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
  // below in's node, which hangs below b. After parent_edge(b) under the root a (gw's stage 0)
  // the path is already b's splay tree: a splay instead of an access.
  cover_path(a, b, out);
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
  // parent is no child), and one given later to a tree holding e's node was given at a root above
  // it: the label that applies is that of e's highest ancestor in its splay tree with a pending
  // label, else e's own. A climb reads it without writing; a splay (3.4 per access before an
  // access was not needed either) pays for a long climb.
  const std::uint32_t x = edge_node(e);
  EdgeId label = nodes_[x].data;
  std::uint32_t depth = 0;
  for (std::uint32_t y = x; !core_.is_splay_root(nodes_.get(), y); ++depth) {
    y = parent(y);
    if (nodes_[y].up & kPending) label = nodes_[y].data;
  }
  if (depth > kLongClimb) splay(x);
  return label;
}

}  // namespace petersen::reduction
