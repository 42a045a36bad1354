#pragma once
// petersen's matchings for a Boost Graph Library graph, with the interface of Boost's own
// edmonds_maximum_cardinality_matching: the user's graph and the user's mate property map; and
// its minimum-cost matching, with the user's cost property map.

#include <array>
#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/property_map/property_map.hpp>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "petersen/matching/any_graph.hpp"

namespace petersen {

namespace adaptor_detail {

/// g's vertices by index (vertex_index maps them onto 0..num_vertices(g)-1) and its edges as
/// index pairs with their descriptors. An undirected graph lists each edge among the out-edges of
/// both ends: it is kept at the end with the smaller index; parallel edges are distinct
/// descriptors, so each copy is kept once; self-loops are skipped (no matching uses one).
template <class Graph, class VertexIndexMap>
struct IndexedEdges {
  using Traits = boost::graph_traits<Graph>;
  std::vector<typename Traits::vertex_descriptor> vertex_of;
  std::vector<std::array<std::uint32_t, 2>> edges;
  std::vector<typename Traits::edge_descriptor> descriptor;

  IndexedEdges(const Graph& g, VertexIndexMap vertex_index)
      : vertex_of(static_cast<std::uint32_t>(num_vertices(g))) {
    typename Traits::vertex_iterator v, v_end;
    for (boost::tie(v, v_end) = vertices(g); v != v_end; ++v)
      vertex_of[static_cast<std::uint32_t>(get(vertex_index, *v))] = *v;
    const auto n = static_cast<std::uint32_t>(vertex_of.size());
    for (std::uint32_t a = 0; a < n; ++a) {
      typename Traits::out_edge_iterator e, e_end;
      for (boost::tie(e, e_end) = out_edges(vertex_of[a], g); e != e_end; ++e) {
        const auto b = static_cast<std::uint32_t>(get(vertex_index, target(*e, g)));
        if (a < b) {
          edges.push_back({a, b});
          descriptor.push_back(*e);
        }
      }
    }
  }

  /// Writes each vertex's partner under `mate_edge` (an edge index per vertex, 0xFFFFFFFF when
  /// free) to `mate`, null_vertex() for a free one.
  template <class MateEdges, class MateMap>
  void put_mates(const MateEdges& mate_edge, MateMap mate) const {
    for (std::uint32_t a = 0; a < vertex_of.size(); ++a) {
      const std::uint32_t e = mate_edge[a];
      put(mate, vertex_of[a],
          e == 0xFFFFFFFFu ? Traits::null_vertex() : vertex_of[edges[e][0] ^ edges[e][1] ^ a]);
    }
  }
};

}  // namespace adaptor_detail

/// A matching of `g`, any undirected BGL graph modelling VertexListGraph and IncidenceGraph,
/// written to `mate` (a read-write vertex -> vertex property map) exactly as
/// boost::edmonds_maximum_cardinality_matching fills it: each vertex's partner, or
/// graph_traits<Graph>::null_vertex() when it is unmatched. `vertex_index` maps the vertices onto
/// 0..num_vertices(g)-1. On a cubic bridgeless graph (parallel edges allowed) the matching is
/// perfect, found by `options.algorithm`, and the result is true; on any other graph it is a
/// maximum matching (augmenting paths, with Tutte–Berge proof checked inside) and the result says
/// whether it is perfect. Self-loops are skipped (no matching uses one; a vertex whose other
/// edges then number fewer than 3 makes the graph non-cubic, as it should). Copies the graph into
/// an edge list: O(n + m) time and memory beside match_any_graph (any_graph.hpp).
template <class Graph, class MateMap, class VertexIndexMap,
          std::enable_if_t<!std::is_convertible_v<VertexIndexMap, PerfectMatchingOptions>, int> = 0>
bool perfect_matching(const Graph& g, MateMap mate, VertexIndexMap vertex_index,
                      const PerfectMatchingOptions& options = {}) {
  const adaptor_detail::IndexedEdges<Graph, VertexIndexMap> indexed(g, vertex_index);
  const AnyGraphMatching matched =
      match_any_graph(static_cast<std::uint32_t>(indexed.vertex_of.size()), indexed.edges, options);
  indexed.put_mates(matched.mate_edge, mate);
  return matched.perfect;
}

/// The same with the graph's own vertex_index property map (as Boost's matching has).
template <class Graph, class MateMap>
bool perfect_matching(const Graph& g, MateMap mate, const PerfectMatchingOptions& options = {}) {
  return perfect_matching(g, mate, get(boost::vertex_index, g), options);
}

/// The matching of least total cost among the maximum matchings of `g` (any undirected BGL
/// graph, as above), under `cost`, a readable edge property map of integers (at most 2^40 in
/// absolute value; real weights are the caller's to scale and round), written to `mate` as
/// perfect_matching writes it; returns its total cost. A perfect matching when g has one.
/// Exact: cheapest_matching_any_graph (any_graph.hpp), whose dual solution the independent
/// verifier checks before it returns; `threads` as there. Self-loops are skipped. Throws
/// std::invalid_argument for a cost out of range.
template <class Graph, class CostMap, class MateMap, class VertexIndexMap,
          std::enable_if_t<!std::is_integral_v<VertexIndexMap>, int> = 0>
std::int64_t min_cost_matching(const Graph& g, CostMap cost, MateMap mate,
                               VertexIndexMap vertex_index, std::uint32_t threads = 1) {
  static_assert(std::is_integral_v<typename boost::property_traits<CostMap>::value_type>,
                "min_cost_matching takes integer costs: scale and round real weights first");
  const adaptor_detail::IndexedEdges<Graph, VertexIndexMap> indexed(g, vertex_index);
  std::vector<std::int64_t> costs;
  costs.reserve(indexed.edges.size());
  for (const auto& e : indexed.descriptor) costs.push_back(static_cast<std::int64_t>(get(cost, e)));
  const AnyGraphCheapestMatching cheapest = cheapest_matching_any_graph(
      static_cast<std::uint32_t>(indexed.vertex_of.size()), indexed.edges, costs, threads);
  indexed.put_mates(cheapest.mate_edge, mate);
  return cheapest.total_cost;
}

/// The same with the graph's own vertex_index property map.
template <class Graph, class CostMap, class MateMap>
std::int64_t min_cost_matching(const Graph& g, CostMap cost, MateMap mate,
                               std::uint32_t threads = 1) {
  return min_cost_matching(g, cost, mate, get(boost::vertex_index, g), threads);
}

}  // namespace petersen
