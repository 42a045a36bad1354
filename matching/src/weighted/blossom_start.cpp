#include <algorithm>
#include <array>
#include <vector>

#include "blossom_solver.hpp"
#include "petersen/matching/augment.hpp"

namespace petersen::weighted_detail {

BlossomSolver::BlossomSolver(const BreadthFirstAdjacency& graph, MinCostStats& stats,
                             std::pmr::memory_resource* memory)
    : graph_(graph),
      stats_(stats),
      n_(graph.node_count()),
      ids_(std::size_t{n_} + n_ / 2 + 1),
      rec_(memory),
      base_(memory),
      link_(memory),
      mark_(memory),
      up_(memory) {
  // Blossom ids get their entries when first handed out (new_blossom): reserving leaves the
  // pages untouched, and few of the n/2 ids are ever used (freed ids are reused first), where
  // filling them all up front would first-touch 116 bytes per id. Reserved before the nodes'
  // entries are made, so that these are not made, then moved into the larger block (two blocks
  // first-touched and a copy, most of the set-up's time on fresh pages).
  rec_.reserve(ids_);
  base_.reserve(ids_);
  link_.reserve(ids_);
  mark_.reserve(ids_);
  up_.reserve(ids_);
  rec_.resize(n_);
  base_.resize(n_);
  link_.resize(n_);
  mark_.resize(n_, 0);
  up_.resize(n_);
  children_.reserve(ids_ - n_);
  conn_.reserve(ids_ - n_);
  for (NodeId v = 0; v < n_; ++v) {
    base_[v] = v;
    // y_v = the cheapest cost at v (C/2): feasible whatever the signs of the costs.
    Cost cheapest = kNoCost;
    for (const Slot& slot : slots_of(v)) cheapest = std::min(cheapest, slot.cost2 / 2);
    rec_[v].y = cheapest;
  }
}

/// Blossom V's greedy start: each free node in id order raises y_v by its smallest slack and
/// takes a tight edge to a free neighbour.
void BlossomSolver::greedy_start() {
  for (NodeId v = 0; v < n_; ++v) {
    if (rec_[v].mate.edge != kNoEdge) continue;
    Cost least = kNoCost;
    for (const Slot& slot : slots_of(v)) {
      least = std::min(least, slot.cost2 - rec_[v].y - rec_[slot.other].y);
    }
    rec_[v].y += least;
    for (const Slot& slot : slots_of(v)) {
      const NodeId w = slot.other;
      if (rec_[w].mate.edge == kNoEdge && slot.cost2 - rec_[v].y - rec_[w].y == 0) {
        rec_[v].mate = {slot.edge, w};
        rec_[w].mate = {slot.edge, v};
        break;
      }
    }
  }
}

/// Grows the matching to a maximum matching of the tight edges by the project's cardinality
/// augmentation (augment_matching on a CsrGraph of the tight edges): every edge it matches is
/// tight, so the duals stay feasible and complementary, and fewer trees are left to grow.
void BlossomSolver::augment_tight() {
  std::vector<std::array<NodeId, 2>> ends;
  std::vector<EdgeId> original;
  // Each edge once, from its smaller end (a loop is never matched).
  for (NodeId a = 0; a < n_; ++a) {
    for (const Slot& slot : slots_of(a)) {
      const NodeId b = slot.other;
      if (b <= a || slot.cost2 - rec_[a].y - rec_[b].y != 0) continue;
      ends.push_back({a, b});
      original.push_back(slot.edge);
    }
  }
  const CsrGraph tight = CsrGraph::from_edges(n_, ends);
  Matching matching(n_);
  for (EdgeId i = 0; i < original.size(); ++i) {
    const auto [a, b] = ends[i];
    if (rec_[a].mate.edge == original[i]) matching.mate_edge[a] = matching.mate_edge[b] = i;
  }
  augment_matching(tight, matching, Augment::local);
  for (NodeId v = 0; v < n_; ++v) {
    const EdgeId i = matching.mate_edge[v];
    rec_[v].mate = i == kNoEdge ? Mate{} : Mate{original[i], tight.other_end(i, v)};
  }
}

/// The nodes left free by the start (greedy_start, augment_tight, short_searches).
std::uint32_t BlossomSolver::free_nodes() const {
  std::uint32_t free = 0;
  for (NodeId v = 0; v < n_; ++v) free += rec_[v].mate.edge == kNoEdge;
  return free;
}

}  // namespace petersen::weighted_detail
