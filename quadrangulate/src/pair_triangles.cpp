#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

#include "pair_by_lrs.hpp"
#include "petersen/graph/component_forest.hpp"
#include "petersen/graph/csr_graph.hpp"
#include "petersen/graph/parallel.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/matching/augment.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/matching/perfect_partners.hpp"
#include "petersen/matching/tutte_berge.hpp"
#include "petersen/matching/verify_min_cost.hpp"
#include "petersen/quadrangulate/stages.hpp"
#include "petersen/quadrangulate/triangle_prices.hpp"

namespace petersen::quad_detail {

namespace {

void add_run(PerfectMatchingStats& total, const PerfectMatchingStats& run) {
  total.initial_seconds += run.initial_seconds;
  total.augment_seconds += run.augment_seconds;
  total.unpaired_after_initial += run.unpaired_after_initial;
  total.augmenting_paths += run.augmenting_paths;
  total.blossoms += run.blossoms;
  total.nodes_labelled += run.nodes_labelled;
  total.reductions += run.reductions;
  total.replacement_searches += run.replacement_searches;
  total.cover_swaps += run.cover_swaps;
  total.schrijver = total.schrijver || run.schrijver;              // some component matched by it
  total.ordered_sweep = total.ordered_sweep || run.ordered_sweep;  // some component paired by it
  for (int k = 0; k < 3; ++k) total.lift_cases[k] += run.lift_cases[k];
}

// The minimum-cost matching's work in the paper's columns: its start as the initial pairing, its
// searches and certificate as the augmentation.
void add_min_cost_run(PerfectMatchingStats& total, const MinCostStats& run) {
  total.initial_seconds += run.init_seconds;
  total.unpaired_after_initial += run.free_after_init;
  total.augment_seconds += run.search_seconds + run.certificate_seconds;
  total.augmenting_paths += run.searches;
  total.blossoms += run.blossoms_shrunk;
  total.nodes_labelled += run.nodes_labelled;
}

// Components of the pairable graph (disjoint sets over its edges), numbered in order of their
// first node, and whether each is closed: every node has three pairable sides.
struct Components {
  std::vector<std::uint32_t> of_node;
  std::vector<std::uint8_t> closed;
};

Components components_of(const PairableGraph& graph) {
  const std::uint32_t n = graph.node_count;
  ComponentForest forest(n, graph.edge_ends);
  auto find = [&](NodeId v) { return forest.find(v); };
  Components components;
  components.of_node.resize(n);
  std::vector<std::uint32_t> id_of_root(n, kNoNode);
  for (NodeId v = 0; v < n; ++v) {
    const NodeId root = find(v);
    if (id_of_root[root] == kNoNode) {
      id_of_root[root] = static_cast<std::uint32_t>(components.closed.size());
      components.closed.push_back(1);
    }
    components.of_node[v] = id_of_root[root];
  }
  for (NodeId v = 0; v < n; ++v) {
    for (int k = 0; k < 3; ++k) {
      if (graph.node_edges[3 * std::size_t{v} + k] == kNoEdge) {
        components.closed[components.of_node[v]] = 0;
      }
    }
  }
  return components;
}

// The subgraph induced by `nodes` (whole components, ascending), renumbered in their order.
// Its edges keep their relative order; local edge i is graph edge edge_of[i].
struct Subgraph {
  std::vector<NodeId> nodes;
  std::vector<EdgeId> edge_of;
  std::pmr::vector<NodeId> edge_ends;
};

Subgraph induced(const PairableGraph& graph, std::vector<NodeId> nodes) {
  Subgraph sub;
  std::vector<NodeId> local(graph.node_count, kNoNode);
  for (NodeId i = 0; i < nodes.size(); ++i) local[nodes[i]] = i;
  // Counted first, so that the arrays are made at their size: grown by doubling, they would hold
  // up to twice that, and three times while moving.
  std::size_t edges = 0;
  for (EdgeId e = 0; e < graph.edge_count(); ++e) edges += local[graph.edge_ends[2 * e]] != kNoNode;
  sub.edge_of.reserve(edges);
  sub.edge_ends.reserve(2 * edges);
  for (EdgeId e = 0; e < graph.edge_count(); ++e) {
    const NodeId a = local[graph.edge_ends[2 * e]];
    if (a == kNoNode) continue;
    sub.edge_of.push_back(e);
    sub.edge_ends.push_back(a);
    sub.edge_ends.push_back(local[graph.edge_ends[2 * e + 1]]);
  }
  sub.nodes = std::move(nodes);
  return sub;
}

// The graph of these edge ends (edge e joins ends 2e and 2e + 1), in CsrGraph's form; the ends are
// freed before the graph is built, so that the two are not live together with the edge list.
CsrGraph csr_taking(std::uint32_t node_count, std::pmr::vector<NodeId> edge_ends,
                    std::pmr::memory_resource* memory) {
  std::vector<std::array<NodeId, 2>> edges(edge_ends.size() / 2);
  for (EdgeId e = 0; e < edges.size(); ++e) {
    edges[e] = {edge_ends[2 * std::size_t{e}], edge_ends[2 * std::size_t{e} + 1]};
  }
  free_storage(edge_ends);
  return CsrGraph::from_edges(node_count, edges, memory);
}

// The exact minimum-cost perfect matching of a closed graph, its certificate checked; adds the
// certified total to the pairing's objective.
Matching cheapest_perfect_matching(const CubicGraph& cubic, std::span<const Cost> costs,
                                   const QuadOptions& options, TrianglePairing& pairing,
                                   QuadStats& stats, Stopwatch& clock) {
  MinCostResult result = min_cost_perfect_matching(
      cubic, costs, {.threads = options.threads, .memory = options.memory});
  add_min_cost_run(stats.matching, result.stats);
  clock.lap();
  if (CertificateCheck check = verify_min_cost_perfect_matching(
          cubic.node_count(), cubic.edge_ends(), costs, result.matching, result.total_cost,
          result.certificate, options.memory);
      !check.ok()) {
    throw std::logic_error("internal error: the minimum-cost matching's certificate fails: " +
                           check.problem);
  }
  pairing.objective_units += result.total_cost;
  return std::move(result.matching);
}

// Closed components by `algorithm` (perfect, by Petersen's theorem), or with `costs` by the
// exact minimum-cost perfect matching; verified, and its certificate checked. `beside_verifier`
// runs on another thread (given options.threads > 1) while the matching is verified: work that
// needs neither the matching nor the matching's memory, which is freed by then.
template <class BesideVerifier>
void pair_closed(const CubicGraph& cubic, std::span<const NodeId> node_of,
                 std::span<const Cost> costs, const QuadOptions& options, Algorithm algorithm,
                 TrianglePairing& pairing, QuadStats& stats, Stopwatch& clock,
                 BesideVerifier beside_verifier) {
  std::string name(to_string(algorithm));
  // Made on options.memory and moved, never assigned (an assignment across resources copies).
  Matching matching = [&] {
    if (!costs.empty()) {
      name = "the minimum-cost matching";
      return cheapest_perfect_matching(cubic, costs, options, pairing, stats, clock);
    }
    // No bridge test: a bridge would leave a set of triangles whose only boundary is one edge,
    // but a boundary (mod 2) has no ends, and one edge has two.
    PerfectMatchingResult result = perfect_matching(cubic, {.algorithm = algorithm,
                                                            .augment = options.augment,
                                                            .seed = options.seed,
                                                            .validate = false,
                                                            .memory = options.memory});
    add_run(stats.matching, result.stats);
    clock.lap();
    return std::move(result.matching);
  }();
  MatchingCheck check;
  run_parallel(options.threads, 2, [&](std::uint32_t task) {
    if (task == 0) {
      check = verify_perfect_matching(cubic, matching);
    } else {
      beside_verifier();
    }
  });
  if (!check.ok()) {
    throw std::logic_error("internal error: " + name +
                           " returned a matching that is not perfect: " + check.message);
  }
  if (node_of.empty()) {
    // The whole graph: the partners are written over the mate edges, each from its own entry,
    // so that no second array of n entries is live beside the graph.
    pairing.partner = std::move(matching.mate_edge);
    for (NodeId v = 0; v < cubic.node_count(); ++v) {
      pairing.partner[v] = cubic.other_end(pairing.partner[v], v);
    }
  } else {
    for (NodeId v = 0; v < cubic.node_count(); ++v) {
      pairing.partner[node_of[v]] = node_of[cubic.other_end(matching.mate_edge[v], v)];
    }
  }
  stats.verify_seconds += clock.lap();
}

// The common case, ps on a closed mesh, on one adjacency: the graph becomes its neighbour rows
// in place and the matching runs on them alone, so at its peak it holds the mesh (24 bytes per
// triangle), the rows (12), the search state (16) and the partners (4). perfect_matching holds
// the graph (24), its table (28) and the mate edges (4) at once, 80 bytes per triangle with the
// mesh before PS's own sets: over the 64 the tool aims at. The same pairs, checked against the
// same adjacency.
// The components are counted on the edge list while the rows are written over the incidences,
// not before: each is a single-threaded pass of random reads, and the forest (4 bytes per node) is
// still gone before the matching's peak.
void pair_by_partners(CubicGraph cubic, Algorithm algorithm, const QuadOptions& options,
                      TrianglePairing& pairing, QuadStats& stats, Stopwatch& clock) {
  const std::uint32_t node_count = cubic.node_count();
  const std::pmr::vector<NodeId> rows =
      std::move(cubic).into_neighbour_rows(options.threads, [&](std::span<const NodeId> edge_ends) {
        stats.components = stats.closed_components =
            ComponentForest(node_count, edge_ends).root_count();
      });
  stats.dual_seconds += clock.lap();
  PartnerResult result = perfect_partners(rows, {.algorithm = algorithm,
                                                 .augment = options.augment,
                                                 .seed = options.seed,
                                                 .memory = options.memory});
  add_run(stats.matching, result.stats);
  clock.lap();
  if (MatchingCheck check = verify_perfect_partners(rows, result.partner); !check.ok()) {
    throw std::logic_error("internal error: ps returned a matching that is not perfect: " +
                           check.message);
  }
  pairing.partner = std::move(result.partner);
  stats.verify_seconds += clock.lap();
}

// The common case, a closed triangle mesh matched by a graph algorithm: the pairable graph is the
// cubic dual itself, taken over.
void pair_closed_whole_mesh(PairableGraph& graph, std::span<const Cost> costs,
                            const QuadOptions& options, Algorithm algorithm,
                            TrianglePairing& pairing, QuadStats& stats, Stopwatch& clock) {
  CubicGraph cubic =
      CubicGraph::from_valid_incidence(std::move(graph.node_edges), std::move(graph.edge_ends));
  if ((algorithm == Algorithm::automatic || algorithm == Algorithm::ps) && costs.empty()) {
    pair_by_partners(std::move(cubic), algorithm, options, pairing, stats, clock);
    return;
  }
  stats.dual_seconds += clock.lap();
  // Only their number, without per-node ids (two fresh arrays, most of a run's 4 KiB page faults),
  // counted while the matching is verified: a pass as long as the rest of the dual phase.
  pair_closed(cubic, {}, costs, options, algorithm, pairing, stats, clock, [&] {
    stats.components = stats.closed_components =
        ComponentForest(cubic.node_count(), cubic.edge_ends()).root_count();
  });
}

// Each closed component by lrs, one at a time; returns the nodes of those it cannot take, for the
// default algorithm (ascending).
std::vector<NodeId> pair_closed_components_by_lrs(PairableGraph& graph, const PolygonMesh& mesh,
                                                  const Components& components,
                                                  std::span<const NodeId> closed_nodes,
                                                  const QuadOptions& options,
                                                  TrianglePairing& pairing, QuadStats& stats,
                                                  Stopwatch& clock) {
  std::vector<NodeId> by_component(closed_nodes.begin(), closed_nodes.end());
  std::stable_sort(by_component.begin(), by_component.end(), [&](NodeId a, NodeId b) {
    return components.of_node[a] < components.of_node[b];
  });
  std::vector<VertexId> local(mesh.positions.size(), kNoNode);
  std::vector<NodeId> left;
  for (std::size_t first = 0; first < by_component.size();) {
    std::size_t last = first + 1;
    const std::uint32_t c = components.of_node[by_component[first]];
    while (last < by_component.size() && components.of_node[by_component[last]] == c) ++last;
    const std::span<const NodeId> nodes(by_component.data() + first, last - first);
    if (!pair_component_by_lrs(graph, mesh, nodes, nullptr, options, local, pairing, stats,
                               clock)) {
      left.insert(left.end(), nodes.begin(), nodes.end());
    }
    first = last;
  }
  std::sort(left.begin(), left.end());
  return left;
}

// The closed components among several, by `algorithm` or at minimum cost, on the subgraph they
// induce.
void pair_closed_components(const PairableGraph& graph, std::vector<NodeId> closed_nodes,
                            std::span<const Cost> costs, const QuadOptions& options,
                            Algorithm algorithm, TrianglePairing& pairing, QuadStats& stats,
                            Stopwatch& clock) {
  Subgraph sub = induced(graph, std::move(closed_nodes));
  std::pmr::vector<EdgeId> node_edges(3 * sub.nodes.size());
  std::vector<EdgeId> local_edge(graph.edge_count(), kNoEdge);
  for (EdgeId i = 0; i < sub.edge_of.size(); ++i) local_edge[sub.edge_of[i]] = i;
  for (NodeId i = 0; i < sub.nodes.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      node_edges[3 * std::size_t{i} + k] =
          local_edge[graph.node_edges[3 * std::size_t{sub.nodes[i]} + k]];
    }
  }
  const CubicGraph cubic =
      CubicGraph::from_valid_incidence(std::move(node_edges), std::move(sub.edge_ends));
  std::pmr::vector<Cost> local_costs;
  if (!costs.empty()) {
    for (EdgeId e : sub.edge_of) local_costs.push_back(costs[e]);
  }
  stats.dual_seconds += clock.lap();
  pair_closed(cubic, sub.nodes, local_costs, options, algorithm, pairing, stats, clock, [] {});
}

// The cheapest of the maximum matchings of the open components, its certificate checked; adds the
// certified total to the pairing's objective.
Matching cheapest_maximum_matching(const CsrGraph& open, std::span<const EdgeId> edge_of,
                                   std::span<const Cost> costs, const QuadOptions& options,
                                   TrianglePairing& pairing, QuadStats& stats, Stopwatch& clock) {
  std::pmr::vector<Cost> local_costs;
  for (EdgeId e : edge_of) local_costs.push_back(costs[e]);
  MinCostMaximumResult cheapest = min_cost_maximum_matching(
      open, local_costs, {.threads = options.threads, .memory = options.memory});
  stats.matching.augment_seconds += clock.lap();
  if (CertificateCheck check = verify_min_cost_maximum_matching(
          open.node_count(), open.edge_ends(), local_costs, cheapest.matching, cheapest.total_cost,
          cheapest.unmatched_cost, cheapest.certificate, options.memory);
      !check.ok()) {
    throw std::logic_error(
        "internal error: the minimum-cost maximum matching's certificate fails: " + check.problem);
  }
  pairing.objective_units += cheapest.total_cost;
  return std::move(cheapest.matching);
}

// The open components by augmenting paths, proved maximum by a Tutte–Berge witness (and with
// `costs` the cheapest such matching). From here on the open components' own arrays are all that
// is read: each copy is freed as soon as the next is made, so that the search's state is not
// added to all of them.
void pair_open_components(PairableGraph& graph, std::vector<NodeId> open_nodes,
                          std::span<const Cost> costs, const QuadOptions& options,
                          TrianglePairing& pairing, QuadStats& stats, Stopwatch& clock) {
  Subgraph sub = induced(graph, std::move(open_nodes));
  free_storage(graph.node_edges);
  free_storage(graph.edge_ends);
  const CsrGraph open = csr_taking(static_cast<std::uint32_t>(sub.nodes.size()),
                                   std::move(sub.edge_ends), options.memory);
  if (costs.empty()) sub.edge_of = std::vector<EdgeId>();  // only the costs are looked up by it
  stats.dual_seconds += clock.lap();
  // The cardinality search runs in every case: its Tutte–Berge witness proves any matching of
  // its size maximum, the minimum-cost one included.
  MaximumMatchingResult result = maximum_matching(open, options.augment);
  // Its greedy pass is the initial pairing here; each augmenting path then paired two more.
  stats.matching.unpaired_after_initial += static_cast<std::uint32_t>(
      open.node_count() - 2 * (result.size - result.stats.augmenting_paths));
  stats.matching.augmenting_paths += result.stats.augmenting_paths;
  stats.matching.blossoms += result.stats.blossoms;
  stats.matching.nodes_labelled += result.stats.nodes_labelled;
  stats.matching.augment_seconds += clock.lap();
  if (!costs.empty()) {
    result.matching =
        cheapest_maximum_matching(open, sub.edge_of, costs, options, pairing, stats, clock);
  }
  if (MatchingCheck check = verify_maximum_matching(open, result.matching, result.tutte_set);
      !check.ok()) {
    throw std::logic_error(
        "internal error: the pairing of the open components is not proved maximum: " +
        check.message);
  }
  for (NodeId i = 0; i < sub.nodes.size(); ++i) {
    const EdgeId e = result.matching.mate_edge[i];
    if (e != kNoEdge) pairing.partner[sub.nodes[i]] = sub.nodes[open.other_end(e, i)];
  }
  for (NodeId i : result.tutte_set) pairing.tutte_set.push_back(sub.nodes[i]);
  stats.verify_seconds += clock.lap();
}

// Objective::quads: the cheapest matching of any size, each triangle left unpaired costing its
// price (triangle_prices: options.triangle_cost, or less for a model's own), over the whole
// pairable graph at once (closed and open components alike: the price makes every component's
// optimum a matching of any size); its certificate checked. Maximum is certified only where nothing
// is left: a perfect pairing is maximum.
void pair_at_least_cost(PairableGraph& graph, std::span<const Cost> costs,
                        const QuadOptions& options, TrianglePairing& pairing, QuadStats& stats,
                        Stopwatch& clock) {
  {
    const Components components = components_of(graph);
    stats.components = components.closed.size();
    for (std::uint8_t closed : components.closed) stats.closed_components += closed;
  }
  free_storage(graph.node_edges);
  const CsrGraph whole = csr_taking(graph.node_count, std::move(graph.edge_ends), options.memory);
  const std::pmr::vector<Cost> prices =
      triangle_prices(whole.node_count(), whole.edge_ends(), costs,
                      std::llround(options.triangle_cost * kDefaultCostScale), options.memory);
  stats.dual_seconds += clock.lap();
  MinCostMatchingResult result = min_cost_matching(
      whole, costs, prices, {.threads = options.threads, .memory = options.memory});
  add_min_cost_run(stats.matching, result.stats);
  clock.lap();
  if (CertificateCheck check = verify_min_cost_matching(
          whole.node_count(), whole.edge_ends(), costs, prices, result.matching, result.total,
          result.certificate, options.memory);
      !check.ok()) {
    throw std::logic_error("internal error: the least-cost pairing's certificate fails: " +
                           check.problem);
  }
  pairing.objective_units = result.total;
  pairing.partner.assign(graph.node_count, kNoNode);
  for (NodeId v = 0; v < whole.node_count(); ++v) {
    const EdgeId e = result.matching.mate_edge[v];
    if (e != kNoEdge) pairing.partner[v] = whole.other_end(e, v);
  }
  stats.maximum_certified = 2 * std::size_t{result.size} == graph.node_count;
  stats.verify_seconds += clock.lap();
}

// Whether lrs takes the whole mesh at once, from the graph's arrays: one closed, consistently
// oriented component of triangles without attributes.
bool lrs_takes_whole_mesh(const PairableGraph& graph, const PolygonMesh& mesh) {
  return graph.cubic && graph.inconsistent_edges == 0 && mesh.all_triangles() &&
         !mesh.attributes.has_corner_attributes() && !mesh.attributes.has_face_attributes() &&
         ComponentForest(graph.node_count, graph.edge_ends).root_count() == 1;
}

}  // namespace

}  // namespace petersen::quad_detail

