// Exact minimum-cost matching: every answer's certificate goes through the
// independent verifier, and its cost is compared with brute force on tiny graphs and with
// LEMON's MaxWeightedPerfectMatching on generated cubic bridgeless and general graphs; the
// verifier rejects perturbed answers.

#include "petersen/matching/min_cost_matching.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "peers.hpp"
#include "petersen/dualize/dual.hpp"
#include "petersen/dualize/pairable_graph.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/graph/csr_graph.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "petersen/matching/real_costs.hpp"
#include "petersen/matching/verify_min_cost.hpp"
#include "petersen/testing/arbitrary.hpp"
#include "shared_meshes.hpp"

namespace petersen {
namespace {

// A cubic bridgeless multigraph drawn by petersen::testing, and its edges as a list.
CubicGraph any_cubic_bridgeless() {
  return *rc::gen::arbitrary<CubicGraph>();
}
std::vector<std::array<std::uint32_t, 2>> edge_list(const CubicGraph& g) {
  std::vector<std::array<std::uint32_t, 2>> edges(g.edge_count());
  for (EdgeId e = 0; e < g.edge_count(); ++e) edges[e] = g.endpoints(e);
  return edges;
}
using Edges = std::vector<std::array<std::uint32_t, 2>>;

// The cheapest matching of the nodes not yet covered, among those of the most edges: returns
// (edges matched, cost); by recursion over the lowest free node (depth <= n/2, tiny graphs).
struct Best {
  int size;
  Cost cost;
};
Best brute_force(std::uint32_t n, const Edges& edges, std::span<const Cost> costs,
                 std::vector<char>& used, bool perfect_only) {
  NodeId v = 0;
  while (v < n && used[v]) ++v;
  if (v == n) return {0, 0};
  std::optional<Best> best;
  auto consider = [&](Best b) {
    if (b.size < 0) return;
    if (!best || b.size > best->size || (b.size == best->size && b.cost < best->cost)) best = b;
  };
  used[v] = 1;
  if (!perfect_only) consider(brute_force(n, edges, costs, used, false));  // v stays free
  for (EdgeId e = 0; e < edges.size(); ++e) {
    const auto [a, b] = edges[e];
    if (a != v && b != v) continue;
    const NodeId w = a == v ? b : a;
    if (used[w]) continue;
    used[w] = 1;
    Best rest = brute_force(n, edges, costs, used, perfect_only);
    used[w] = 0;
    if (rest.size >= 0) consider({rest.size + 1, rest.cost + costs[e]});
  }
  used[v] = 0;
  return best ? *best : Best{-1, 0};  // -1: no perfect matching of the rest
}

// Costs over all of low..high at every size (RapidCheck's inRange favours the low end at small
// sizes).
std::vector<Cost> random_costs(std::size_t m, Cost low, Cost high) {
  return *rc::gen::container<std::vector<Cost>>(
      m, rc::gen::resize(100, rc::gen::inRange<Cost>(low, high + 1)));
}

// Ends drawn over all of 0..n-1 at every size (as random_costs), else most tiny graphs would
// draw loops only.
Edges random_edges(std::uint32_t n, std::uint32_t m) {
  Edges edges;
  const auto end = rc::gen::resize(100, rc::gen::inRange<std::uint32_t>(0, n));
  for (std::uint32_t i = 0; i < m; ++i) {
    const auto a = *end;
    const auto b = *end;
    if (a != b) edges.push_back({a, b});
  }
  return edges;
}

// random_edges, and half the time a perfect matching besides (so that most graphs with an even
// number of nodes have one).
Edges random_edges_often_perfect(std::uint32_t n, std::uint32_t m) {
  Edges edges = random_edges(n, m);
  if (*rc::gen::arbitrary<bool>()) {
    for (NodeId v = 0; v + 1 < n; v += 2) edges.push_back({v, v + 1});
  }
  return edges;
}

std::span<const NodeId> ends_of(const CsrGraph& g) {
  return g.edge_ends();
}

RC_GTEST_PROP(MinCostPerfect, TinyGraphsMatchBruteForce, ()) {
  const auto n = 2 * *rc::gen::inRange<std::uint32_t>(1, 6);
  const Edges edges = random_edges(n, *rc::gen::inRange<std::uint32_t>(0, 3 * n));
  const std::vector<Cost> costs = random_costs(edges.size(), -30, 60);
  const CsrGraph g = CsrGraph::from_edges(n, edges);
  std::vector<char> used(n, 0);
  const Best best = brute_force(n, edges, costs, used, true);
  if (best.size < 0) {
    RC_ASSERT_THROWS_AS(min_cost_perfect_matching(g, costs), GraphError);
    return;
  }
  const MinCostResult r = min_cost_perfect_matching(g, costs);
  RC_ASSERT(r.total_cost == best.cost);
  const CertificateCheck check = verify_min_cost_perfect_matching(n, ends_of(g), costs, r.matching,
                                                                  r.total_cost, r.certificate);
  RC_ASSERT(check.ok());
}

RC_GTEST_PROP(MinCostPerfect, CubicBridgelessEqualsLemonAndIsCertified, ()) {
  const CubicGraph g = any_cubic_bridgeless();
  const Edges edges = edge_list(g);
  const Cost high = *rc::gen::element<Cost>(1, 10, 1000, 1 << 24);
  const std::vector<Cost> costs = random_costs(edges.size(), 0, high);
  const bool greedy = *rc::gen::arbitrary<bool>();
  const bool short_searches = *rc::gen::arbitrary<bool>();
  const MinCostResult r = min_cost_perfect_matching(
      g, costs, {.greedy_start = greedy, .short_searches = short_searches});
  RC_ASSERT(verify_perfect_matching(g, r.matching).ok());
  const auto lemon = testing::lemon_min_cost_perfect(g.node_count(), edges, costs);
  RC_ASSERT(lemon.has_value());
  RC_ASSERT(r.total_cost == *lemon);
  const CertificateCheck check = verify_min_cost_perfect_matching(
      g.node_count(), g.edge_ends(), costs, r.matching, r.total_cost, r.certificate);
  RC_ASSERT(check.ok());
  RC_TAG(r.certificate.set_count() > 0 ? "with odd sets" : "no odd sets");
}

RC_GTEST_PROP(MinCostPerfect, GeneralGraphsEqualLemonAndAreCertified, ()) {
  // A random perfect matching plus random edges, so most graphs with an even number of nodes
  // have one; odd ones have none; negative costs too, with and without the greedy start.
  const auto n = *rc::gen::inRange<std::uint32_t>(1, 120);
  const Edges edges = random_edges_often_perfect(n, *rc::gen::inRange<std::uint32_t>(0, 4 * n));
  const std::vector<Cost> costs = random_costs(edges.size(), -100, 100);
  const CsrGraph g = CsrGraph::from_edges(n, edges);
  const MinCostOptions options{.greedy_start = *rc::gen::arbitrary<bool>(),
                               .short_searches = *rc::gen::arbitrary<bool>(),
                               .threads = *rc::gen::inRange<std::uint32_t>(1, 3)};
  const auto lemon = testing::lemon_min_cost_perfect(n, edges, costs);
  if (!lemon) {
    RC_ASSERT_THROWS_AS(min_cost_perfect_matching(g, costs, options), GraphError);
    return;
  }
  const MinCostResult r = min_cost_perfect_matching(g, costs, options);
  RC_ASSERT(r.total_cost == *lemon);
  const CertificateCheck check = verify_min_cost_perfect_matching(n, ends_of(g), costs, r.matching,
                                                                  r.total_cost, r.certificate);
  RC_ASSERT(check.ok());
  // The short searches' work is capped: 16 labels a node, and one search beyond in each of
  // their three rounds (the graph's two halves, then the whole), which labels each node once.
  RC_ASSERT(r.stats.short_labels <= std::uint64_t{16} * n + 3 * n);
  RC_TAG(r.certificate.set_count() > 0 ? "with odd sets" : "no odd sets");
  RC_TAG(r.stats.short_half_cycles > 0 ? "half cycles closed" : "no half cycle");
}

// The short searches run in two halves of the graph on separate threads; the halves share no
// node, so the threads change nothing: the same matching, duals and counters.
RC_GTEST_PROP(MinCostPerfect, ThreadsChangeNothing, ()) {
  const CubicGraph g = any_cubic_bridgeless();
  const std::vector<Cost> costs = random_costs(g.edge_count(), 0, 1000);
  const MinCostResult one = min_cost_perfect_matching(g, costs, {.threads = 1});
  const MinCostResult two = min_cost_perfect_matching(g, costs, {.threads = 2});
  RC_ASSERT(one.matching.mate_edge == two.matching.mate_edge);
  RC_ASSERT(one.certificate.node_dual == two.certificate.node_dual);
  RC_ASSERT(one.certificate.set_dual == two.certificate.set_dual);
  RC_ASSERT(one.stats.short_labels == two.stats.short_labels);
  RC_ASSERT(one.stats.nodes_labelled == two.stats.nodes_labelled);
  RC_ASSERT(one.stats.short_half_cycles == two.stats.short_half_cycles);
  RC_TAG(one.stats.short_augmentations > 0 ? "short searches augmented" : "none augmented");
  RC_TAG(one.stats.short_half_cycles > 0 ? "half cycles closed" : "no half cycle");
}

RC_GTEST_PROP(MinCostMaximum, TinyGraphsMatchBruteForce, ()) {
  const auto n = *rc::gen::inRange<std::uint32_t>(1, 11);
  const Edges edges = random_edges(n, *rc::gen::inRange<std::uint32_t>(0, 2 * n));
  const std::vector<Cost> costs = random_costs(edges.size(), -20, 40);
  const CsrGraph g = CsrGraph::from_edges(n, edges);
  std::vector<char> used(n, 0);
  const Best best = brute_force(n, edges, costs, used, false);
  const MinCostMaximumResult r = min_cost_maximum_matching(g, costs);
  RC_ASSERT(static_cast<int>(r.size) == best.size);
  RC_ASSERT(r.total_cost == best.cost);
  const CertificateCheck check = verify_min_cost_maximum_matching(
      n, ends_of(g), costs, r.matching, r.total_cost, r.unmatched_cost, r.certificate);
  RC_ASSERT(check.ok());
}

RC_GTEST_PROP(MinCostMaximum, SizeEqualsLemonMaximumAndIsCertified, ()) {
  const auto n = *rc::gen::inRange<std::uint32_t>(1, 120);
  const Edges edges = random_edges(n, *rc::gen::inRange<std::uint32_t>(0, 3 * n));
  const std::vector<Cost> costs = random_costs(edges.size(), 0, 1 << 20);
  const CsrGraph g = CsrGraph::from_edges(n, edges);
  const MinCostMaximumResult r = min_cost_maximum_matching(g, costs);
  RC_ASSERT(r.size == testing::lemon_matching_size(n, edges));
  const CertificateCheck check = verify_min_cost_maximum_matching(
      n, ends_of(g), costs, r.matching, r.total_cost, r.unmatched_cost, r.certificate);
  RC_ASSERT(check.ok());
  // A perfect matching, when there is one, costs what LEMON's weighted optimum costs.
  if (2 * r.size == n) RC_ASSERT(testing::lemon_min_cost_perfect(n, edges, costs) == r.total_cost);
}

// A case from fuzz/match_fuzzer.cpp. The unmatched-node cost K bounds a matching's size by the
// edges and the nodes they touch, not by n: one edge among 60,000 isolated nodes, at a cost near
// 2^40, must not be refused (a bound by n takes K past 2^52). And the doubled graph's own total,
// K for each of the thousands of free nodes, passes 2^63, so it must not be summed in 64 bits.
TEST(MinCostMaximum, FewEdgesAmongManyFreeNodesAndFarApartCosts) {
  {
    const std::uint32_t n = 60000;
    const Edges edges = {{1, 6}};
    const std::vector<Cost> costs = {(Cost{1} << 40) - 1};
    const CsrGraph g = CsrGraph::from_edges(n, edges);
    const MinCostMaximumResult r = min_cost_maximum_matching(g, costs);
    EXPECT_EQ(r.size, 1u);
    EXPECT_EQ(r.total_cost, costs[0]);
    EXPECT_TRUE(verify_min_cost_maximum_matching(n, ends_of(g), costs, r.matching, r.total_cost,
                                                 r.unmatched_cost, r.certificate)
                    .ok());
  }
  {
    // 2,000 disjoint edges at +-2^40 (K just under 2^52) and 3,000 isolated nodes.
    const std::uint32_t n = 7000;
    Edges edges;
    std::vector<Cost> costs;
    for (NodeId i = 0; i < 2000; ++i) {
      edges.push_back({2 * i, 2 * i + 1});
      costs.push_back(i % 2 == 0 ? Cost{1} << 40 : -(Cost{1} << 40));
    }
    const CsrGraph g = CsrGraph::from_edges(n, edges);
    const MinCostMaximumResult r = min_cost_maximum_matching(g, costs);
    EXPECT_EQ(r.size, 2000u);
    EXPECT_EQ(r.total_cost, 0);
    EXPECT_GT(r.unmatched_cost, Cost{1} << 51);
    EXPECT_TRUE(verify_min_cost_maximum_matching(n, ends_of(g), costs, r.matching, r.total_cost,
                                                 r.unmatched_cost, r.certificate)
                    .ok());
  }
}

// ---- matchings of any size with a price per unmatched node

// The least cost(M) + Σ price over the nodes M leaves free, among matchings of the nodes not
// yet used; by recursion over the lowest free node (depth <= n, tiny graphs).
Cost brute_force_priced(std::uint32_t n, const Edges& edges, std::span<const Cost> costs,
                        std::span<const Cost> prices, std::vector<char>& used) {
  NodeId v = 0;
  while (v < n && used[v]) ++v;
  if (v == n) return 0;
  used[v] = 1;
  Cost best = prices[v] + brute_force_priced(n, edges, costs, prices, used);
  for (EdgeId e = 0; e < edges.size(); ++e) {
    const auto [a, b] = edges[e];
    const NodeId w = a == v ? b : a;
    if ((a != v && b != v) || used[w]) continue;
    used[w] = 1;
    best = std::min(best, costs[e] + brute_force_priced(n, edges, costs, prices, used));
    used[w] = 0;
  }
  used[v] = 0;
  return best;
}

// Any prices (one per node, or one for all; of either sign), any costs: the optimum of brute
// force, the total and the size as the matching says, and the certificate accepted.
RC_GTEST_PROP(MinCostAnySize, TinyGraphsMatchBruteForce, ()) {
  const auto n = *rc::gen::resize(100, rc::gen::inRange<std::uint32_t>(1, 11));
  const Edges edges =
      random_edges(n, *rc::gen::resize(100, rc::gen::inRange<std::uint32_t>(0, 2 * n)));
  const std::vector<Cost> costs = random_costs(edges.size(), -30, 40);
  const bool one_price = *rc::gen::arbitrary<bool>();
  const std::vector<Cost> prices = random_costs(one_price ? 1 : n, -10, 25);
  const std::vector<Cost> per_node = one_price ? std::vector<Cost>(n, prices[0]) : prices;
  const CsrGraph g = CsrGraph::from_edges(n, edges);
  std::vector<char> used(n, 0);
  const Cost best = brute_force_priced(n, edges, costs, per_node, used);
  const MinCostMatchingResult r = min_cost_matching(g, costs, prices);
  RC_ASSERT(r.total == best);
  RC_ASSERT(verify_matching(g, r.matching).ok());
  Cost matched = 0, unmatched = 0;
  std::uint32_t size = 0;
  for (NodeId v = 0; v < n; ++v) {
    const EdgeId e = r.matching.mate_edge[v];
    if (e == kNoEdge) unmatched += per_node[v];
    if (e != kNoEdge && g.endpoints(e)[0] == v) {
      matched += costs[e];
      ++size;
    }
  }
  RC_ASSERT(r.matched_cost == matched);
  RC_ASSERT(r.total == matched + unmatched);
  RC_ASSERT(r.size == size);
  const CertificateCheck check =
      verify_min_cost_matching(n, ends_of(g), costs, prices, r.matching, r.total, r.certificate);
  RC_ASSERT(check.ok());
  // The same certificate does not prove a smaller total, nor the answer under other prices.
  RC_ASSERT(!verify_min_cost_matching(n, ends_of(g), costs, prices, r.matching, r.total - 1,
                                      r.certificate)
                 .ok());
  RC_TAG(size == 0 ? "empty" : 2 * size == n ? "perfect" : "partial");
}

// A price above every matching's cost difference makes the fewest free nodes cheapest: the
// minimum-cost maximum matching's cost, on graphs too large for brute force.
RC_GTEST_PROP(MinCostAnySize, LargePriceGivesTheMinimumCostMaximum, ()) {
  const auto n = *rc::gen::inRange<std::uint32_t>(1, 120);
  const Edges edges = random_edges(n, *rc::gen::inRange<std::uint32_t>(0, 3 * n));
  const std::vector<Cost> costs = random_costs(edges.size(), -1000, 1000);
  const CsrGraph g = CsrGraph::from_edges(n, edges);
  const MinCostMaximumResult maximum = min_cost_maximum_matching(g, costs);
  const std::vector<Cost> price = {maximum.unmatched_cost};
  const MinCostMatchingResult r = min_cost_matching(g, costs, price, {.threads = 2});
  RC_ASSERT(r.size == maximum.size);
  RC_ASSERT(r.matched_cost == maximum.total_cost);
  RC_ASSERT(
      verify_min_cost_matching(n, ends_of(g), costs, price, r.matching, r.total, r.certificate)
          .ok());
}

// Maximum weight of any size (costs = −weight, price 0) on a path 0–1–2–3 of weights 2, 3, 2:
// the two end edges (4) beat the middle one (3), and a negative weight is never taken.
TEST(MinCostAnySize, MaximumWeightIsNegatedCostsAtPriceZero) {
  const Edges edges = {{0, 1}, {1, 2}, {2, 3}, {3, 4}};
  const std::vector<Cost> costs = {-2, -3, -2, 5};
  const std::vector<Cost> zero = {0};
  const CsrGraph g = CsrGraph::from_edges(5, edges);
  const MinCostMatchingResult r = min_cost_matching(g, costs, zero);
  std::vector<char> used(5, 0);
  EXPECT_EQ(r.total, brute_force_priced(5, edges, costs, std::vector<Cost>(5, 0), used));
  EXPECT_EQ(r.size, 2u);
  EXPECT_EQ(r.matching.mate_edge[4], kNoEdge);
  const CertificateCheck check =
      verify_min_cost_matching(5, ends_of(g), costs, zero, r.matching, r.total, r.certificate);
  EXPECT_TRUE(check.ok()) << check.problem;
}

TEST(MinCostAnySize, RejectsBadPrices) {
  const CsrGraph g = CsrGraph::from_edges(3, Edges{{0, 1}, {1, 2}});
  const std::vector<Cost> costs = {1, 2};
  EXPECT_THROW(min_cost_matching(g, costs, std::vector<Cost>{1, 2}), std::invalid_argument);
  EXPECT_THROW(min_cost_matching(g, costs, std::vector<Cost>{}), std::invalid_argument);
  EXPECT_THROW(min_cost_matching(g, costs, std::vector<Cost>{kMaxCost + 1}), std::invalid_argument);
  const CsrGraph empty = CsrGraph::from_edges(0, Edges{});
  const MinCostMatchingResult r = min_cost_matching(empty, {}, std::vector<Cost>{7});
  EXPECT_EQ(r.total, 0);
  EXPECT_TRUE(
      verify_min_cost_matching(0, {}, {}, std::vector<Cost>{7}, r.matching, r.total, r.certificate)
          .ok());
}

// cheapest_maximum_matching picks the perfect solver or the maximum one; either way the answer
// is as large as LEMON's maximum and as cheap as the maximum solver's.
RC_GTEST_PROP(CheapestMaximum, EqualsTheMaximumSolversOptimum, ()) {
  const auto n = *rc::gen::inRange<std::uint32_t>(1, 80);
  const Edges edges = random_edges_often_perfect(n, *rc::gen::inRange<std::uint32_t>(0, 3 * n));
  const std::vector<Cost> costs = random_costs(edges.size(), -50, 1000);
  const CsrGraph g = CsrGraph::from_edges(n, edges);
  const CheapestMaximumResult r = cheapest_maximum_matching(g, costs);
  RC_ASSERT(r.size == testing::lemon_matching_size(n, edges));
  RC_ASSERT(r.perfect == (2 * r.size == n));
  RC_ASSERT(r.total_cost == min_cost_maximum_matching(g, costs).total_cost);
  Cost written = 0;
  for (NodeId v = 0; v < n; ++v) {
    const EdgeId e = r.matching.mate_edge[v];
    if (e != kNoEdge && g.endpoints(e)[0] == v) written += costs[e];
  }
  RC_ASSERT(written == r.total_cost);
  RC_TAG(r.perfect ? "perfect" : "not perfect");
}

// ---- the verifier rejects perturbed answers

RC_GTEST_PROP(MinCostVerifier, RejectsACostlierPerfectMatching, ()) {
  // The cardinality algorithm's matching (shape-blind) with the optimum's certificate: when it
  // costs more, complementary slackness must fail somewhere.
  const CubicGraph g = any_cubic_bridgeless();
  const std::vector<Cost> costs = random_costs(g.edge_count(), 0, 1000);
  const MinCostResult r = min_cost_perfect_matching(g, costs);
  const PerfectMatchingResult other = perfect_matching(g, {.algorithm = Algorithm::automatic});
  Cost other_cost = 0;
  for (EdgeId e = 0; e < g.edge_count(); ++e)
    if (other.matching.mate_edge[g.endpoints(e)[0]] == e) other_cost += costs[e];
  RC_PRE(other_cost > r.total_cost);
  RC_ASSERT(!verify_min_cost_perfect_matching(g.node_count(), g.edge_ends(), costs, other.matching,
                                              other_cost, r.certificate)
                 .ok());
  RC_ASSERT(!verify_min_cost_perfect_matching(g.node_count(), g.edge_ends(), costs, other.matching,
                                              r.total_cost, r.certificate)
                 .ok());
}

RC_GTEST_PROP(MinCostVerifier, RejectsPerturbedDuals, ()) {
  const CubicGraph g = any_cubic_bridgeless();
  const std::vector<Cost> costs = random_costs(g.edge_count(), 0, 1000);
  const MinCostResult r = min_cost_perfect_matching(g, costs);
  auto check = [&](const Matching& m, const MatchingCertificate& c) {
    return verify_min_cost_perfect_matching(g.node_count(), g.edge_ends(), costs, m, r.total_cost,
                                            c);
  };
  RC_ASSERT(check(r.matching, r.certificate).ok());
  const NodeId v = *rc::gen::inRange<NodeId>(0, g.node_count());
  {  // a raised potential: its matched edge or the dual objective gives it away
    MatchingCertificate c = r.certificate;
    c.node_dual[v] += 1;
    RC_ASSERT(!check(r.matching, c).ok());
  }
  {  // a swapped matched edge at v (a matching no longer)
    Matching m = r.matching;
    const auto edges = g.incident_edges(v);
    m.mate_edge[v] = edges[0] == m.mate_edge[v] ? edges[1] : edges[0];
    RC_ASSERT(!check(m, r.certificate).ok());
  }
  if (r.certificate.set_count() > 0) {
    const std::size_t s = *rc::gen::inRange<std::size_t>(0, r.certificate.set_count());
    {  // a broken blossom: one member moved out to the enclosing set (an even set)
      MatchingCertificate c = r.certificate;
      auto holds = [&](NodeId v) {
        for (std::uint32_t at = c.node_set[v]; at != kNoSet; at = c.set_parent[at])
          if (at == s) return true;
        return false;
      };
      NodeId member = 0;
      while (!holds(member)) ++member;
      // Out of s and of every set between it and the node: those sets all turn even.
      c.node_set[member] = c.set_parent[s];
      RC_ASSERT(!check(r.matching, c).ok());
    }
    {  // a cycle of sets
      MatchingCertificate c = r.certificate;
      c.set_parent[s] = static_cast<std::uint32_t>(s);
      RC_ASSERT(!check(r.matching, c).ok());
    }
    {  // a blossom's dual moved to a node: same objective, infeasible or not tight somewhere
      MatchingCertificate c = r.certificate;
      c.set_dual[s] = -c.set_dual[s];
      RC_ASSERT(!check(r.matching, c).ok());
    }
  }
  RC_TAG(r.certificate.set_count() > 0 ? "with odd sets" : "no odd sets");
}

// ---- the shared meshes under the quad measure

TEST(MinCostPerfect, SharedMeshesUnderTheQuadMeasureEqualLemonAndAreCertified) {
  const auto dir = testing::shared_mesh_dir();
  if (!dir) GTEST_SKIP() << "no shared meshes";
  for (const testing::SharedMesh& mesh : testing::shared_meshes_up_to(25'000)) {
    SCOPED_TRACE(mesh.file);
    const PolygonMesh triangles = read_mesh(*dir + "/" + mesh.file);
    const Dual dual = build_dual(triangles);
    // On a closed triangle mesh the pairable graph is the dual, edge for edge (both number edges
    // by their mesh edge): its costs are the dual's.
    const PairableGraph pairable = build_pairable_graph(triangles);
    ASSERT_EQ(pairable.edge_count(), dual.graph.edge_count());
    const std::pmr::vector<Cost> costs = scale_costs(pairable_edge_quality(pairable, triangles));
    // Two threads (the short searches' halves run at once on graphs of this size), and the same
    // matching on one.
    const MinCostResult r = min_cost_perfect_matching(dual.graph, costs, {.threads = 2});
    const CertificateCheck check =
        verify_min_cost_perfect_matching(dual.graph.node_count(), dual.graph.edge_ends(), costs,
                                         r.matching, r.total_cost, r.certificate);
    EXPECT_TRUE(check.ok()) << check.problem;
    EXPECT_EQ(min_cost_perfect_matching(dual.graph, costs, {.threads = 1}).matching.mate_edge,
              r.matching.mate_edge);
    const std::vector<Cost> lemon_costs(costs.begin(), costs.end());
    EXPECT_EQ(testing::lemon_min_cost_perfect(dual.graph.node_count(), edge_list(dual.graph),
                                              lemon_costs),
              r.total_cost);
  }
}

// ---- hand-built cases, optimum by brute force

TEST(MinCostPerfect, TwoTrianglesJoinedNeedABlossom) {
  // Triangles 0-1-2 and 3-4-5 with cheap inner edges and a costly bridge 2-3: every perfect
  // matching uses the bridge, and the optimal dual needs the triangles as odd sets.
  const Edges edges = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}, {2, 3}};
  const std::vector<Cost> costs = {1, 5, 7, 2, 3, 9, 100};
  const CsrGraph g = CsrGraph::from_edges(6, edges);
  std::vector<char> used(6, 0);
  const Best best = brute_force(6, edges, costs, used, true);
  const MinCostResult r = min_cost_perfect_matching(g, costs, {.greedy_start = false});
  EXPECT_EQ(r.total_cost, best.cost);
  const CertificateCheck check = verify_min_cost_perfect_matching(6, ends_of(g), costs, r.matching,
                                                                  r.total_cost, r.certificate);
  EXPECT_TRUE(check.ok()) << check.problem;
}

TEST(MinCostPerfect, PetersenGraphWithDistinctCosts) {
  const CubicGraph g = petersen_graph();
  std::vector<Cost> costs(g.edge_count());
  for (EdgeId e = 0; e < g.edge_count(); ++e) costs[e] = (7 * e + 3) % 11;
  const Edges edges = edge_list(g);
  std::vector<char> used(g.node_count(), 0);
  const Best best = brute_force(g.node_count(), edges, costs, used, true);
  const MinCostResult r = min_cost_perfect_matching(g, costs);
  EXPECT_EQ(r.total_cost, best.cost);
  const CertificateCheck check = verify_min_cost_perfect_matching(
      g.node_count(), g.edge_ends(), costs, r.matching, r.total_cost, r.certificate);
  EXPECT_TRUE(check.ok()) << check.problem;
}

TEST(MinCostPerfect, NoPerfectMatchingThrows) {
  const Edges edges = {{0, 1}, {1, 2}, {2, 0}, {3, 4}, {4, 5}, {5, 3}};
  const CsrGraph g = CsrGraph::from_edges(6, edges);
  const std::vector<Cost> costs(edges.size(), 1);
  EXPECT_THROW(min_cost_perfect_matching(g, costs), GraphError);
}

// The solver renumbers the nodes; the error names the node as the caller numbered it.
TEST(MinCostPerfect, NodeWithoutEdgeIsNamedByTheCallersId) {
  const Edges edges = {{0, 2}, {2, 3}, {3, 4}, {4, 0}};  // node 1 has no edge
  const CsrGraph g = CsrGraph::from_edges(5, edges);
  const std::vector<Cost> costs(edges.size(), 1);
  try {
    min_cost_perfect_matching(g, costs);
    ADD_FAILURE() << "no error";
  } catch (const GraphError& error) {
    EXPECT_NE(std::string(error.what()).find("node 1 has no edge"), std::string::npos)
        << error.what();
  }
}

TEST(MinCostPerfect, RejectsBadCosts) {
  const CubicGraph g = theta_graph();
  EXPECT_THROW(min_cost_perfect_matching(g, std::vector<Cost>{1, 2}), std::invalid_argument);
  EXPECT_THROW(min_cost_perfect_matching(g, std::vector<Cost>{1, 2, kMaxCost + 1}),
               std::invalid_argument);
}

TEST(ScaleCosts, RoundsAndRejectsNonFinite) {
  const std::vector<double> degrees = {0.0, 1.0, 90.5, 270.0};
  const std::pmr::vector<Cost> scaled = scale_costs(degrees);
  for (std::size_t i = 0; i < degrees.size(); ++i)
    EXPECT_EQ(scaled[i], static_cast<Cost>(std::llround(degrees[i] * kDefaultCostScale)));
  const std::vector<double> bad = {1.0, std::numeric_limits<double>::quiet_NaN()};
  EXPECT_THROW(scale_costs(bad), std::invalid_argument);
}

// Binary doubles that a power of two makes integers within the limit are exact; others are
// rounded at the largest power of two that keeps them within it, the rounding stated.
TEST(IntegerCosts, ExactForShortBinaryFractionsRoundedOtherwise) {
  const std::vector<double> binary = {2.5, -3.0, 0.125, 0};
  const IntegerCosts exact = integer_costs(binary);
  EXPECT_TRUE(exact.exact);
  EXPECT_EQ(exact.exponent, 3);
  EXPECT_EQ(std::vector<Cost>(exact.costs.begin(), exact.costs.end()),
            (std::vector<Cost>{20, -24, 1, 0}));
  EXPECT_EQ(exact.rounding, 0);
  EXPECT_EQ(exact.gap_bound(1000), 0);
  const std::vector<double> reals = {3.141592653589793, -2.718281828459045, 0.1};
  const IntegerCosts rounded = integer_costs(reals);
  EXPECT_FALSE(rounded.exact);
  for (std::size_t e = 0; e < reals.size(); ++e) {
    EXPECT_LE(std::abs(static_cast<double>(rounded.costs[e])), static_cast<double>(kMaxCost));
    EXPECT_LE(
        std::abs(std::ldexp(static_cast<double>(rounded.costs[e]), -rounded.exponent) - reals[e]),
        rounded.rounding);
  }
  EXPECT_LE(rounded.rounding, std::ldexp(0.5, -rounded.exponent));
  EXPECT_GT(std::abs(static_cast<double>(rounded.costs[0])), static_cast<double>(kMaxCost) / 4);
  // A smaller limit, and costs far past it (a negative exponent).
  const IntegerCosts small = integer_costs(reals, 1000);
  EXPECT_LE(std::abs(small.costs[0]), 1000);
  const std::vector<double> huge = {1e300, -3e299};
  const IntegerCosts far = integer_costs(huge);
  EXPECT_LT(far.exponent, 0);
  EXPECT_LE(std::abs(far.costs[0]), kMaxCost);
  const std::vector<double> bad = {1.0, std::numeric_limits<double>::infinity()};
  EXPECT_THROW(integer_costs(bad), std::invalid_argument);
  EXPECT_THROW(integer_costs(binary, 0), std::invalid_argument);
}

}  // namespace
}  // namespace petersen
