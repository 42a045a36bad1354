// SG and PS (paper §3.1) alone: valid matchings, maximal, seeded; the ordered sweep, which takes
// PS's place where the numbering is local; Schrijver's exact matching of bipartite graphs, which
// takes it where the sweep leaves nodes or does not run.

#include "greedy/greedy.hpp"

#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <vector>

#include "neighbour_table.hpp"
#include "petersen/graph/seeded_random.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "petersen/matching/perfect_partners.hpp"
#include "petersen/testing/arbitrary.hpp"

namespace petersen {
namespace {

// No edge joins two unpaired nodes: both greedy pairings run until no free edge is left.
bool is_maximal(const CubicGraph& g, const Matching& m) {
  for (EdgeId e = 0; e < g.edge_count(); ++e) {
    auto [a, b] = g.endpoints(e);
    if (!m.is_matched(a) && !m.is_matched(b)) return false;
  }
  return true;
}

RC_GTEST_PROP(SimpleGreedy, ReturnsAValidMaximalMatching, ()) {
  CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  Matching m(g.node_count());
  simple_greedy(g, m, *rc::gen::arbitrary<std::uint64_t>());
  RC_ASSERT(verify_matching(g, m).ok());
  RC_ASSERT(is_maximal(g, m));
}

RC_GTEST_PROP(PuliSegal, ReturnsAValidMaximalMatching, ()) {
  CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  Matching m(g.node_count());
  puli_segal(g, m, *rc::gen::arbitrary<std::uint64_t>());
  RC_ASSERT(verify_matching(g, m).ok());
  RC_ASSERT(is_maximal(g, m));
}

RC_GTEST_PROP(Greedy, SameSeedSamePairing, ()) {
  CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  const auto seed = *rc::gen::arbitrary<std::uint64_t>();
  for (auto pairing : {&simple_greedy, &puli_segal}) {
    Matching first(g.node_count()), second(g.node_count());
    pairing(g, first, seed);
    pairing(g, second, seed);
    RC_ASSERT(first.mate_edge == second.mate_edge);
  }
}

TEST(PuliSegal, PairsFarMoreThanSimpleGreedyOnASurface) {
  // The paper's §4 finding: SG pairs about 87 % of the triangles, PS more than 99 %.
  CubicGraph g = dual_graph(voxel_plate({.holes_x = 3, .holes_y = 3, .subdivision = 6}));
  Matching sg(g.node_count()), ps(g.node_count());
  simple_greedy(g, sg, 7);
  puli_segal(g, ps, 7);
  const double n = g.node_count();
  EXPECT_GT(sg.unmatched_count() / n, 0.08);
  EXPECT_LT(sg.unmatched_count() / n, 0.18);
  EXPECT_LT(ps.unmatched_count() / n, 0.01);
}

// Two-colourable, by a breadth-first colouring of its own (the oracle Schrijver is held to).
bool is_bipartite(const CubicGraph& g) {
  std::vector<int> colour(g.node_count(), -1);
  for (NodeId s = 0; s < g.node_count(); ++s) {
    if (colour[s] >= 0) continue;
    colour[s] = 0;
    std::vector<NodeId> queue{s};
    for (std::size_t head = 0; head < queue.size(); ++head) {
      const NodeId v = queue[head];
      for (EdgeId e : g.incident_edges(v)) {
        const NodeId u = g.other_end(e, v);
        if (colour[u] < 0) {
          colour[u] = 1 - colour[v];
          queue.push_back(u);
        } else if (colour[u] == colour[v]) {
          return false;
        }
      }
    }
  }
  return true;
}

// A random 3-regular bipartite multigraph on 2k nodes: three random perfect matchings between
// the two sides (parallel edges where two agree), the node ids shuffled so the sides interleave.
CubicGraph random_bipartite_cubic(std::uint32_t k, std::uint64_t seed) {
  SeededRandom random(seed);
  std::vector<NodeId> id(2 * k);
  std::iota(id.begin(), id.end(), 0);
  for (std::uint32_t i = 2 * k - 1; i > 0; --i) std::swap(id[i], id[random.below(i + 1)]);
  std::vector<std::array<NodeId, 2>> edges;
  std::vector<NodeId> side(k);
  for (int round = 0; round < 3; ++round) {
    std::iota(side.begin(), side.end(), 0);
    for (std::uint32_t i = k - 1; i > 0; --i) std::swap(side[i], side[random.below(i + 1)]);
    for (std::uint32_t i = 0; i < k; ++i) edges.push_back({id[i], id[k + side[i]]});
  }
  return CubicGraph::from_edges(2 * k, edges);
}

rc::Gen<CubicGraph> bipartite_cubic_graphs() {
  return rc::gen::apply(random_bipartite_cubic, rc::gen::inRange<std::uint32_t>(1, 300),
                        rc::gen::arbitrary<std::uint64_t>());
}

// The graph with its node ids permuted at random, so that neighbours' ids lie far apart.
CubicGraph shuffled(const CubicGraph& g, std::uint64_t seed) {
  SeededRandom random(seed);
  std::vector<NodeId> id(g.node_count());
  std::iota(id.begin(), id.end(), 0);
  for (std::uint32_t i = g.node_count() - 1; i > 0; --i) std::swap(id[i], id[random.below(i + 1)]);
  std::vector<std::array<NodeId, 2>> edges;
  for (EdgeId e = 0; e < g.edge_count(); ++e) {
    auto [a, b] = g.endpoints(e);
    edges.push_back({id[a], id[b]});
  }
  return CubicGraph::from_edges(g.node_count(), edges);
}

// Each slot's four fields, to compare a table's search state before and after.
std::vector<std::array<std::uint32_t, 4>> slots_of(const NeighbourTable& table) {
  std::vector<std::array<std::uint32_t, 4>> slots;
  for (NodeId v = 0; v < table.node_count(); ++v) {
    const augment_detail::Slot& s = table.slot(v);
    slots.push_back({s.mate, s.tag, s.link, s.base});
  }
  return slots;
}

RC_GTEST_PROP(Schrijver, MatchesEveryBipartiteCubicGraphPerfectly, ()) {
  const CubicGraph g = *bipartite_cubic_graphs();
  // Its search state written by the walk itself, or fresh already (a table built from the empty
  // matching), as the ordered sweep leaves it.
  const bool state_is_fresh = *rc::gen::arbitrary<bool>();
  Matching m(g.node_count());
  NeighbourTable table(g, state_is_fresh ? &m.mate_edge : nullptr);
  RC_ASSERT(schrijver(table, &m.mate_edge, state_is_fresh));
  RC_ASSERT(verify_perfect_matching(g, m).ok());
  // The search state is fresh for the matching, as PS leaves it for the augmentation.
  for (NodeId v = 0; v < g.node_count(); ++v) {
    const augment_detail::Slot& slot = table.slot(v);
    RC_ASSERT(slot.mate == g.other_end(m.mate_edge[v], v));
    RC_ASSERT(slot.tag == 0u);
    RC_ASSERT(slot.link == augment_detail::kNone);
    RC_ASSERT(slot.base == v);
  }
}

RC_GTEST_PROP(Schrijver, FailsOnlyOnOddCyclesAndThenWritesNothing, ()) {
  // Cubic bridgeless graphs of every kind (K3,3, even prisms and thetas are bipartite; duals of
  // irregular triangulations and the Petersen graph are not). A bipartite graph is always
  // matched; another one is either matched perfectly (the walk met even cycles only, as on K4)
  // or left untouched.
  const CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  NeighbourTable table(g);
  Matching m(g.node_count());
  const bool matched = schrijver(table, &m.mate_edge, false);
  if (is_bipartite(g)) RC_ASSERT(matched);
  if (matched) {
    RC_ASSERT(verify_perfect_matching(g, m).ok());
  } else {
    RC_ASSERT(m.unmatched_count() == g.node_count());
  }
  RC_TAG(is_bipartite(g) ? "bipartite" : matched ? "matched anyway" : "odd cycle met");
}

RC_GTEST_PROP(Schrijver, AfterTheSweepMatchesPerfectlyOrPutsTheSweepsStateBack, ()) {
  // The order of pair_in_ps_place: the sweep's pairing, then Schrijver's walk from its fresh
  // state. On an odd cycle the sweep's mates and search state must be exactly as it left them.
  const CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  NeighbourTable table(g);
  Matching m(g.node_count());
  const std::optional<std::uint32_t> swept = ordered_sweep(table, &m.mate_edge);
  RC_PRE(swept.has_value());
  const Matching swept_matching = m;
  const auto swept_slots = slots_of(table);
  const bool matched = schrijver(table, &m.mate_edge, true);
  if (is_bipartite(g)) RC_ASSERT(matched);
  if (matched) {
    RC_ASSERT(verify_perfect_matching(g, m).ok());
  } else {
    RC_ASSERT(m.mate_edge == swept_matching.mate_edge);
    RC_ASSERT(slots_of(table) == swept_slots);
  }
  RC_TAG(is_bipartite(g) ? "bipartite" : matched ? "matched anyway" : "sweep's state put back");
}

RC_GTEST_PROP(Schrijver, BipartiteGraphsArePairedPerfectlyBeforeAugmentingAtBothFrontDoors, ()) {
  // By the sweep where the numbering is local and it pairs every node, else by Schrijver's walk:
  // nothing is left to augment either way, and both doors choose alike.
  const CubicGraph g = *bipartite_cubic_graphs();
  const PerfectMatchingResult r =
      perfect_matching(g, {.algorithm = Algorithm::automatic, .validate = false});
  RC_ASSERT(r.stats.schrijver != r.stats.ordered_sweep);
  RC_ASSERT(r.stats.unpaired_after_initial == 0u);
  RC_ASSERT(r.stats.augmenting_paths == 0u);
  RC_ASSERT(verify_perfect_matching(g, r.matching).ok());
  const std::pmr::vector<NodeId> rows = CubicGraph(g).into_neighbour_rows();
  const PartnerResult p = perfect_partners(rows);
  RC_ASSERT(p.stats.schrijver == r.stats.schrijver);
  RC_ASSERT(p.stats.ordered_sweep == r.stats.ordered_sweep);
  RC_ASSERT(verify_perfect_partners(rows, p.partner).ok());
  RC_TAG(r.stats.schrijver ? "Schrijver" : "the sweep");
}

TEST(Schrijver, TakesOverWhereTheSweepLeavesNodesOfABipartiteGraph) {
  // Small bipartite graphs (any numbering of up to 16 nodes is local) on which the sweep without
  // its repairs leaves nodes: Schrijver's matching replaces that pairing. With the repairs the
  // sweep pairs every one of them (its searches are complete on a bipartite graph this small),
  // so the front doors need no augmentation either way.
  int found = 0;
  for (std::uint64_t seed = 1; seed < 2000 && found < 5; ++seed) {
    const CubicGraph g = random_bipartite_cubic(8, seed);
    NeighbourTable unrepaired(g);
    Matching swept(g.node_count());
    if (ordered_sweep(unrepaired, &swept.mate_edge, 0).value_or(0) == 0) continue;
    ++found;
    NeighbourTable table(g);
    Matching m(g.node_count());
    const PsPlace place = pair_in_ps_place(table, &m.mate_edge, {.sweep_repair_budget = 0});
    EXPECT_TRUE(place.schrijver);
    EXPECT_FALSE(place.ordered_sweep);
    EXPECT_TRUE(verify_perfect_matching(g, m).ok());
    const PerfectMatchingResult r = perfect_matching(g, {.validate = false});
    EXPECT_EQ(r.stats.unpaired_after_initial, 0u);
    EXPECT_EQ(r.stats.augmenting_paths, 0u);
    EXPECT_TRUE(verify_perfect_matching(g, r.matching).ok());
    const std::pmr::vector<NodeId> rows = CubicGraph(g).into_neighbour_rows();
    EXPECT_EQ(perfect_partners(rows).stats.unpaired_after_initial, 0u);
  }
  EXPECT_EQ(found, 5);
}

TEST(Schrijver, MatchesAShuffledPlateAndLeavesThePetersenGraphToTheSweep) {
  // A regular voxel plate's dual is bipartite (the plates where PS leaves one-colour patches).
  // In the generator's order the sweep pairs it perfectly; shuffled, the sweep refuses the order
  // and Schrijver's walk matches it.
  const CubicGraph plate = dual_graph(voxel_plate({.holes_x = 3, .holes_y = 2, .subdivision = 5}));
  const PerfectMatchingResult in_order = perfect_matching(plate);
  EXPECT_TRUE(in_order.stats.ordered_sweep);
  EXPECT_EQ(in_order.stats.unpaired_after_initial, 0u);
  EXPECT_TRUE(verify_perfect_matching(plate, in_order.matching).ok());
  const CubicGraph mixed = shuffled(plate, 3);
  const PerfectMatchingResult r = perfect_matching(mixed);
  EXPECT_TRUE(r.stats.schrijver);
  EXPECT_EQ(r.stats.augmenting_paths, 0u);
  EXPECT_TRUE(verify_perfect_matching(mixed, r.matching).ok());
  const PerfectMatchingResult p = perfect_matching(petersen_graph());
  EXPECT_FALSE(p.stats.schrijver);
  EXPECT_TRUE(verify_perfect_matching(petersen_graph(), p.matching).ok());
}

// Algorithm::ps runs the paper's PS alone: on the plate it leaves nodes to augment.
TEST(Schrijver, IsSkippedByPaperPS) {
  const CubicGraph plate = dual_graph(voxel_plate({.holes_x = 3, .holes_y = 2, .subdivision = 5}));
  const PerfectMatchingResult r = perfect_matching(plate, {.algorithm = Algorithm::ps});
  EXPECT_FALSE(r.stats.schrijver);
  EXPECT_GT(r.stats.unpaired_after_initial, 0u);
  EXPECT_TRUE(verify_perfect_matching(plate, r.matching).ok());
  const std::pmr::vector<NodeId> rows = CubicGraph(plate).into_neighbour_rows();
  const PartnerResult p = perfect_partners(rows, {.algorithm = Algorithm::ps});
  EXPECT_FALSE(p.stats.schrijver);
  EXPECT_GT(p.stats.unpaired_after_initial, 0u);
  EXPECT_TRUE(verify_perfect_partners(rows, p.partner).ok());
}

RC_GTEST_PROP(OrderedSweep, ReturnsAValidMaximalMatchingWithAFreshSearchStateOrNothing, ()) {
  // With repairs of any budget (2: the stranded node's neighbours only) and without.
  const CubicGraph g = *rc::gen::arbitrary<CubicGraph>();
  const std::uint32_t budget = *rc::gen::element(0u, 2u, 3u, 8u, kSweepRepairBudget);
  NeighbourTable table(g);
  Matching m(g.node_count());
  const std::optional<std::uint32_t> unpaired = ordered_sweep(table, &m.mate_edge, budget);
  RC_TAG(unpaired ? "swept" : "order not local");
  if (!unpaired) {
    RC_ASSERT(m.unmatched_count() == g.node_count());  // refused: nothing written
    return;
  }
  RC_ASSERT(verify_matching(g, m).ok());
  RC_ASSERT(is_maximal(g, m));
  RC_ASSERT(*unpaired == m.unmatched_count());
  for (NodeId v = 0; v < g.node_count(); ++v) {
    const augment_detail::Slot& slot = table.slot(v);
    RC_ASSERT(slot.mate == (m.is_matched(v) ? g.other_end(m.mate_edge[v], v) : kNoNode));
    RC_ASSERT(slot.tag == 0u);
    RC_ASSERT(slot.link == augment_detail::kNone);
    RC_ASSERT(slot.base == v);
  }
}

TEST(OrderedSweep, SweepsALocalNumberingAndRefusesAShuffledOne) {
  // The plate's generator numbers its triangles row by row: a local numbering. (Its dual is
  // bipartite, which the sweep does not care about.)
  const CubicGraph plate = dual_graph(voxel_plate({.holes_x = 3, .holes_y = 3, .subdivision = 6}));
  NeighbourTable table(plate);
  Matching m(plate.node_count());
  const std::optional<std::uint32_t> unpaired = ordered_sweep(table, &m.mate_edge);
  ASSERT_TRUE(unpaired.has_value());
  EXPECT_LT(*unpaired / double(plate.node_count()), 0.01);
  EXPECT_TRUE(verify_matching(plate, m).ok());
  const CubicGraph mixed = shuffled(plate, 5);
  NeighbourTable mixed_table(mixed);
  Matching untouched(mixed.node_count());
  EXPECT_FALSE(ordered_sweep(mixed_table, &untouched.mate_edge).has_value());
  EXPECT_EQ(untouched.unmatched_count(), mixed.node_count());
}

TEST(OrderedSweep, RepairsMostOfWhatItStrandsOnAnIrregularPlate) {
  // Splits and flips make the plate's dual non-bipartite and irregular; stored in Morton order,
  // as petersen generate --spatial-order and scanners do. Without repairs the sweep strands 452 of
  // the 80,000 nodes here; with them 32 are left.
  const PolygonMesh mesh = spatially_ordered(randomize_triangulation(
      voxel_plate({.holes_x = 2, .holes_y = 1, .subdivision = 20}), 20000, 20000, 7));
  const CubicGraph g = dual_graph(mesh);
  std::uint32_t left[2];
  for (const std::uint32_t budget : {0u, kSweepRepairBudget}) {
    NeighbourTable table(g);
    Matching m(g.node_count());
    const std::optional<std::uint32_t> unpaired = ordered_sweep(table, &m.mate_edge, budget);
    ASSERT_TRUE(unpaired.has_value());
    EXPECT_TRUE(verify_matching(g, m).ok());
    EXPECT_EQ(*unpaired, m.unmatched_count());
    left[budget != 0] = *unpaired;
  }
  EXPECT_GT(left[0], 0u);
  EXPECT_LT(left[1] * 4, left[0]) << left[0] << " stranded, " << left[1] << " left";
}

TEST(OrderedSweep, TakesPSsPlaceAtBothFrontDoorsWhereTheNumberingIsLocal) {
  // In the generator's order the sweep pairs the plate whole, so Schrijver's matching, which
  // would take over where the sweep leaves nodes of a bipartite graph, does not run: the same
  // pairing as on a graph that is not bipartite.
  const CubicGraph plate = dual_graph(voxel_plate({.holes_x = 3, .holes_y = 2, .subdivision = 5}));
  const std::pmr::vector<NodeId> rows = CubicGraph(plate).into_neighbour_rows();
  for (const std::uint64_t seed : {1u, 2u}) {
    const PerfectMatchingResult r = perfect_matching(plate, {.seed = seed});
    EXPECT_TRUE(r.stats.ordered_sweep);
    EXPECT_FALSE(r.stats.schrijver);
    EXPECT_TRUE(verify_perfect_matching(plate, r.matching).ok());
    const PartnerResult p = perfect_partners(rows, {.seed = seed});
    EXPECT_TRUE(p.stats.ordered_sweep);
    EXPECT_EQ(p.stats.unpaired_after_initial, r.stats.unpaired_after_initial);
    EXPECT_TRUE(verify_perfect_partners(rows, p.partner).ok());
    for (NodeId v = 0; v < plate.node_count(); ++v)
      ASSERT_EQ(p.partner[v], plate.other_end(r.matching.mate_edge[v], v));
  }
  // Paper PS, or a numbering that is not local: PS pairs (with Schrijver's matching turned off,
  // as on a graph that is not bipartite).
  EXPECT_FALSE(perfect_matching(plate, {.algorithm = Algorithm::ps}).stats.ordered_sweep);
  const CubicGraph mixed = shuffled(plate, 9);
  NeighbourTable mixed_table(mixed);
  Matching by_ps(mixed.node_count());
  const PsPlace place = pair_in_ps_place(mixed_table, &by_ps.mate_edge, {.bipartite_exact = false});
  EXPECT_FALSE(place.ordered_sweep);
  EXPECT_FALSE(place.schrijver);
  EXPECT_EQ(place.unpaired, by_ps.unmatched_count());
  EXPECT_TRUE(verify_matching(mixed, by_ps).ok());
  const PerfectMatchingResult ps = perfect_matching(mixed);
  EXPECT_FALSE(ps.stats.ordered_sweep);
  EXPECT_TRUE(verify_perfect_matching(mixed, ps.matching).ok());
  // The Petersen graph (not bipartite, ten nodes: any numbering is local) goes to the sweep.
  const PerfectMatchingResult petersen = perfect_matching(petersen_graph());
  EXPECT_FALSE(petersen.stats.schrijver);
  EXPECT_TRUE(petersen.stats.ordered_sweep);
  EXPECT_TRUE(verify_perfect_matching(petersen_graph(), petersen.matching).ok());
}

TEST(Algorithms, AutoPairsInPSsPlaceAndPsRunsThePapersPSAlone) {
  // auto: the sweep on the plate in its generator's order, Schrijver's walk on it shuffled.
  // ps: the paper's PS on both (its pairing is puli_segal's for the same seed), never the others.
  const CubicGraph plate = dual_graph(voxel_plate({.holes_x = 3, .holes_y = 2, .subdivision = 5}));
  const CubicGraph mixed = shuffled(plate, 3);
  EXPECT_TRUE(perfect_matching(plate, {.algorithm = Algorithm::automatic}).stats.ordered_sweep);
  EXPECT_TRUE(perfect_matching(mixed, {.algorithm = Algorithm::automatic}).stats.schrijver);
  for (const CubicGraph* g : {&plate, &mixed}) {
    const PerfectMatchingResult r = perfect_matching(*g, {.algorithm = Algorithm::ps, .seed = 7});
    EXPECT_FALSE(r.stats.ordered_sweep);
    EXPECT_FALSE(r.stats.schrijver);
    EXPECT_TRUE(verify_perfect_matching(*g, r.matching).ok());
    NeighbourTable table(*g);
    Matching by_ps(g->node_count());
    EXPECT_EQ(r.stats.unpaired_after_initial, puli_segal(table, &by_ps.mate_edge, 7));
    const std::pmr::vector<NodeId> rows = CubicGraph(*g).into_neighbour_rows();
    const PartnerResult p = perfect_partners(rows, {.algorithm = Algorithm::ps, .seed = 7});
    EXPECT_FALSE(p.stats.ordered_sweep);
    EXPECT_FALSE(p.stats.schrijver);
    EXPECT_EQ(p.stats.unpaired_after_initial, r.stats.unpaired_after_initial);
  }
  const std::pmr::vector<NodeId> rows = CubicGraph(plate).into_neighbour_rows();
  EXPECT_THROW(perfect_partners(rows, {.algorithm = Algorithm::sg}), std::invalid_argument);
}

}  // namespace
}  // namespace petersen
