#include "contestants.hpp"

#include <boost/graph/adjacency_list.hpp>
#include <boost/graph/max_cardinality_matching.hpp>
#include <chrono>
#include <stdexcept>
#include <utility>

#include "bfs_floor.hpp"
#include "petersen/lemon_peer/lemon_peer.hpp"
#include "petersen/lrs/lrs.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "verification_error.hpp"

namespace petersen::bench {

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

void require_perfect(const CubicGraph& graph, const Matching& matching) {
  const MatchingCheck check = verify_perfect_matching(graph, matching);
  if (!check.ok()) throw VerificationError(check.message);
}

// The floor (bfs_floor.hpp).
Measures breadth_first_search(const BenchInput& input, std::uint64_t) {
  const auto start = std::chrono::steady_clock::now();
  const std::uint32_t reached = bfs_floor(input.dual.graph);
  Measures measures;
  measures.initial_seconds = seconds_since(start);
  if (reached != input.dual.graph.node_count()) throw std::logic_error("BFS missed nodes");
  return measures;
}

// petersen's own algorithms, through the front door (the graph was validated once, up front).
Measures petersen_algorithm(const BenchInput& input, Algorithm algorithm, Augment augment,
                            std::uint64_t seed) {
  const PerfectMatchingResult result = perfect_matching(
      input.dual.graph,
      {.algorithm = algorithm, .augment = augment, .seed = seed, .validate = false});
  require_perfect(input.dual.graph, result.matching);
  Measures measures;
  measures.initial_seconds = result.stats.initial_seconds;
  measures.augment_seconds = result.stats.augment_seconds;
  measures.unpaired = result.stats.unpaired_after_initial;
  measures.two_phase =
      algorithm == Algorithm::sg || algorithm == Algorithm::ps || algorithm == Algorithm::automatic;
  measures.augmenting_paths = result.stats.augmenting_paths;
  measures.labels = result.stats.nodes_labelled;
  measures.reductions = result.stats.reductions;
  return measures;
}

// LEMON's MaxMatching through the C++17 peer target: greedyInit() then startSparse(), one step
// here (the peer's time includes copying the graph into a lemon::SmartGraph).
Measures lemon_max_matching(const BenchInput& input, std::uint64_t) {
  const CubicGraph& graph = input.dual.graph;
  const auto start = std::chrono::steady_clock::now();
  Matching matching(graph.node_count());
  lemon_peer::maximum_matching(graph.node_count(), graph.edge_ends().data(), graph.edge_count(),
                               matching.mate_edge.data());
  Measures measures;
  measures.initial_seconds = seconds_since(start);
  require_perfect(graph, matching);
  return measures;
}

// Boost's edmonds_maximum_cardinality_matching, phase by phase as boost::matching() runs it:
// extra_greedy_matching, then edmonds_augmenting_path_finder until no path is left. Boost's own
// verifier, which edmonds_maximum_cardinality_matching runs last, is left out of the time.
Measures boost_peer(const BenchInput& input, std::uint64_t) {
  using Graph = boost::adjacency_list<boost::vecS, boost::vecS, boost::undirectedS>;
  using Vertex = boost::graph_traits<Graph>::vertex_descriptor;
  const CubicGraph& graph = input.dual.graph;
  Graph g(graph.node_count());
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const auto [a, b] = graph.endpoints(e);
    boost::add_edge(a, b, g);
  }
  std::vector<Vertex> mate(graph.node_count());
  Measures measures;
  measures.two_phase = true;
  auto start = std::chrono::steady_clock::now();
  boost::extra_greedy_matching<Graph, Vertex*>::find_matching(g, mate.data());
  measures.initial_seconds = seconds_since(start);
  const Vertex none = boost::graph_traits<Graph>::null_vertex();
  for (Vertex v : mate) measures.unpaired += v == none;
  start = std::chrono::steady_clock::now();
  boost::edmonds_augmenting_path_finder<Graph, Vertex*,
                                        boost::property_map<Graph, boost::vertex_index_t>::type>
      augmentor(g, mate.data(), boost::get(boost::vertex_index, g));
  while (augmentor.augment_matching()) ++measures.augmenting_paths;
  augmentor.get_current_matching(mate.data());
  measures.augment_seconds = seconds_since(start);

