// The BGL adaptor on boost::adjacency_list, checked by Boost's own matching functions.

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>
#include <cstdint>
#include <cstdio>
#include <petersen/adaptors/boost_graph.hpp>
#include <petersen/testing/arbitrary.hpp>
#include <vector>

#include "checks.hpp"

namespace {

using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
using Vertex = boost::graph_traits<Graph>::vertex_descriptor;

// Boost's checks: a matching, of size n/2, and the adaptor's answer says perfect.
bool perfect_by_boost(const Graph& g) {
  std::vector<Vertex> mate(boost::num_vertices(g));
  const bool perfect = petersen::perfect_matching(g, &mate[0]);
  return perfect && boost::is_a_matching(g, &mate[0]) &&
         2 * boost::matching_size(g, &mate[0]) == boost::num_vertices(g);
}

Graph petersen_graph() {
  Graph g(10);
  for (int i = 0; i < 5; ++i) {
    boost::add_edge(i, (i + 1) % 5, g);          // outer cycle
    boost::add_edge(5 + i, 5 + (i + 2) % 5, g);  // inner pentagram
    boost::add_edge(i, 5 + i, g);                // spokes
  }
  return g;
}

}  // namespace

int check_boost_graph() {
  int failures = 0;
  failures += !perfect_by_boost(petersen_graph());

  // Random cubic bridgeless multigraphs (parallel edges included) copied into adjacency_lists.
  failures +=
      !rc::check("the BGL adaptor finds perfect matchings", [](const petersen::CubicGraph& c) {
        Graph g(c.node_count());
        for (petersen::EdgeId e = 0; e < c.edge_count(); ++e)
          boost::add_edge(c.endpoints(e)[0], c.endpoints(e)[1], g);
        RC_ASSERT(perfect_by_boost(g));
      });

  // A star K1,3 is not cubic: a maximum matching (one edge) and false, as Boost's own finds.
  Graph star(4);
  for (int leaf = 1; leaf < 4; ++leaf) boost::add_edge(0, leaf, star);
  std::vector<Vertex> mate(4), boost_mate(4);
  const bool perfect = petersen::perfect_matching(star, &mate[0]);
  boost::edmonds_maximum_cardinality_matching(star, &boost_mate[0]);
  failures += perfect || !boost::is_a_matching(star, &mate[0]) ||
              boost::matching_size(star, &mate[0]) != boost::matching_size(star, &boost_mate[0]);

  // The cheapest maximum matching through an edge_weight property: on a 4-cycle with costs
  // 1, 5, 1, 5 around it, the two edges of cost 1.
  using Weighted =
      boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS, boost::no_property,
                            boost::property<boost::edge_weight_t, long>>;
  Weighted square(4);
  for (int k = 0; k < 4; ++k) boost::add_edge(k, (k + 1) % 4, k % 2 == 0 ? 1L : 5L, square);
  std::vector<Vertex> square_mate(4);
  const std::int64_t total =
      petersen::min_cost_matching(square, get(boost::edge_weight, square), &square_mate[0]);
  failures += total != 2 || square_mate[0] != 1 || square_mate[2] != 3;
  std::printf("BGL adaptor: %s\n", failures == 0 ? "ok" : "FAILED");
  return failures;
}
