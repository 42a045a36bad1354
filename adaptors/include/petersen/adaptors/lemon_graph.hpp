#pragma once
// petersen's matchings for a LEMON graph, filling the mate map as lemon::MaxMatching's
// matchingMap() does. C++17, with everything it includes: Debian's LEMON 1.3.1 headers do not
// compile as C++20, so a LEMON user's translation unit is C++17.

#include <lemon/core.h>

#include <array>
#include <cstdint>
#include <vector>

#include "petersen/matching/any_graph.hpp"

namespace petersen {

/// A matching of `g` (ListGraph, SmartGraph or any graph of LEMON's undirected Graph concept),
/// written to `mate` as lemon::MaxMatching::matchingMap() holds it: for each node, its matched
/// edge directed away from it (g.source(mate[v]) == v), or lemon::INVALID when it is unmatched.
/// On a cubic bridgeless graph (parallel edges allowed) the matching is perfect, found by
/// `options.algorithm`, and the result is true; on any other graph (loops included: never
/// matched) it is a maximum matching (augmenting paths, with Tutte–Berge proof checked inside)
/// and the result says whether it is perfect. Copies the graph into an edge list: O(n + m) time
/// and memory beside match_any_graph (any_graph.hpp).
template <class GR>
bool perfect_matching(const GR& g, typename GR::template NodeMap<typename GR::Arc>& mate,
                      const Options& options = {}) {
  typename GR::template NodeMap<std::uint32_t> index(g);
  std::vector<typename GR::Node> node_of;
  for (typename GR::NodeIt v(g); v != lemon::INVALID; ++v) {
    index[v] = static_cast<std::uint32_t>(node_of.size());
    node_of.push_back(v);
  }
  std::vector<typename GR::Edge> edge_of;
  std::vector<std::array<std::uint32_t, 2>> edges;
  for (typename GR::EdgeIt e(g); e != lemon::INVALID; ++e) {
    edge_of.push_back(e);
    edges.push_back({index[g.u(e)], index[g.v(e)]});
  }
  const AnyGraphMatching matched =
      match_any_graph(static_cast<std::uint32_t>(node_of.size()), edges, options);
  for (std::uint32_t v = 0; v < node_of.size(); ++v) {
    const std::uint32_t e = matched.mate_edge[v];
    mate[node_of[v]] =
        e == 0xFFFFFFFFu ? typename GR::Arc(lemon::INVALID) : g.direct(edge_of[e], node_of[v]);
  }
  return matched.perfect;
}

}  // namespace petersen
