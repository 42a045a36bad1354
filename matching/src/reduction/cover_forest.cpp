#include "reduction/cover_forest.hpp"

#include <utility>

namespace petersen::reduction {

namespace {
constexpr std::uint32_t kNil = 0xFFFFFFFFu;
}

CoverForest::CoverForest(std::uint32_t node_count, std::uint32_t edge_capacity)
    : nodes_(std::size_t{node_count} + edge_capacity,
             Node{{kNil, kNil}, kNil, kNoEdge, kNoEdge, 0}),
      base_(node_count) {}

void CoverForest::hang(NodeId child, EdgeId e, NodeId parent, EdgeId cover) {
  // Path-parent pointers alone are a valid link-cut forest: every splay tree a single node.
  nodes_[child].parent = edge_node(e);
  nodes_[edge_node(e)].parent = parent;
  nodes_[edge_node(e)].label = cover;
}

bool CoverForest::is_splay_root(std::uint32_t x) const {
  const std::uint32_t p = nodes_[x].parent;
  return p == kNil || (nodes_[p].child[0] != x && nodes_[p].child[1] != x);
}

void CoverForest::give_label(std::uint32_t x, EdgeId label) {
  if (x >= base_) nodes_[x].label = label;
  nodes_[x].pending = label;
}

void CoverForest::push(std::uint32_t x) {
  Node& n = nodes_[x];
  if (n.reversed) {
    std::swap(n.child[0], n.child[1]);
    for (std::uint32_t c : n.child)
      if (c != kNil) nodes_[c].reversed ^= 1;
    n.reversed = 0;
  }
  if (n.pending != kNoEdge) {
    for (std::uint32_t c : n.child)
      if (c != kNil) give_label(c, n.pending);
    n.pending = kNoEdge;
  }
}

void CoverForest::rotate(std::uint32_t x) {
  const std::uint32_t y = nodes_[x].parent, z = nodes_[y].parent;
  const int side = nodes_[y].child[1] == x ? 1 : 0;
  if (!is_splay_root(y)) nodes_[z].child[nodes_[z].child[1] == y ? 1 : 0] = x;
  nodes_[x].parent = z;
  const std::uint32_t moved = nodes_[x].child[1 - side];
  nodes_[y].child[side] = moved;
  if (moved != kNil) nodes_[moved].parent = y;
  nodes_[x].child[1 - side] = y;
  nodes_[y].parent = x;
}

void CoverForest::splay(std::uint32_t x) {
  path_.clear();
  for (std::uint32_t y = x;; y = nodes_[y].parent) {
    path_.push_back(y);
    if (is_splay_root(y)) break;
  }
  for (auto it = path_.rbegin(); it != path_.rend(); ++it) push(*it);
  while (!is_splay_root(x)) {
    const std::uint32_t y = nodes_[x].parent;
    if (!is_splay_root(y)) {
      const std::uint32_t z = nodes_[y].parent;
      const bool zigzig = (nodes_[y].child[0] == x) == (nodes_[z].child[0] == y);
      rotate(zigzig ? y : x);
    }
    rotate(x);
  }
}

std::uint32_t CoverForest::access(std::uint32_t x) {
  std::uint32_t last = kNil;
  for (std::uint32_t y = x; y != kNil; y = nodes_[y].parent) {
    splay(y);
    nodes_[y].child[1] = last;
    last = y;
  }
  splay(x);
  return last;
}

void CoverForest::evert(NodeId a) {
  access(a);
  nodes_[a].reversed ^= 1;
}

void CoverForest::link(EdgeId e, NodeId a, NodeId b) {
  const std::uint32_t m = edge_node(e);
  nodes_[m] = Node{{kNil, kNil}, b, kNoEdge, kNoEdge, 0};  // m below b
  evert(a);
  nodes_[a].parent = m;  // a's tree below m
}

void CoverForest::cut(EdgeId e, NodeId a, NodeId b) {
  evert(edge_node(e));
  for (std::uint32_t x : {a, b}) {  // x hangs right below e's node: detach it from the root
    access(x);
    nodes_[nodes_[x].child[0]].parent = kNil;
    nodes_[x].child[0] = kNil;
  }
}

void CoverForest::cut_above(EdgeId e) {
  const std::uint32_t m = edge_node(e);
  access(m);
  nodes_[nodes_[m].child[0]].parent = kNil;
  nodes_[m].child[0] = kNil;
}

NodeId CoverForest::lca(NodeId a, NodeId b) {
  access(a);
  return access(b);
}

NodeId CoverForest::lca_after(NodeId b) {
  return access(b);
}

void CoverForest::cover_path(NodeId a, NodeId b, EdgeId cover) {
  evert(a);
  access(b);
  give_label(b, cover);
}

EdgeId CoverForest::cover(EdgeId e) {
  access(edge_node(e));
  return nodes_[edge_node(e)].label;
}

}  // namespace petersen::reduction
