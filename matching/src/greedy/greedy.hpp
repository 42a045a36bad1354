#pragma once
// The two greedy initial pairings of the paper's §3.1; perfect_matching augments what they leave.

#include <cstdint>
#include <optional>

#include "neighbour_table.hpp"
#include "petersen/matching/matching.hpp"

namespace petersen {

/// SG, the simple greedy pairing (§3.1): every edge, in a seeded random order, joins its two
/// nodes if both are still free. `matching` must start empty. Θ(n).
void simple_greedy(const CubicGraph& graph, Matching& matching, std::uint64_t seed);

/// PS, Puli and Segal's priority pairing (§3.1): repeatedly pair a node of the highest non-empty
/// priority set with a highest-priority neighbour over a free edge. `matching` must start empty.
/// Θ(n), every set operation O(1).
void puli_segal(const CubicGraph& graph, Matching& matching, std::uint64_t seed);
/// PS over a table the caller keeps, for the augmentation that follows: the table's search state
/// ends up fresh for the matching PS returns (augment_cubic.hpp).
void puli_segal(NeighbourTable& table, Matching& matching, std::uint64_t seed);
/// PS over a table built on neighbour rows (no CubicGraph, so no mate edges): the matching is
/// the table's search state, each slot's mate node. Returns the number of nodes left unpaired.
std::uint32_t puli_segal_on_rows(NeighbourTable& table, std::uint64_t seed);

/// The ordered sweep (ordered_sweep.cpp): the nodes in id order, each free one paired with its
/// free neighbour of fewest free neighbours (of smallest id on ties), a node left with one free
/// neighbour paired at once.
/// Over a table whose search state (and, with `mate_edge`, the mate edges) it writes fresh for its
/// matching, like PS; returns the number of nodes left unpaired. Returns std::nullopt, touching
/// nothing, when the numbering is not local (the median largest id gap between sampled nodes and
/// their neighbours above a few √n), where its pairing front would break up. Θ(n); n bytes of
/// state.
std::optional<std::uint32_t> ordered_sweep(NeighbourTable& table, HugeVector<EdgeId>* mate_edge);

/// Schrijver's perfect matching of a 3-regular bipartite graph (schrijver.cpp), over a table
/// whose search state it writes fresh for the matching (and, with `mate_edge`, the mate edges),
/// like PS. Returns false when the walk meets an odd cycle or a loop, so never on a bipartite
/// graph: then no mate edge is written and the search state is left for PS to write. (On a
/// graph that is not bipartite the walk may still meet even cycles only; its matching is then
/// perfect all the same: every node keeps weight 3 on exactly one edge.)
/// Θ(n) time; extra memory: the walk's path, 8 bytes per node on it (at most n).
bool schrijver(NeighbourTable& table, HugeVector<EdgeId>* mate_edge);

}  // namespace petersen
