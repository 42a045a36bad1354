#include "reduction/gw_chooser.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "petersen/graph/component_forest.hpp"

namespace petersen::reduction {

namespace {

bool contains(std::span<const EdgeId> edges, EdgeId e) {
  return std::find(edges.begin(), edges.end(), e) != edges.end();
}

}  // namespace

GwChooser::GwChooser(const ReductionGraph& graph, std::uint32_t edge_capacity,
                     std::span<const EdgeId> tree_edge, std::span<const EdgeId> cover)
    : forest_(graph.node_count(), edge_capacity), in_tree_(edge_capacity, 0) {
  for (NodeId v = 0; v < graph.node_count(); ++v) {
    const EdgeId e = tree_edge[v];
    if (e == kNoEdge) continue;
    in_tree_[e] = 1;
    forest_.hang(v, e, graph.other_end(e, v), cover[v]);
  }
}

void GwChooser::swap(EdgeId in, NodeId a, NodeId b, EdgeId out) {
  forest_.swap(in, a, b, out);
  in_tree_[out] = 0;
  in_tree_[in] = 1;
  ++swaps_;
}

void GwChooser::remove(const ReductionGraph& graph, std::span<const EdgeId> edges) {
  const EdgeId e = edges[0];
  const NodeId u = graph.end(e, 0), v = graph.end(e, 1);
  const auto internal = [&](EdgeId g) {
    return (graph.end(g, 0) ^ graph.end(g, 1)) == (u ^ v) &&
           (graph.end(g, 0) == u || graph.end(g, 0) == v);
  };
  const auto at_u = [&](EdgeId g) { return graph.end(g, 0) == u || graph.end(g, 1) == u; };
  // Stage 0: an edge between u and v in the tree.
  if (std::none_of(edges.begin(), edges.end(),
                   [&](EdgeId g) { return internal(g) && in_tree_[g]; })) {
    // Rooted at v, u's parent edge is the attachment at u on T's u–v path (one access; asking
    // each tree attachment at u whether it leads up took one lca, two accesses, each).
    forest_.evert(v);
    swap(e, v, u, forest_.parent_edge(u));  // swap need not evert v again
  }
  // Stage 1: merge pieces while a tree attachment has a cover outside the step. When none is
  // left, each piece's tree attachment and its cover are the piece's two attachments.
  for (bool merged = true; merged;) {
    merged = false;
    pieces_ = 0;
    for (EdgeId t : edges) {
      if (internal(t) || !in_tree_[t]) continue;
      const EdgeId c = forest_.cover(t);
      if (!contains(edges, c)) {
        swap(c, graph.end(c, 0), graph.end(c, 1), t);
        merged = true;
        break;
      }
      if (pieces_ < 2) piece_[pieces_] = {t, c};
      ++pieces_;
    }
  }
  // Stage 2: cut the tree attachments (one per piece), each below its end u or v made the root.
  // u, v and the tree edges between them are left as a tree of their own that no live node
  // reaches and no operation visits again, so they need no cuts. One access per end instead of
  // one per tree edge takes 6.4 % off the reductions' instructions (fertility-sub3's dual).
  for (EdgeId t : edges) {
    if (!in_tree_[t]) continue;
    in_tree_[t] = 0;
    if (internal(t)) continue;
    forest_.evert(at_u(t) ? u : v);
    forest_.cut_below_root(t);
  }
}

bool GwChooser::choose_h1(const ReductionGraph& graph, const Step& step) {
  if (pieces_ == 2) {
    // The pieces hold 13|24, 14|23 or 12|34 (see the header): H2 exactly for 13|24.
    for (const auto& piece : piece_)
      if ((piece[0] == step.a1 || piece[1] == step.a1))
        return !(piece[0] == step.b3 || piece[1] == step.b3);
  }
  const NodeId x1 = graph.other_end(step.a1, step.u), x2 = graph.other_end(step.a2, step.u);
  const NodeId x3 = graph.other_end(step.b3, step.v), x4 = graph.other_end(step.b4, step.v);
  // The ds rule: H2 exactly when the quartet is 13|24. Rooted at x1, x2 and x4 meet at l24 and
  // x3 joins x4's path at l34, both on the path from x4 up; 13|24 exactly when l24 lies strictly
  // below l34, i.e. off the path from x1 to x3, which the last access left preferred: a splay
  // tells, where a fourth access did. For H1, add() then labels that path without an access.
  forest_.evert(x1);
  const NodeId l24 = forest_.lca(x2, x4), l34 = forest_.lca_after(x3);
  return l24 == l34 || forest_.on_root_path(l24);
}

void GwChooser::add(const ReductionGraph& graph, std::span<const EdgeId> edges) {
  // With two pieces the chosen pairing joins them: one new edge links them, the other covers.
  std::size_t first_cover = 0;
  if (pieces_ == 2) {
    forest_.link(edges[0], graph.end(edges[0], 0), graph.end(edges[0], 1));
    in_tree_[edges[0]] = 1;
    first_cover = 1;
  }
  for (std::size_t i = first_cover; i < edges.size(); ++i)
    forest_.cover_path(graph.end(edges[i], 0), graph.end(edges[i], 1), edges[i]);
}

void GwChooser::verify(const ReductionGraph& graph) {
  const std::uint32_t n = graph.node_count(), m = graph.edge_count();
  const auto fail = [](const std::string& what) { throw std::logic_error("gw chooser: " + what); };
  std::vector<std::uint8_t> live(m, 0);
  std::vector<std::vector<std::pair<NodeId, EdgeId>>> tree(n);
  ComponentForest graph_parts(n), tree_parts(n);
  std::uint32_t graph_joins = 0;
  for (NodeId v = 0; v < n; ++v) {
    if (!graph.alive(v)) continue;
    for (int k = 0; k < 3; ++k) live[graph.slot(v, k)] = 1;
  }
  for (EdgeId g = 0; g < m; ++g) {
    if (!live[g]) {
      if (in_tree_[g]) fail("removed edge " + std::to_string(g) + " is in the forest");
      continue;
    }
    const NodeId a = graph.end(g, 0), b = graph.end(g, 1);
    graph_joins += graph_parts.unite(a, b);
    if (!in_tree_[g]) continue;
    if (!tree_parts.unite(a, b)) fail("the forest has a cycle through edge " + std::to_string(g));
    tree[a].push_back({b, g});
    tree[b].push_back({a, g});
  }
  std::uint32_t tree_edges = 0;
  for (EdgeId g = 0; g < m; ++g) tree_edges += live[g] && in_tree_[g];
  if (tree_edges != graph_joins) fail("the forest does not span the graph");
  // Root every tree, then walk each cover's tree path.
  std::vector<NodeId> parent(n, kNoNode);
  std::vector<EdgeId> up(n, kNoEdge);
  std::vector<std::uint32_t> depth(n, 0);
  std::vector<std::uint8_t> seen(n, 0);
  for (NodeId r = 0; r < n; ++r) {
    if (!graph.alive(r) || seen[r]) continue;
    std::vector<NodeId> queue = {r};
    seen[r] = 1;
    for (std::size_t i = 0; i < queue.size(); ++i)
      for (auto [w, g] : tree[queue[i]])
        if (!seen[w]) {
          seen[w] = 1, parent[w] = queue[i], up[w] = g, depth[w] = depth[queue[i]] + 1;
          queue.push_back(w);
        }
  }
  for (EdgeId t = 0; t < m; ++t) {
    if (!live[t] || !in_tree_[t]) continue;
    const EdgeId c = forest_.cover(t);
    if (c >= m || !live[c] || in_tree_[c])
      fail("tree edge " + std::to_string(t) + " has no live non-tree cover");
    NodeId a = graph.end(c, 0), b = graph.end(c, 1);
    bool on_path = false;
    while (a != b) {
      if (depth[a] < depth[b]) std::swap(a, b);
      on_path |= up[a] == t;
      a = parent[a];
    }
    if (!on_path)
      fail("cover " + std::to_string(c) + " of tree edge " + std::to_string(t) + " misses it");
  }
}

}  // namespace petersen::reduction
