#include "petersen/matching/any_graph.hpp"

#include <optional>
#include <stdexcept>

#include "petersen/graph/connectivity.hpp"
#include "petersen/graph/csr_graph.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/matching/augment.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "petersen/matching/tutte_berge.hpp"
#include "petersen/matching/verify_min_cost.hpp"

namespace petersen {

namespace {

std::string edge_name(EdgeId e, const std::array<NodeId, 2>& ends) {
  return "edge " + std::to_string(e) + " (" + std::to_string(ends[0]) + ", " +
         std::to_string(ends[1]) + ")";
}

// What the note of match_any_graph says: of node `v` or edge `e`, `predicate`.
void set_note(AnyGraphMatching& result, NodeId v, EdgeId e, const std::array<NodeId, 2>& ends,
              std::string predicate) {
  result.note_node = v;
  result.note_edge = e;
  result.note = (e != kNoEdge ? edge_name(e, ends) : "node " + std::to_string(v)) + " " + predicate;
  result.note_predicate = std::move(predicate);
}

// Notes why the graph is not cubic (the first node of another degree, or the first loop); false
// when it is.
bool not_cubic(std::uint32_t node_count, const std::vector<std::array<NodeId, 2>>& edges,
               AnyGraphMatching& result) {
  std::vector<std::uint32_t> degree(node_count, 0);
  for (EdgeId e = 0; e < edges.size(); ++e) {
    auto [a, b] = edges[e];
    if (a == b) {
      set_note(result, kNoNode, e, edges[e], "is a loop");
      return true;
    }
    ++degree[a];
    ++degree[b];
  }
  for (NodeId v = 0; v < node_count; ++v) {
    if (degree[v] != 3) {
      set_note(result, v, kNoEdge, {}, "has degree " + std::to_string(degree[v]));
      return true;
    }
  }
  return false;
}

// PerfectMatchingOptions::algorithm on a cubic graph, verified; false (and the bridge in `note`) if
// it has one.
bool match_cubic(std::uint32_t node_count, const std::vector<std::array<NodeId, 2>>& edges,
                 const PerfectMatchingOptions& options, AnyGraphMatching& result) {
  const CubicGraph graph = CubicGraph::from_edges(node_count, edges);
  Stopwatch validate;
  if (const std::optional<EdgeId> bridge = find_bridge(graph)) {
    set_note(result, kNoNode, *bridge, edges[*bridge], "is a bridge");
    return false;
  }
  const double validate_seconds = validate.seconds();
  PerfectMatchingOptions without_check = options;
  without_check.validate = false;
  PerfectMatchingResult matched = perfect_matching(graph, without_check);
  if (MatchingCheck check = verify_perfect_matching(graph, matched.matching); !check.ok()) {
    throw std::logic_error("internal error: " + std::string(to_string(options.algorithm)) +
                           " returned a matching that is not perfect: " + check.message);
  }
  result.mate_edge.assign(matched.matching.mate_edge.begin(), matched.matching.mate_edge.end());
  result.stats = matched.stats;
  result.stats.validate_seconds = validate_seconds;
  result.size = node_count / 2;
  result.perfect = result.cubic_bridgeless = true;
  return true;
}

// A maximum matching of the loop-free part, with its witness, verified.
void match_general(std::uint32_t node_count, const std::vector<std::array<NodeId, 2>>& edges,
                   const PerfectMatchingOptions& options, AnyGraphMatching& result) {
  std::vector<std::array<NodeId, 2>> loop_free;
  std::vector<EdgeId> id_of;  // the input's id of each loop-free edge
  for (EdgeId e = 0; e < edges.size(); ++e) {
    if (edges[e][0] == edges[e][1]) continue;
    loop_free.push_back(edges[e]);
    id_of.push_back(e);
  }
  const CsrGraph graph = CsrGraph::from_edges(node_count, loop_free);
  Stopwatch clock;
  MaximumMatchingResult matched = maximum_matching(graph, options.augment);
  result.stats.augment_seconds = clock.seconds();
  result.stats.augmenting_paths = matched.stats.augmenting_paths;
  result.stats.blossoms = matched.stats.blossoms;
  result.stats.nodes_labelled = matched.stats.nodes_labelled;
  if (MatchingCheck check = verify_maximum_matching(graph, matched.matching, matched.tutte_set);
      !check.ok()) {
    throw std::logic_error("internal error: the maximum matching fails its check: " +
                           check.message);
  }
  result.mate_edge.assign(node_count, kNoEdge);
  for (NodeId v = 0; v < node_count; ++v) {
    if (matched.matching.mate_edge[v] != kNoEdge)
      result.mate_edge[v] = id_of[matched.matching.mate_edge[v]];
  }
  result.tutte_set.assign(matched.tutte_set.begin(), matched.tutte_set.end());
  result.size = matched.size;
  result.perfect = 2 * std::uint64_t{matched.size} == node_count;
}

// A certificate the independent verifier refused is a bug, never an answer.
void certified(const CertificateCheck& check) {
  if (!check.ok()) {
    throw std::logic_error("internal error: the minimum-cost matching's certificate fails: " +
                           check.problem);
  }
}

// GraphError naming the first edge with an endpoint out of range, or too many edges.
void check_edge_list(std::uint32_t node_count,
                     const std::vector<std::array<std::uint32_t, 2>>& edges) {
  if (edges.size() >= kNoEdge) throw GraphError("more than 2^32 - 1 edges");
  for (EdgeId e = 0; e < edges.size(); ++e) {
    if (edges[e][0] >= node_count || edges[e][1] >= node_count) {
      throw GraphError(edge_name(e, edges[e]) + " has an endpoint out of range (" +
                       std::to_string(node_count) + " nodes)");
    }
  }
}

}  // namespace

AnyGraphMatching match_any_graph(std::uint32_t node_count,
                                 const std::vector<std::array<std::uint32_t, 2>>& edges,
                                 const PerfectMatchingOptions& options) {
  check_edge_list(node_count, edges);
  AnyGraphMatching result;
  if (!not_cubic(node_count, edges, result) && match_cubic(node_count, edges, options, result)) {
    return result;
  }
  match_general(node_count, edges, options, result);
  return result;
}

AnyGraphCheapestMatching cheapest_matching_any_graph(
    std::uint32_t node_count, const std::vector<std::array<std::uint32_t, 2>>& edges,
    const std::vector<std::int64_t>& costs, std::uint32_t threads, CostObjective objective) {
  check_edge_list(node_count, edges);
  const MinCostOptions options{.threads = threads};
  if (costs.size() != edges.size()) {
    throw std::invalid_argument("min-cost matching: " + std::to_string(costs.size()) +
                                " costs for " + std::to_string(edges.size()) + " edges");
  }
  std::vector<std::array<NodeId, 2>> kept;
  std::vector<Cost> kept_costs;
  std::vector<EdgeId> input_edge;
  for (EdgeId e = 0; e < edges.size(); ++e) {
    if (edges[e][0] == edges[e][1]) continue;
    kept.push_back(edges[e]);
    kept_costs.push_back(costs[e]);
    input_edge.push_back(e);
  }
  const CsrGraph graph = CsrGraph::from_edges(node_count, kept);
  AnyGraphCheapestMatching result;
  result.mate_edge.assign(node_count, kNoEdge);
  Matching matching;
  if (objective == CostObjective::maximum) {
    CheapestMaximumResult cheapest = cheapest_maximum_matching(graph, kept_costs, options);
    matching = std::move(cheapest.matching);
    result.size = cheapest.size;
    result.total_cost = cheapest.total_cost;
  } else if (objective == CostObjective::any_size) {
    const std::vector<Cost> zero = {0};
    MinCostMatchingResult cheapest = min_cost_matching(graph, kept_costs, zero, options);
    certified(verify_min_cost_matching(node_count, graph.edge_ends(), kept_costs, zero,
                                       cheapest.matching, cheapest.total, cheapest.certificate));
    matching = std::move(cheapest.matching);
    result.size = cheapest.size;
    result.total_cost = cheapest.total;
  } else {
    AnyGraphMatching maximum = match_any_graph(node_count, edges);  // verified by its witness
    if (!maximum.perfect) {
      result.mate_edge = std::move(maximum.mate_edge);
      result.size = maximum.size;
      result.tutte_set = std::move(maximum.tutte_set);
      return result;
    }
    MinCostResult cheapest = min_cost_perfect_matching(graph, kept_costs, options);
    certified(verify_min_cost_perfect_matching(node_count, graph.edge_ends(), kept_costs,
                                               cheapest.matching, cheapest.total_cost,
                                               cheapest.certificate));
    matching = std::move(cheapest.matching);
    result.size = node_count / 2;
    result.total_cost = cheapest.total_cost;
  }
  for (NodeId v = 0; v < node_count; ++v) {
    const EdgeId e = matching.mate_edge[v];
    if (e != kNoEdge) result.mate_edge[v] = input_edge[e];
  }
  result.perfect = 2 * std::uint64_t{result.size} == node_count;
  return result;
}

}  // namespace petersen
