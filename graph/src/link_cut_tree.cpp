#include "petersen/graph/link_cut_tree.hpp"

#include <stdexcept>
#include <utility>

namespace petersen {

using detail::kLinkCutNil;
using detail::kLinkCutReversed;

LinkCutTree::LinkCutTree(std::uint32_t node_count) {
  if (node_count >= kLinkCutNil) throw std::length_error("LinkCutTree: 2^30 - 1 nodes or more");
  nodes_.assign(node_count, {{kLinkCutNil, kLinkCutNil}, kLinkCutNil, 0});
}

void LinkCutTree::evert(NodeId u) {
  access(u);
  nodes_[u].up ^= kLinkCutReversed;
}

void LinkCutTree::link(NodeId u, NodeId v) {
  evert(u);
  core_.set_parent(nodes_.data(), u, v);  // u, a splay root alone on its path, hangs below v
}

void LinkCutTree::cut(NodeId u, NodeId v) {
  // After the access, u ends its preferred path. Either v is u's parent: v is u's predecessor on
  // that path, and once splayed it has u alone on its right. Or v is u's child: v then starts
  // its own path, whose splay tree hangs from u by a path parent, and v has nothing on its left
  // once splayed. So a splay does, where an evert and a second access would make cut 5.2 % of
  // ds's instructions (armadillo's dual).
  access(u);
  splay(v);
  if (nodes_[v].child[1] == u) {
    nodes_[v].child[1] = kLinkCutNil;
    core_.set_parent(nodes_.data(), u, kLinkCutNil);
  } else {
    core_.set_parent(nodes_.data(), v, kLinkCutNil);
  }
}

NodeId LinkCutTree::find_root(NodeId u) {
  access(u);
  NodeId x = u;
  for (push(x); nodes_[x].child[0] != kLinkCutNil; push(x)) x = nodes_[x].child[0];
  splay(x);
  return x;
}

bool LinkCutTree::in_tree_of(NodeId r, NodeId u) {
  // After u's access, u's splay tree holds the path from u's root: r is in it exactly when it is
  // that root. The climb from r takes at most four steps: r was the root of its splay tree, the
  // access's splay there leaves that old root at most two levels below the splayed node, and the
  // final splay of u puts that node at most two below u (measured: 1-4 steps on armadillo's
  // dual). find_root walked down to r instead, splayed it, and the next access of u splayed u
  // back.
  access(u);
  std::uint32_t x = r;
  while (!core_.is_splay_root(nodes_.data(), x)) x = core_.parent(nodes_.data(), x);
  return x == u;
}

NodeId LinkCutTree::lca(NodeId u, NodeId v) {
  access(u);
  return access(v);
}

}  // namespace petersen