namespace petersen {

TrianglePairing pair_triangles(PairableGraph& graph, const PolygonMesh& mesh,
                               std::pmr::vector<VertexId>* releasable_corners,
                               std::span<const double> degrees, const QuadOptions& options,
                               QuadStats& stats) {
  using namespace quad_detail;  // the strategies above
  Stopwatch clock;
  TrianglePairing pairing{.partner = std::pmr::vector<NodeId>(options.memory),
                          .lrs_quads = std::pmr::vector<LrsQuad>(options.memory)};
  // With lrs, auto matches the closed components lrs does not take.
  const Algorithm* chosen = std::get_if<Algorithm>(&options.algorithm);
  const Algorithm closed_algorithm = chosen ? *chosen : Algorithm::automatic;
  // lrs flips edges, making quads the threshold never judged: with one, auto does its work.
  bool use_lrs = !chosen && options.objective == Objective::pairs && !options.max_corner_deviation;
  const std::pmr::vector<Cost> costs = options.objective != Objective::pairs
                                           ? scale_costs(degrees, kDefaultCostScale, options.memory)
                                           : std::pmr::vector<Cost>(options.memory);
  stats.dual_seconds += clock.lap();
  stats.optimality_certified = options.objective != Objective::pairs;
  // With all_quad every triangle left is split into quads anyway: the quads objective then pairs
  // the cheapest maximum, as quality does, which leaves the fewest triangles to split.
  if (options.objective == Objective::quads && !options.all_quad) {
    pair_at_least_cost(graph, costs, options, pairing, stats, clock);
    return pairing;
  }
  stats.maximum_certified = true;

  if (use_lrs && lrs_takes_whole_mesh(graph, mesh)) {
    stats.components = stats.closed_components = 1;
    std::vector<VertexId> unused_local;  // the whole graph keeps the input's vertex ids
    if (pair_component_by_lrs(graph, mesh, {}, releasable_corners, options, unused_local, pairing,
                              stats, clock)) {
      return pairing;
    }
    use_lrs = false;  // a pinched vertex: the graph is made again for the default algorithm
  }
  if (graph.cubic && !use_lrs) {
    pair_closed_whole_mesh(graph, costs, options, closed_algorithm, pairing, stats, clock);
    return pairing;
  }

  pairing.partner.assign(graph.node_count, kNoNode);
  std::vector<NodeId> closed_nodes, open_nodes;
  {
    const Components components = components_of(graph);
    stats.components = components.closed.size();
    for (NodeId v = 0; v < graph.node_count; ++v) {
      (components.closed[components.of_node[v]] ? closed_nodes : open_nodes).push_back(v);
    }
    for (std::uint8_t closed : components.closed) stats.closed_components += closed;
    if (use_lrs && !closed_nodes.empty()) {
      closed_nodes = pair_closed_components_by_lrs(graph, mesh, components, closed_nodes, options,
                                                   pairing, stats, clock);
    }
  }
  if (!closed_nodes.empty()) {
    pair_closed_components(graph, std::move(closed_nodes), costs, options, closed_algorithm,
                           pairing, stats, clock);
  }
  if (!open_nodes.empty()) {
    pair_open_components(graph, std::move(open_nodes), costs, options, pairing, stats, clock);
  }
  return pairing;
}

}  // namespace petersen
