#include "petersen/generators/graph_generators.hpp"

#include <utility>

#include "petersen/graph/connectivity.hpp"
#include "petersen/graph/seeded_random.hpp"

namespace petersen {

namespace {

using EdgeList = std::vector<std::array<NodeId, 2>>;

CubicGraph build(std::uint32_t n, const EdgeList& edges) {
  return CubicGraph::from_edges(n, edges);
}

}  // namespace

CubicGraph theta_graph() {
  return build(2, {{0, 1}, {0, 1}, {0, 1}});
}

CubicGraph complete_k4() {
  return build(4, {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}});
}

CubicGraph complete_k33() {
  EdgeList edges;
  for (NodeId a = 0; a < 3; ++a)
    for (NodeId b = 3; b < 6; ++b) edges.push_back({a, b});
  return build(6, edges);
}

CubicGraph petersen_graph() {
  EdgeList edges;
  for (NodeId i = 0; i < 5; ++i) {
    edges.push_back({i, (i + 1) % 5});          // outer cycle
    edges.push_back({i, 5 + i});                // spoke
    edges.push_back({5 + i, 5 + (i + 2) % 5});  // inner pentagram
  }
  return build(10, edges);
}

CubicGraph prism(std::uint32_t k) {
  if (k < 2) throw GraphError("prism needs k >= 2; got " + std::to_string(k));
  EdgeList edges;
  for (NodeId i = 0; i < k; ++i) {
    edges.push_back({i, (i + 1) % k});
    edges.push_back({k + i, k + (i + 1) % k});
    edges.push_back({i, k + i});
  }
  return build(2 * k, edges);
}

CubicGraph necklace(std::uint32_t k) {
  if (k < 1) throw GraphError("necklace needs k >= 1");
  // Diamond i: a=4i, b=4i+1, c=4i+2, d=4i+3 with a-b, a-c, b-c, b-d, c-d; d joins the next a.
  EdgeList edges;
  for (NodeId i = 0; i < k; ++i) {
    NodeId a = 4 * i, b = a + 1, c = a + 2, d = a + 3;
    edges.insert(edges.end(), {{a, b}, {a, c}, {b, c}, {b, d}, {c, d}, {d, 4 * ((i + 1) % k)}});
  }
  return build(4 * k, edges);
}

CubicGraph random_cubic_bridgeless(std::uint32_t n, std::uint64_t seed) {
  if (n < 2 || n % 2 != 0) {
    throw GraphError("a cubic graph needs an even number >= 2 of nodes; got " + std::to_string(n));
  }
  SeededRandom random(seed);
  std::vector<NodeId> stubs(3 * std::size_t{n});
  for (std::size_t i = 0; i < stubs.size(); ++i) stubs[i] = static_cast<NodeId>(i / 3);
  EdgeList edges(stubs.size() / 2);
  // Loops appear about once per try whatever n is, so about e tries are expected.
  for (;;) {
    // Fisher–Yates with petersen's own draws: the same graph from a seed on any library.
    for (std::size_t i = stubs.size() - 1; i > 0; --i)
      std::swap(stubs[i], stubs[random.below64(i + 1)]);
    bool has_loop = false;
    for (std::size_t i = 0; i < edges.size(); ++i) {
      edges[i] = {stubs[2 * i], stubs[2 * i + 1]};
      has_loop |= edges[i][0] == edges[i][1];
    }
    if (has_loop) continue;
    CubicGraph graph = build(n, edges);
    if (count_components(graph) == 1 && !find_bridge(graph)) return graph;
  }
}

}  // namespace petersen
