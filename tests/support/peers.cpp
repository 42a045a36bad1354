#include "peers.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>

#include "petersen/lemon_peer/lemon_peer.hpp"

namespace petersen::testing {

std::uint32_t boost_matching_size(std::uint32_t node_count,
                                  std::span<const std::array<std::uint32_t, 2>> edges) {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  Graph graph(node_count);
  for (auto [a, b] : edges) boost::add_edge(a, b, graph);
  std::vector<boost::graph_traits<Graph>::vertex_descriptor> mate(node_count);
  boost::edmonds_maximum_cardinality_matching(graph, mate.data());
  return static_cast<std::uint32_t>(boost::matching_size(graph, mate.data()));
}

Matching lemon_matching(const CubicGraph& g) {
  Matching matching(g.node_count());
  lemon_peer::maximum_matching(g.node_count(), g.edge_ends().data(), g.edge_count(),
                               matching.mate_edge.data());
  return matching;
}

std::uint32_t lemon_matching_size(std::uint32_t node_count,
                                  std::span<const std::array<std::uint32_t, 2>> edges) {
  std::vector<std::uint32_t> ends;
  for (auto [a, b] : edges) ends.insert(ends.end(), {a, b});
  std::vector<std::uint32_t> mate(node_count);
  lemon_peer::maximum_matching(node_count, ends.data(), static_cast<std::uint32_t>(edges.size()),
                               mate.data());
  std::uint32_t matched = 0;
  for (std::uint32_t e : mate) matched += e != 0xFFFFFFFFu;
  return matched / 2;
}

std::optional<std::int64_t> lemon_min_cost_perfect(
    std::uint32_t node_count, std::span<const std::array<std::uint32_t, 2>> edges,
    std::span<const std::int64_t> costs) {
  std::vector<std::uint32_t> mate(node_count);
  std::int64_t total = 0;
  std::vector<std::uint32_t> ends;
  for (const auto& [a, b] : edges) ends.insert(ends.end(), {a, b});
  if (!lemon_peer::min_cost_perfect_matching(node_count, ends.data(),
                                             static_cast<std::uint32_t>(edges.size()), costs.data(),
                                             mate.data(), total)) {
    return std::nullopt;
  }
  return total;
}

}  // namespace petersen::testing
