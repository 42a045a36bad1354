#pragma once
// petersen's matchings for a LEMON graph, filling the mate map as lemon::MaxMatching's
// matchingMap() does, and its minimum-cost matching under the user's edge cost map. C++17, with
// everything it includes: Debian's LEMON 1.3.1 headers do not compile as C++20, so a LEMON
// user's translation unit is C++17.

#include <lemon/core.h>

#include <array>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "petersen/matching/any_graph.hpp"

namespace petersen {

namespace adaptor_detail {

/// g's nodes and edges numbered in LEMON's iteration order, the edges as index pairs.
template <class GR>
struct LemonIndexedEdges {
  std::vector<typename GR::Node> node_of;
  std::vector<typename GR::Edge> edge_of;
  std::vector<std::array<std::uint32_t, 2>> edges;

  explicit LemonIndexedEdges(const GR& g) {
    typename GR::template NodeMap<std::uint32_t> index(g);
    for (typename GR::NodeIt v(g); v != lemon::INVALID; ++v) {
      index[v] = static_cast<std::uint32_t>(node_of.size());
      node_of.push_back(v);
    }
    for (typename GR::EdgeIt e(g); e != lemon::INVALID; ++e) {
      edge_of.push_back(e);
      edges.push_back({index[g.u(e)], index[g.v(e)]});
    }
  }

  /// Writes each node's matched edge under `mate_edge` (an edge index per node, 0xFFFFFFFF when
  /// free), directed away from it, to `mate`; lemon::INVALID for a free one.
  void put_mates(const GR& g, const std::vector<std::uint32_t>& mate_edge,
                 typename GR::template NodeMap<typename GR::Arc>& mate) const {
    for (std::uint32_t v = 0; v < node_of.size(); ++v) {
      const std::uint32_t e = mate_edge[v];
      mate[node_of[v]] =
          e == 0xFFFFFFFFu ? typename GR::Arc(lemon::INVALID) : g.direct(edge_of[e], node_of[v]);
    }
  }
};

}  // namespace adaptor_detail

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
                      const PerfectMatchingOptions& options = {}) {
  const adaptor_detail::LemonIndexedEdges<GR> indexed(g);
  const AnyGraphMatching matched =
      match_any_graph(static_cast<std::uint32_t>(indexed.node_of.size()), indexed.edges, options);
  indexed.put_mates(g, matched.mate_edge, mate);
  return matched.perfect;
}

/// The matching of least total cost among the maximum matchings of `g` under `cost` (an edge
/// map of integers, at most 2^40 in absolute value; real weights are the caller's to scale and
/// round), written to `mate` as perfect_matching writes it; returns its total cost. A perfect
/// matching when g has one. Exact: cheapest_matching_any_graph (any_graph.hpp), whose dual
/// solution the independent verifier checks before it returns; `threads` as there. Loops are
/// never matched. Throws std::invalid_argument for a cost out of range.
template <class GR, class CostMap>
std::int64_t min_cost_matching(const GR& g, const CostMap& cost,
                               typename GR::template NodeMap<typename GR::Arc>& mate,
                               std::uint32_t threads = 1) {
  static_assert(std::is_integral<typename CostMap::Value>::value,
                "min_cost_matching takes integer costs: scale and round real weights first");
  const adaptor_detail::LemonIndexedEdges<GR> indexed(g);
  std::vector<std::int64_t> costs;
  costs.reserve(indexed.edge_of.size());
  for (const auto& e : indexed.edge_of) costs.push_back(static_cast<std::int64_t>(cost[e]));
  const AnyGraphCheapestMatching cheapest = cheapest_matching_any_graph(
      static_cast<std::uint32_t>(indexed.node_of.size()), indexed.edges, costs, threads);
  indexed.put_mates(g, cheapest.mate_edge, mate);
  return cheapest.total_cost;
}

}  // namespace petersen
