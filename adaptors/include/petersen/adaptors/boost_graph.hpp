#pragma once
// petersen's matchings for a Boost Graph Library graph, with the interface of Boost's own
// edmonds_maximum_cardinality_matching: the user's graph and the user's mate property map.

#include <array>
#include <boost/graph/graph_traits.hpp>
#include <boost/graph/properties.hpp>
#include <boost/property_map/property_map.hpp>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "petersen/matching/any_graph.hpp"

namespace petersen {

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
          std::enable_if_t<!std::is_convertible_v<VertexIndexMap, Options>, int> = 0>
bool perfect_matching(const Graph& g, MateMap mate, VertexIndexMap vertex_index,
                      const Options& options = {}) {
  using Traits = boost::graph_traits<Graph>;
  using Vertex = typename Traits::vertex_descriptor;
  const auto n = static_cast<std::uint32_t>(num_vertices(g));
  std::vector<Vertex> vertex_of(n);
  typename Traits::vertex_iterator v, v_end;
  for (boost::tie(v, v_end) = vertices(g); v != v_end; ++v)
    vertex_of[static_cast<std::uint32_t>(get(vertex_index, *v))] = *v;
  // An undirected graph lists each edge among the out-edges of both ends: keep it at the end with
  // the smaller index. Parallel edges are distinct descriptors, so each copy is kept once.
  std::vector<std::array<std::uint32_t, 2>> edges;
  for (std::uint32_t a = 0; a < n; ++a) {
    typename Traits::out_edge_iterator e, e_end;
    for (boost::tie(e, e_end) = out_edges(vertex_of[a], g); e != e_end; ++e) {
      const auto b = static_cast<std::uint32_t>(get(vertex_index, target(*e, g)));
      if (a < b) edges.push_back({a, b});
    }
  }
  const AnyGraphMatching matched = match_any_graph(n, edges, options);
  for (std::uint32_t a = 0; a < n; ++a) {
    const std::uint32_t e = matched.mate_edge[a];
    put(mate, vertex_of[a],
        e == 0xFFFFFFFFu ? Traits::null_vertex() : vertex_of[edges[e][0] ^ edges[e][1] ^ a]);
  }
  return matched.perfect;
}

/// The same with the graph's own vertex_index property map (as Boost's matching has).
template <class Graph, class MateMap>
bool perfect_matching(const Graph& g, MateMap mate, const Options& options = {}) {
  return perfect_matching(g, mate, get(boost::vertex_index, g), options);
}

}  // namespace petersen