  // Boost names the mate node; both ends take the smallest edge id joining them.
  Matching matching(graph.node_count());
  for (NodeId v = 0; v < graph.node_count(); ++v) {
    if (mate[v] == none) continue;
    for (EdgeId e : graph.incident_edges(v))
      if (graph.other_end(e, v) == mate[v] && e < matching.mate_edge[v]) matching.mate_edge[v] = e;
  }
  require_perfect(graph, matching);
  return measures;
}

// LRS (paper §3.3–3.4) on the mesh: (a) contraction + expansion, (c) ℓ, (d) augmentation. Its
// matching pairs the triangles of K (the input with some edges flipped): lrs verifies it perfect
// on K's dual, and every triangle must be in one of its quads.
Measures lrs_contestant(const BenchInput& input, std::uint64_t) {
  const LrsPairing result = pair_closed_component_by_lrs(input.mesh, {.augment = Augment::local});
  if (2 * result.quads.size() != input.mesh.face_count()) {
    throw VerificationError("lrs left triangles unpaired");
  }
  Measures measures;
  measures.initial_seconds = result.stats.contraction_seconds + result.stats.expansion_seconds;
  measures.augment_seconds = result.stats.augment_seconds;
  measures.unpaired = result.stats.unpaired_after_expansion;
  measures.two_phase = true;
  measures.augmenting_paths = result.stats.augmenting_paths;
  measures.flips = result.stats.flipped_edges;
  return measures;
}

}  // namespace

std::vector<Contestant> all_contestants(std::uint32_t frink_max_nodes) {
  std::vector<Contestant> list;
  list.push_back({"bfs", "", false, true, 0xFFFFFFFFu, breadth_first_search});
  // The paper-faithful rows run the paper's PS (ps-faithful), the local rows what a user gets
  // by default (auto-local: the ordered sweep where the numbering is local, Schrijver's exact
  // matching on a bipartite dual where the sweep leaves nodes).
  const std::pair<Algorithm, Augment> greedy_rows[] = {{Algorithm::sg, Augment::local},
                                                       {Algorithm::sg, Augment::faithful},
                                                       {Algorithm::automatic, Augment::local},
                                                       {Algorithm::ps, Augment::faithful}};
  for (const auto& [algorithm, augment] : greedy_rows) {
    const std::string name =
        std::string(to_string(algorithm)) + "-" + std::string(to_string(augment));
    list.push_back({name, algorithm == Algorithm::sg ? "SG" : "PS", true, false, 0xFFFFFFFFu,
                    [algorithm, augment](const BenchInput& input, std::uint64_t seed) {
                      return petersen_algorithm(input, algorithm, augment, seed);
                    }});
  }
  for (Algorithm algorithm : {Algorithm::ds, Algorithm::gw, Algorithm::frink}) {
    list.push_back({std::string(to_string(algorithm)), algorithm == Algorithm::ds ? "DS" : "",
                    false, false, algorithm == Algorithm::frink ? frink_max_nodes : 0xFFFFFFFFu,
                    [algorithm](const BenchInput& input, std::uint64_t seed) {
                      return petersen_algorithm(input, algorithm, Augment::local, seed);
                    }});
  }
  list.push_back({"lrs", "LRS", false, false, 0xFFFFFFFFu, lrs_contestant});
  list.push_back({"lemon", "", false, false, 0xFFFFFFFFu, lemon_max_matching});
  list.push_back({"boost", "", false, false, 0xFFFFFFFFu, boost_peer});
  return list;
}

}  // namespace petersen::bench
