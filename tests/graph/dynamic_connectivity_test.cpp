// Holm–de Lichtenberg–Thorup dynamic connectivity against union-find on random update sequences,
// with the reported spanning-forest changes replayed on a mirror forest.

#include "petersen/graph/dynamic_connectivity.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <numeric>
#include <set>
#include <vector>

namespace petersen {
namespace {

struct UnionFind {
  std::vector<NodeId> parent;
  explicit UnionFind(std::uint32_t n) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
  NodeId find(NodeId x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  }
  bool unite(NodeId a, NodeId b) {
    a = find(a), b = find(b);
    parent[a] = b;
    return a != b;
  }
};

RC_GTEST_PROP(DynamicConnectivity, AgreesWithUnionFindAndReportsTheForest, ()) {
  const auto n = *rc::gen::inRange<std::uint32_t>(1, 16);
  const std::uint32_t capacity = 48;
  DynamicConnectivity dc(n, capacity);
  std::vector<std::array<NodeId, 2>> ends(capacity);
  std::set<EdgeId> present, forest;  // forest: F_0 as replayed from the return values
  std::uint64_t tree_deletions = 0;
  // Half the runs start from a bulk insertion of edges 0..k-1, whose forest must be the one
  // inserting them one by one in id order gives.
  if (*rc::gen::arbitrary<bool>()) {
    const auto k = *rc::gen::inRange<EdgeId>(0, capacity);
    std::vector<NodeId> flat;
    UnionFind order(n);
    for (EdgeId e = 0; e < k; ++e) {
      ends[e] = {*rc::gen::inRange<NodeId>(0, n), *rc::gen::inRange<NodeId>(0, n)};
      flat.insert(flat.end(), ends[e].begin(), ends[e].end());
    }
    dc.insert_all(flat);
    for (EdgeId e = 0; e < k; ++e) {
      present.insert(e);
      const bool joins = ends[e][0] != ends[e][1] && order.unite(ends[e][0], ends[e][1]);
      RC_ASSERT(dc.is_tree_edge(e) == joins);
      if (joins) forest.insert(e);
    }
  }
  const auto steps = *rc::gen::inRange(1, 300);
  for (int s = 0; s < steps; ++s) {
    const EdgeId e = *rc::gen::inRange<EdgeId>(0, capacity);
    if (!present.count(e)) {
      const NodeId u = *rc::gen::inRange<NodeId>(0, n), v = *rc::gen::inRange<NodeId>(0, n);
      ends[e] = {u, v};
      present.insert(e);
      if (dc.insert_edge(e, u, v)) forest.insert(e);
    } else {
      const DynamicConnectivity::Deletion d = dc.delete_edge(e);
      present.erase(e);
      RC_ASSERT(d.was_tree_edge == (forest.count(e) == 1));
      forest.erase(e);
      tree_deletions += d.was_tree_edge;
      if (d.replacement != kNoEdge) {
        RC_ASSERT(present.count(d.replacement) == 1);
        RC_ASSERT(forest.count(d.replacement) == 0);
        forest.insert(d.replacement);
      }
    }
    // The mirror is a spanning forest of the present edges, and connectivity agrees with it.
    UnionFind all(n), tree(n);
    for (EdgeId f : present) all.unite(ends[f][0], ends[f][1]);
    for (EdgeId f : forest) {
      RC_ASSERT(present.count(f) == 1);
      RC_ASSERT(dc.is_tree_edge(f));
      RC_ASSERT(tree.unite(ends[f][0], ends[f][1]));  // acyclic
    }
    for (NodeId u = 0; u < n; ++u)
      for (NodeId v = 0; v < n; ++v) {
        RC_ASSERT((all.find(u) == all.find(v)) == (tree.find(u) == tree.find(v)));
        RC_ASSERT(dc.connected(u, v) == (all.find(u) == all.find(v)));
      }
  }
  RC_ASSERT(dc.replacement_searches() == tree_deletions);
}

TEST(DynamicConnectivity, ReplacesADeletedCycleEdge) {
  DynamicConnectivity dc(4, 4);
  for (EdgeId e = 0; e < 4; ++e) dc.insert_edge(e, e, (e + 1) % 4);
  EXPECT_FALSE(dc.is_tree_edge(3));  // closes the cycle
  const auto d = dc.delete_edge(1);
  EXPECT_TRUE(d.was_tree_edge);
  EXPECT_EQ(d.replacement, 3u);
  EXPECT_TRUE(dc.connected(1, 2));
  EXPECT_FALSE(dc.delete_edge(3).replacement != kNoEdge);
  EXPECT_FALSE(dc.connected(1, 2));
}

}  // namespace
}  // namespace petersen
