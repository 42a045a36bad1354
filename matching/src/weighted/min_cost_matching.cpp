#include "petersen/matching/min_cost_matching.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "blossom_solver.hpp"
#include "breadth_first_order.hpp"
#include "doubled_order.hpp"
#include "petersen/graph/connectivity.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/matching/augment.hpp"
#include "petersen/matching/tutte_berge.hpp"
#include "petersen/matching/verify_min_cost.hpp"

namespace petersen {

namespace {

void check_costs(std::span<const Cost> costs, std::uint32_t edge_count, Cost limit) {
  if (costs.size() != edge_count) {
    throw std::invalid_argument("min-cost matching: " + std::to_string(costs.size()) +
                                " costs for " + std::to_string(edge_count) + " edges");
  }
  for (std::size_t e = 0; e < costs.size(); ++e) {
    if (costs[e] > limit || costs[e] < -limit) {
      throw std::invalid_argument("min-cost matching: cost " + std::to_string(costs[e]) +
                                  " of edge " + std::to_string(e) + " is out of range");
    }
  }
}

using weighted_detail::WideCost;

// A total cost as the results hold it: a total past 64 bits is an error, not a wrapped number.
Cost fitting_total(WideCost total) {
  if (total > INT64_MAX || total < INT64_MIN) {
    throw std::overflow_error(
        "min-cost matching: the total cost passes 2^63 (many edges of costs near 2^40); "
        "scale the costs down");
  }
  return static_cast<Cost>(total);
}

// The solver runs on the breadth-first renumbering (breadth_first_order.hpp says why: 4x fewer
// cache misses per scanned neighbour on subdivided meshes); it writes the matching and the node
// duals in the input's ids, the odd sets need no mapping. Returns the total cost exact, beside
// the result, whose total_cost it leaves to the caller. `init` runs from before the rows were
// made: the start's time includes them.
WideCost solve_on(const weighted_detail::BreadthFirstAdjacency& order,
                  const MinCostOptions& options, Stopwatch init, MinCostResult& result) {
  weighted_detail::BlossomSolver solver(order, result.stats, options.memory);
  if (options.greedy_start) solver.greedy_start();
  if (options.short_searches) {
    solver.short_searches(options.threads);
  } else if (options.greedy_start) {
    solver.augment_tight();
  }
  result.stats.init_seconds = init.seconds();
  result.stats.free_after_init = solver.free_nodes();
  Stopwatch searches;
  solver.run();
  result.stats.search_seconds = searches.seconds();
  Stopwatch certificate;
  const WideCost total = solver.write_result(order.new_node, result);
  result.stats.certificate_seconds = certificate.seconds();
  return total;
}

template <class Graph>
WideCost solve(const Graph& graph, std::span<const Cost> costs, const MinCostOptions& options,
               MinCostResult& result) {
  Stopwatch init;
  return solve_on(weighted_detail::breadth_first_adjacency(graph, costs, options.memory), options,
                  init, result);
}

template <class Graph>
MinCostResult solve_perfect(const Graph& graph, std::span<const Cost> costs,
                            const MinCostOptions& options) {
  check_costs(costs, graph.edge_count(), kMaxCost);
  // The matching is made on options.memory (write_result), so that moving it out copies nothing.
  MinCostResult result{.matching = Matching(0, options.memory)};
  result.total_cost = fitting_total(solve(graph, costs, options, result));
  return result;
}

// The first copy of an optimal perfect matching of the doubled graph (min_cost_matching.hpp).
struct FirstCopy {
  Matching matching;
  std::uint32_t size = 0;
  WideCost matched_cost = 0;
  MatchingCertificate certificate = {};
  MinCostStats stats = {};
};

// The reduction of min_cost_matching and min_cost_maximum_matching: H = G ∪ G' plus v–v' (edge
// 2m + v) at pair_costs[v], solved as a perfect matching; H always has one (every v–v').
// Returns G's part. O(n + m) besides the solve of 2n nodes and 2m + n edges.
FirstCopy solve_doubled(const CsrGraph& graph, std::span<const Cost> costs,
                        std::span<const Cost> pair_costs, const MinCostOptions& options) {
  const std::uint32_t n = graph.node_count(), m = graph.edge_count();
  if (n > 0x7FFFFFFFu || std::uint64_t{2} * m + n > 0xFFFFFFFEu) {
    throw std::invalid_argument("min-cost matching: the doubled graph needs 32-bit ids");
  }
  // The doubled graph's own total (up to n edges of cost K) is not needed: the first copy's is.
  // Its rows are made from G's (doubled_order.hpp); the matching and the certificate come back in
  // its ids (v, n + v; edges e, m + e, 2m + v).
  Stopwatch init;
  MinCostResult inner{.matching = Matching(0, options.memory)};
  solve_on(
      weighted_detail::doubled_breadth_first_adjacency(graph, costs, pair_costs, options.memory),
      options, init, inner);
  FirstCopy first{.matching = Matching(n, options.memory)};
  // Both copies are optimal halves of equal objective (else the cheaper one, doubled, would
  // beat the optimum), so the first copy is optimal.
  for (NodeId v = 0; v < n; ++v) {
    const EdgeId e = inner.matching.mate_edge[v];
    if (e < m) {
      first.matching.mate_edge[v] = e;
      if (graph.endpoints(e)[0] == v) {
        ++first.size;
        first.matched_cost += costs[e];
      }
    }
  }
  first.certificate = std::move(inner.certificate);
  first.stats = inner.stats;
  return first;
}

// Every node of degree 3 (a CsrGraph has no loops) and no bridge.
bool cubic_bridgeless(const CsrGraph& graph) {
  const std::uint32_t n = graph.node_count();
  for (NodeId v = 0; v < n; ++v) {
    if (graph.degree(v) != 3) return false;
  }
  std::pmr::vector<EdgeId> node_edges(3 * std::size_t{n});
  for (NodeId v = 0; v < n; ++v) {
    const std::span<const EdgeId> edges = graph.incident_edges(v);
    std::copy(edges.begin(), edges.end(), node_edges.begin() + 3 * std::size_t{v});
  }
  const std::span<const NodeId> ends = graph.edge_ends();
  std::pmr::vector<NodeId> edge_ends(ends.size());
  std::copy(ends.begin(), ends.end(), edge_ends.begin());
  // Consistent by the CsrGraph's construction: each edge listed once at each of its two ends.
  return !find_bridge(
      CubicGraph::from_valid_incidence(std::move(node_edges), std::move(edge_ends)));
}

}  // namespace

std::pmr::vector<Cost> scale_costs(std::span<const double> costs, double scale,
                                   std::pmr::memory_resource* memory) {
  std::pmr::vector<Cost> scaled(costs.size(), memory);
  for (std::size_t e = 0; e < costs.size(); ++e) {
    const double value = std::round(costs[e] * scale);
    if (!std::isfinite(value) || std::abs(value) > static_cast<double>(kMaxCost)) {
      throw std::invalid_argument("scale_costs: cost " + std::to_string(costs[e]) + " at index " +
                                  std::to_string(e) + " is not finite or exceeds 2^40 scaled");
    }
    scaled[e] = static_cast<Cost>(value);
  }
  return scaled;
}

MinCostResult min_cost_perfect_matching(const CubicGraph& graph, std::span<const Cost> costs,
                                        const MinCostOptions& options) {
  return solve_perfect(graph, costs, options);
}

MinCostResult min_cost_perfect_matching(const CsrGraph& graph, std::span<const Cost> costs,
                                        const MinCostOptions& options) {
  return solve_perfect(graph, costs, options);
}

MinCostMaximumResult min_cost_maximum_matching(const CsrGraph& graph, std::span<const Cost> costs,
                                               const MinCostOptions& options) {
  check_costs(costs, graph.edge_count(), kMaxCost);
  const std::uint32_t n = graph.node_count(), m = graph.edge_count();
  Cost most = 0, least = 0;
  for (Cost c : costs) {
    most = std::max(most, c);
    least = std::min(least, c);
  }
  // K = 1 + ν̄·(max(0, most) − min(0, least)) exceeds the cost difference of any two matchings
  // (see the header), ν̄ = min(half the nodes with an edge, the edges) bounding their size: a
  // graph of a few edges among many isolated nodes (found by fuzz/match_fuzzer.cpp) keeps a small
  // K, where floor(n/2) refused it. K is kept below 2^52 so that the doubled graph's duals (about
  // K) and their doubling stay far inside 64 bits; the product is taken in 128 bits (ν̄ < 2^31,
  // most − least <= 2^41).
  std::uint32_t touched = 0;
  for (NodeId v = 0; v < n; ++v) touched += graph.degree(v) > 0;
  const std::uint32_t largest = std::min(touched / 2, m);
  const WideCost k = 1 + WideCost{largest} * (WideCost{most} - WideCost{least});
  if (k >= WideCost{1} << 52) {
    throw std::invalid_argument(
        "min_cost_maximum_matching: the unmatched-node cost exceeds 2^52 (costs too far apart "
        "for this many matchable edges)");
  }
  const Cost unmatched_cost = static_cast<Cost>(k);
  const std::vector<Cost> pair_costs(n, unmatched_cost);
  FirstCopy first = solve_doubled(graph, costs, pair_costs, options);
  MinCostMaximumResult result{.matching = std::move(first.matching)};
  result.size = first.size;
  result.total_cost = fitting_total(first.matched_cost);
  result.unmatched_cost = unmatched_cost;
  result.certificate = std::move(first.certificate);
  result.stats = first.stats;
  return result;
}

MinCostMatchingResult min_cost_matching(const CsrGraph& graph, std::span<const Cost> costs,
                                        std::span<const Cost> unmatched_cost,
                                        const MinCostOptions& options) {
  check_costs(costs, graph.edge_count(), kMaxCost);
  const std::uint32_t n = graph.node_count();
  if (unmatched_cost.size() != n && unmatched_cost.size() != 1) {
    throw std::invalid_argument("min_cost_matching: " + std::to_string(unmatched_cost.size()) +
                                " unmatched-node prices for " + std::to_string(n) +
                                " nodes (one per node, or one for all)");
  }
  auto price = [&](NodeId v) { return unmatched_cost[unmatched_cost.size() == 1 ? 0 : v]; };
  std::vector<Cost> pair_costs(n);
  for (NodeId v = 0; v < n; ++v) {
    if (price(v) > kMaxCost || price(v) < -kMaxCost) {
      throw std::invalid_argument("min_cost_matching: unmatched-node price " +
                                  std::to_string(price(v)) + " of node " + std::to_string(v) +
                                  " is out of range");
    }
    pair_costs[v] = 2 * price(v);
  }
  FirstCopy first = solve_doubled(graph, costs, pair_costs, options);
  WideCost total = first.matched_cost;
  for (NodeId v = 0; v < n; ++v) {
    if (!first.matching.is_matched(v)) total += price(v);
  }
  MinCostMatchingResult result{.matching = std::move(first.matching)};
  result.size = first.size;
  result.matched_cost = fitting_total(first.matched_cost);
  result.total = fitting_total(total);
  result.certificate = std::move(first.certificate);
  result.stats = first.stats;
  return result;
}

CheapestMaximumResult cheapest_maximum_matching(const CsrGraph& graph, std::span<const Cost> costs,
                                                const MinCostOptions& options) {
  check_costs(costs, graph.edge_count(), kMaxCost);
  const std::uint32_t n = graph.node_count();
  // A cubic bridgeless graph has a perfect matching (Petersen's theorem): no maximum matching
  // needs finding first (`petersen match --objective cost` on rocker-arm-sub3's dual with its
  // quality costs: 1.51-1.63 s against 1.79-1.92 with it).
  std::optional<MaximumMatchingResult> maximum;
  if (!cubic_bridgeless(graph)) {
    maximum = maximum_matching(graph);
    if (const MatchingCheck check =
            verify_maximum_matching(graph, maximum->matching, maximum->tutte_set);
        !check.ok()) {
      throw std::logic_error("internal error: the maximum matching fails its witness: " +
                             check.message);
    }
  }
  CheapestMaximumResult result;
  result.perfect = !maximum || 2 * std::uint64_t{maximum->size} == n;
  CertificateCheck check;
  if (result.perfect) {
    MinCostResult cheapest = min_cost_perfect_matching(graph, costs, options);
    check = verify_min_cost_perfect_matching(n, graph.edge_ends(), costs, cheapest.matching,
                                             cheapest.total_cost, cheapest.certificate);
    result.matching = std::move(cheapest.matching);
    result.size = n / 2;  // the verifier has checked it perfect
    result.total_cost = cheapest.total_cost;
    result.stats = cheapest.stats;
  } else {
    MinCostMaximumResult cheapest = min_cost_maximum_matching(graph, costs, options);
    check = verify_min_cost_maximum_matching(n, graph.edge_ends(), costs, cheapest.matching,
                                             cheapest.total_cost, cheapest.unmatched_cost,
                                             cheapest.certificate);
    result.matching = std::move(cheapest.matching);
    result.size = cheapest.size;
    result.total_cost = cheapest.total_cost;
    result.stats = cheapest.stats;
  }
  if (!check.ok()) {
    throw std::logic_error("internal error: the minimum-cost matching's certificate fails: " +
                           check.problem);
  }
  if (maximum && result.size != maximum->size) {
    throw std::logic_error("internal error: the minimum-cost matching has " +
                           std::to_string(result.size) + " edges, the maximum " +
                           std::to_string(maximum->size));
  }
  return result;
}

}  // namespace petersen
