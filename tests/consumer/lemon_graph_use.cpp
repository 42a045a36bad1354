// The LEMON adaptor on lemon::ListGraph, in a C++17 translation unit, checked against LEMON's
// own MaxMatching and MaxWeightedPerfectMatching.

#include <lemon/list_graph.h>
#include <lemon/matching.h>

#include <cstdint>
#include <cstdio>
#include <petersen/adaptors/lemon_graph.hpp>
#include <vector>

#include "checks.hpp"

namespace {

using lemon::ListGraph;

// The mate map holds a matching as MaxMatching's matchingMap() does: each node's arc starts at
// it, and its partner's arc is the opposite one. Returns the matched edge count, or -1.
int matching_size(const ListGraph& g, const ListGraph::NodeMap<ListGraph::Arc>& mate) {
  int matched_nodes = 0;
  for (ListGraph::NodeIt v(g); v != lemon::INVALID; ++v) {
    if (mate[v] == lemon::INVALID) continue;
    if (g.source(mate[v]) != v || mate[g.target(mate[v])] != g.oppositeArc(mate[v])) return -1;
    ++matched_nodes;
  }
  return matched_nodes / 2;
}

int lemon_size(const ListGraph& g) {
  lemon::MaxMatching<ListGraph> matcher(g);
  matcher.run();
  return matcher.matchingSize();
}

}  // namespace

int check_lemon_graph() {
  int failures = 0;
  ListGraph petersen_graph;
  std::vector<ListGraph::Node> v;
  for (int i = 0; i < 10; ++i) v.push_back(petersen_graph.addNode());
  for (int i = 0; i < 5; ++i) {
    petersen_graph.addEdge(v[i], v[(i + 1) % 5]);
    petersen_graph.addEdge(v[5 + i], v[5 + (i + 2) % 5]);
    petersen_graph.addEdge(v[i], v[5 + i]);
  }
  ListGraph::NodeMap<ListGraph::Arc> mate(petersen_graph);
  const bool perfect = petersen::perfect_matching(petersen_graph, mate, {petersen::Algorithm::gw});
  failures += !perfect || matching_size(petersen_graph, mate) != 5;

  // Two nodes joined by three parallel edges (the theta graph): perfect, one edge.
  ListGraph theta;
  const ListGraph::Node a = theta.addNode(), b = theta.addNode();
  for (int k = 0; k < 3; ++k) theta.addEdge(a, b);
  ListGraph::NodeMap<ListGraph::Arc> theta_mate(theta);
  failures +=
      !petersen::perfect_matching(theta, theta_mate) || matching_size(theta, theta_mate) != 1;

  // A path of five nodes with a loop: not cubic, a maximum matching of LEMON's size, false.
  ListGraph path;
  std::vector<ListGraph::Node> p;
  for (int i = 0; i < 5; ++i) p.push_back(path.addNode());
  for (int i = 0; i + 1 < 5; ++i) path.addEdge(p[i], p[i + 1]);
  path.addEdge(p[2], p[2]);
  ListGraph::NodeMap<ListGraph::Arc> path_mate(path);
  failures += petersen::perfect_matching(path, path_mate) ||
              matching_size(path, path_mate) != lemon_size(path);

  // The cheapest perfect matching of the Petersen graph under costs 1..15, against LEMON's
  // MaxWeightedPerfectMatching on the negated costs.
  ListGraph::EdgeMap<int> cost(petersen_graph), negated(petersen_graph);
  int k = 0;
  for (ListGraph::EdgeIt e(petersen_graph); e != lemon::INVALID; ++e, ++k) {
    cost[e] = 1 + (k * 7) % 15;
    negated[e] = -cost[e];
  }
  ListGraph::NodeMap<ListGraph::Arc> cheapest_mate(petersen_graph);
  const std::int64_t total = petersen::min_cost_matching(petersen_graph, cost, cheapest_mate);
  lemon::MaxWeightedPerfectMatching<ListGraph, ListGraph::EdgeMap<int>> weighted(petersen_graph,
                                                                                 negated);
  weighted.run();
  std::int64_t written = 0;
  for (ListGraph::NodeIt v(petersen_graph); v != lemon::INVALID; ++v) {
    if (cheapest_mate[v] != lemon::INVALID && petersen_graph.source(cheapest_mate[v]) == v &&
        petersen_graph.id(v) < petersen_graph.id(petersen_graph.target(cheapest_mate[v]))) {
      written += cost[cheapest_mate[v]];
    }
  }
  failures += matching_size(petersen_graph, cheapest_mate) != 5 ||
              total != -weighted.matchingWeight() || written != total;
  std::printf("LEMON adaptor: %s\n", failures == 0 ? "ok" : "FAILED");
  return failures;
}
