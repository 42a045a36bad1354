// Link-cut trees against a brute-force forest on random operation sequences.

#include "petersen/graph/link_cut_tree.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <set>
#include <utility>
#include <vector>

namespace petersen {
namespace {

// A forest as an edge set plus one root flag per tree, answering by breadth-first search.
struct BruteForest {
  explicit BruteForest(std::uint32_t n) : is_root(n, 1), n(n) {}
  std::set<std::pair<NodeId, NodeId>> edges;
  std::vector<char> is_root;
  std::uint32_t n;

  // Parents when every tree hangs from its root, and the tree (root) of each node.
  std::pair<std::vector<NodeId>, std::vector<NodeId>> hang() const {
    std::vector<NodeId> parent(n, kNoNode), tree(n, kNoNode);
    for (NodeId r = 0; r < n; ++r) {
      if (!is_root[r]) continue;
      std::vector<NodeId> queue = {r};
      tree[r] = r;
      for (std::size_t i = 0; i < queue.size(); ++i)
        for (auto [a, b] : edges)
          for (auto [x, y] : {std::pair{a, b}, std::pair{b, a}})
            if (x == queue[i] && tree[y] == kNoNode) tree[y] = r, parent[y] = x, queue.push_back(y);
    }
    return {parent, tree};
  }
};

RC_GTEST_PROP(LinkCutTree, AgreesWithBruteForce, ()) {
  const auto n = *rc::gen::inRange<std::uint32_t>(2, 24);
  LinkCutTree lct(n);
  BruteForest brute(n);
  const auto steps = *rc::gen::inRange(1, 200);
  for (int s = 0; s < steps; ++s) {
    const NodeId u = *rc::gen::inRange<NodeId>(0, n), v = *rc::gen::inRange<NodeId>(0, n);
    auto [parent, tree] = brute.hang();
    switch (*rc::gen::inRange(0, 5)) {
      case 0:  // link
        if (tree[u] != tree[v]) {
          brute.is_root[tree[u]] = 0;
          lct.link(u, v);
          brute.edges.insert({std::min(u, v), std::max(u, v)});
        }
        break;
      case 1:  // cut an existing edge: the part without the root is rooted at its end of it
        if (!brute.edges.empty()) {
          auto it = brute.edges.begin();
          std::advance(it, *rc::gen::inRange<std::size_t>(0, brute.edges.size()));
          auto [a, b] = *it;
          brute.edges.erase(it);
          brute.is_root[parent[a] == b ? a : b] = 1;
          if (*rc::gen::arbitrary<bool>()) std::swap(a, b);
          lct.cut(a, b);
        }
        break;
      case 2:
        brute.is_root[tree[u]] = 0;
        brute.is_root[u] = 1;
        lct.evert(u);
        break;
      case 3:
        RC_ASSERT(lct.find_root(u) == tree[u]);
        RC_ASSERT(lct.connected(u, v) == (tree[u] == tree[v]));
        RC_ASSERT(lct.in_tree_of(tree[v], u) == (tree[u] == tree[v]));
        break;
      default:
        if (tree[u] == tree[v]) {
          std::set<NodeId> up;
          for (NodeId x = u; x != kNoNode; x = parent[x]) up.insert(x);
          NodeId expected = v;
          while (!up.count(expected)) expected = parent[expected];
          RC_ASSERT(lct.lca(u, v) == expected);
        }
    }
  }
}

}  // namespace
}  // namespace petersen
