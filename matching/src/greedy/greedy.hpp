#pragma once
// The two greedy initial pairings of the paper's §3.1; perfect_matching augments what they leave.

#include <cstdint>
#include <optional>

#include "neighbour_table.hpp"
#include "petersen/matching/matching.hpp"
#include "petersen/matching/options.hpp"

namespace petersen {

/// SG, the simple greedy pairing (§3.1): every edge, in a seeded random order, joins its two
/// nodes if both are still free. `matching` must start empty. Θ(n).
void simple_greedy(const CubicGraph& graph, Matching& matching, std::uint64_t seed);

/// PS, Puli and Segal's priority pairing (§3.1): repeatedly pair a node of the highest non-empty
/// priority set with a highest-priority neighbour over a free edge. `matching` must start empty.
/// Θ(n), every set operation O(1).
void puli_segal(const CubicGraph& graph, Matching& matching, std::uint64_t seed);
/// PS over a table the caller keeps, for the augmentation that follows: the table's search state
/// ends up fresh for the matching PS makes (augment_cubic.hpp), and so do the mate edges, given
/// `mate_edge` (all kNoEdge on entry; nullptr over a table on neighbour rows, which has no
/// CubicGraph: the matching is then each slot's mate node). Returns the number of nodes left
/// unpaired.
std::uint32_t puli_segal(NeighbourTable& table, std::pmr::vector<EdgeId>* mate_edge,
                         std::uint64_t seed);

/// Even nodes a repair of the ordered sweep searches at most (ordered_sweep.cpp says why 64).
inline constexpr std::uint32_t kSweepRepairBudget = 64;

/// The ordered sweep (ordered_sweep.cpp): the nodes in id order, each free one paired with its
/// free neighbour of fewest free neighbours (of smallest id on ties), a node left with one free
/// neighbour paired at once, a node left with none (stranded) repaired by a short augmenting path
/// when a search that scans no further once it has reached `repair_budget` even nodes (the stranded
/// one included, so 0 and 1 turn the repairs off) finds one. Over a table whose search state (and,
/// with `mate_edge`, the mate edges) it writes fresh for its matching, like PS; returns the number
/// of nodes left unpaired. Returns std::nullopt, touching nothing, when the numbering is not local
/// (the median largest id gap between sampled nodes and their neighbours above a few √n), where its
/// pairing front would break up. Θ(n); n bytes of state.
std::optional<std::uint32_t> ordered_sweep(NeighbourTable& table,
                                           std::pmr::vector<EdgeId>* mate_edge,
                                           std::uint32_t repair_budget = kSweepRepairBudget);

/// Schrijver's perfect matching of a 3-regular bipartite graph (schrijver.cpp), over a table
/// whose search state it writes fresh for the matching (and, with `mate_edge`, the mate edges),
/// like PS. Returns false when the walk meets an odd cycle or a loop, so never on a bipartite
/// graph: then no mate edge is written, and the search state is as it was when
/// `state_is_fresh` (every slot fresh on entry, as a sweep or PS leaves them: the walk then
/// starts from it), else left for PS to write. (On a graph that is not bipartite the walk may
/// still meet even cycles only; its matching is then perfect all the same: every node keeps
/// weight 3 on exactly one edge.)
/// Θ(n) time; extra memory: the walk's path, 8 bytes per node on it (at most n).
bool schrijver(NeighbourTable& table, std::pmr::vector<EdgeId>* mate_edge, bool state_is_fresh);

/// What pairs in PS's place. Algorithm::automatic turns both on, Algorithm::ps both off (the
/// paper's PS alone); tests turn them on one at a time.
struct PsPlaceOptions {
  bool ordered_sweep = true;                               ///< the sweep where the order is local
  bool bipartite_exact = true;                             ///< Schrijver's where the sweep leaves
  std::uint64_t seed = 1;                                  ///< PS's
  std::uint32_t sweep_repair_budget = kSweepRepairBudget;  ///< the sweep's (tests turn it off)
};

/// The options of pair_in_ps_place for a front door's algorithm (automatic or ps).
inline PsPlaceOptions ps_place_options(Algorithm algorithm, std::uint64_t seed) {
  const bool automatic = algorithm == Algorithm::automatic;
  return {.ordered_sweep = automatic, .bipartite_exact = automatic, .seed = seed};
}

/// What made the initial pairing in PS's place, and what it left.
struct PsPlace {
  bool ordered_sweep = false;  ///< the sweep's pairing stands (PerfectMatchingStats::ordered_sweep)
  bool schrijver =
      false;  ///< Schrijver's perfect matching replaced it (PerfectMatchingStats::schrijver)
  std::uint32_t unpaired = 0;
};

/// The initial pairing of `auto` (paper §3.1, PS's place), as both front doors make it over a table
/// whose search state it writes fresh (and, with `mate_edge`, all kNoEdge on entry, the mate
/// edges): the ordered sweep where the numbering is local; where it leaves a node unpaired or does
/// not run, Schrijver's exact matching, which pairs a bipartite graph perfectly; where neither
/// stands, PS. The sweep goes first because it pairs every node of the bipartite plates (A1,
/// D0-D6) in 0.8-2.0 times a BFS's time, where Schrijver's walk takes 2.3-3.2 (bench/RESULTS.md,
/// the two orders alternated); where it leaves nodes on a graph that is not bipartite,
/// Schrijver's walk starts from the sweep's fresh state and gives up at its first odd cycle.
PsPlace pair_in_ps_place(NeighbourTable& table, std::pmr::vector<EdgeId>* mate_edge,
                         const PsPlaceOptions& options);

}  // namespace petersen
