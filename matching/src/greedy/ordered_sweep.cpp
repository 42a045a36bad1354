// The ordered sweep: an initial pairing in the nodes' own order, for graphs whose numbering
// follows the surface (the bench's plates, meshes stored in a spatial order, some scanned
// meshes), tried in PS's place.
//   Nodes are taken in id order; a node still free is paired with the free neighbour that has
//   the fewest free neighbours left (the min-degree rule), and a node left with one free
//   neighbour is paired at once (Karp and Sipser's forced move; last in, first out). A node with
//   no free neighbour left is stranded; once the forced moves are done, it looks for an augmenting
//   path over at most kSweepRepairBudget (64) even nodes, and stays unpaired if none is found.
// Why the repair: a node is stranded just behind the front, where a free node a few steps ahead
// is usually at the end of a short alternating path, which costs a few dozen reads there and a
// tree growing through the graph in the augmentation. Without and with the repair
// (petersen_bench, labels of the augmentation; bench/RESULTS.md): nodes left on A2 230 and 136,
// A5 88 and 12, B5 92 and 2, B3 422 and 216, a 16M-triangle irregular plate 62,396 and 3,534;
// the augmentation's labels summed over A2-A5 and B2-B5 7.0M and 4.0M (budgets 48, 96 and 128:
// 6.0M, 5.1M, 6.7M; the few nodes left are far apart, and how far decides the labels, so more
// budget is not better). B2 alone is no better (514 and 284 nodes, 2.3M and 2.8M labels): the
// nodes its sweep strands need paths no local search finds.
// Why: PS's pass costs about two BFS passes (its priority sets, random draws and a rescan of each
// node leaving priority 0; a flat profile, no one hot spot), while the sweep reads each node's
// row and its neighbours' state bytes once, in the order of the rows. Where that order is local
// the pairing front is a line moving over the surface and strands no more nodes than PS (A2: 230
// against 690; B2: 514 against 550). petersen_bench, PS and the sweep alternated twice at load
// 4-5 (bench/RESULTS.md): A2 0.288 and 0.311 s with PS against 0.082 and 0.133, B2 0.510 and
// 0.434 against 0.135 and 0.132.
// Where the order jumps about (a subdivided mesh numbers each level's triangles after the
// coarser ones: fertility-sub3's median neighbour gap is 0.75 n), the front breaks into pieces
// everywhere and strands 1-3 % of the nodes (armadillo-sub2 17,174 against PS's 390), so the
// sweep refuses such an order before touching anything: it runs only when the median, over
// nodes sampled evenly, of a node's largest id distance to a neighbour is at most kLocalGap
// times √n. (A row-major grid's is about √n; the plates' 13-1,110, the subdivided meshes'
// 0.5-0.75 n.)

#include <algorithm>
#include <cmath>
#include <vector>

#include "greedy.hpp"
#include "neighbour_table.hpp"

namespace petersen {

namespace {

// The state byte, as in PS: bits 0-1 free-neighbour count, bit 4 out of play (paired or
// stranded), bit 5 paired, whose low bits then hold the index of the pairing edge in the row.
constexpr std::uint8_t kFreeMask = 3;
constexpr std::uint8_t kOut = 1 << 4;
constexpr std::uint8_t kPaired = 1 << 5;
constexpr std::uint8_t kStart = 3;
constexpr std::uint8_t kSeen = 1 << 6;  // reached by the current repair's search
constexpr std::uint32_t kNoParent = ~0u;

// The order counts as local up to this many √n of median largest gap (bench/RESULTS.md): the
// plates 0.01-1.9, where the sweep beats PS by 1.3-3.7x; homer 3.65, rocker-arm 1.2, fandisk 0.7,
// where it beats PS warm by 1.2-1.9x; nefertiti 4.62, where it leaves 544 nodes against PS's 82
// and loses warm (15 against 12 ms); bunny 9.0, where it loses too.
constexpr double kLocalGap = 4.0;
constexpr std::uint32_t kSamples = 1024;

bool order_is_local(const NeighbourTable& table) {
  const std::uint32_t n = table.node_count();
  if (n == 0) return true;
  const std::uint32_t step = std::max<std::uint32_t>(1, n / kSamples);
  std::vector<std::uint32_t> gaps;
  gaps.reserve(n / step + 1);
  for (NodeId v = 0; v < n; v += step) {
    std::uint32_t widest = 0;
    for (NodeId u : table.neighbours(v)) widest = std::max(widest, u > v ? u - v : v - u);
    gaps.push_back(widest);
  }
  const auto middle = gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2);
  std::nth_element(gaps.begin(), middle, gaps.end());
  return *middle <= kLocalGap * std::sqrt(double(n));
}

class OrderedSweep {
 public:
  OrderedSweep(NeighbourTable& table, std::pmr::vector<EdgeId>* mate, std::uint32_t repair_budget)
      : table_(table),
        mate_(mate),
        repair_budget_(repair_budget),
        state_(table.node_count(), kStart) {}

  std::uint32_t run() {
    const std::uint32_t n = table_.node_count();
    for (NodeId s = 0; s < n; ++s) {
      if (state_[s] & kOut) continue;
      pair_from(s);
      while (!forced_.empty() || !stranded_.empty()) {
        if (!forced_.empty()) {
          const NodeId v = forced_.back();
          forced_.pop_back();
          if (!(state_[v] & kOut)) pair_from(v);
        } else {
          const NodeId v = stranded_.back();
          stranded_.pop_back();
          if (!(state_[v] & kPaired)) repair(v);
        }
      }
    }
    return table_.start_searches(
        [&](NodeId v) { return state_[v] & kPaired ? state_[v] & kFreeMask : -1; }, mate_);
  }

 private:
  std::span<const NodeId, 3> neighbours(NodeId v) const { return table_.neighbours(v); }
  bool paired(NodeId v) const { return state_[v] & kPaired; }
  NodeId mate(NodeId v) const { return neighbours(v)[state_[v] & kFreeMask]; }

  // Pairs v, in play, with its free neighbour of fewest free neighbours; on ties, the one of
  // smallest id: the nearest to the front (every node before the sweep's position is out), so the
  // front stays straight. The first in the row would leave 2,938 nodes on B2 against 514, and
  // 12,642 on A2 against 230 (labels 13.1M and 1.49M against 2.3M and 1.18M; on the generated
  // plates the same within 10 %: bench/RESULTS.md).
  void pair_from(NodeId v) {
    int best = -1;
    int best_free = kStart + 1;
    for (int i = 0; i < 3; ++i) {
      const NodeId u = neighbours(v)[i];
      const std::uint8_t s = state_[u];
      const int free = s & kFreeMask;
      if (s & kOut) continue;
      if (free < best_free || (free == best_free && u < neighbours(v)[best])) {
        best = i;
        best_free = free;
      }
    }
    if (best < 0) {  // every neighbour is out: v is stranded
      strand(v);
      return;
    }
    const NodeId u = neighbours(v)[best];
    pair(v, best, u);
    take(v);
    take(u);
  }

  void pair(NodeId v, int i, NodeId u) {
    state_[v] = static_cast<std::uint8_t>(kOut | kPaired | i);
    state_[u] =
        static_cast<std::uint8_t>(kOut | kPaired | table_.index_across(v, i, u, mate_ != nullptr));
  }

  // w just went out of play: its neighbours in play lose a free neighbour.
  void take(NodeId w) {
    for (NodeId z : neighbours(w)) {
      if (state_[z] & kOut) continue;
      const int free = --state_[z] & kFreeMask;
      if (free == 0) {
        strand(z);  // its last free neighbour was just taken
      } else if (free == 1) {
        forced_.push_back(z);
      }
    }
  }

  void strand(NodeId v) {
    state_[v] |= kOut;
    stranded_.push_back(v);
  }

  // Stranded v looks for a short augmenting path to the nearest node not paired (a free node ahead
  // of the front, or another stranded node): an alternating breadth-first search from v, without
  // blossoms (a path it finds is a path all the same; the augmentation finds those it misses),
  // that scans no further once it has reached repair_budget_ even nodes. Right behind the front
  // such paths are short.
  void repair(NodeId v) {
    found_.assign(1, {v, kNoParent, 0});
    mark(v);
    for (std::uint32_t r = 0; r < found_.size() && found_.size() < repair_budget_; ++r) {
      const NodeId x = found_[r].node;
      for (int i = 0; i < 3; ++i) {
        const NodeId o = neighbours(x)[i];
        if (state_[o] & kSeen) continue;
        if (!paired(o)) {
          augment(r, i, o);
          break;
        }
        const NodeId m = mate(o);
        mark(o);
        mark(m);
        found_.push_back({m, r, static_cast<std::uint8_t>(i)});
      }
      if (paired(v)) break;
    }
    for (NodeId u : seen_) state_[u] &= ~kSeen;
    seen_.clear();
  }

  void mark(NodeId v) {
    state_[v] |= kSeen;
    seen_.push_back(v);
  }

  // Pairs found_[r]'s node with f across its i-th edge, and each even node above it with the odd
  // node below it, up to the stranded root.
  void augment(std::uint32_t r, int i, NodeId f) {
    const bool f_in_play = !(state_[f] & kOut);
    NodeId below = f;
    for (;;) {
      const Found here = found_[r];
      const NodeId odd = here.parent == kNoParent ? kNoNode : mate(here.node);
      pair(here.node, i, below);
      if (here.parent == kNoParent) break;
      below = odd;
      i = here.via;
      r = here.parent;
    }
    if (f_in_play) take(f);
  }

  NeighbourTable& table_;
  std::pmr::vector<EdgeId>* mate_;  // nullptr: the matching is the table's state only
  std::uint32_t repair_budget_;
  std::vector<std::uint8_t> state_;
  std::vector<NodeId> forced_;    // nodes left with one free neighbour, to pair next
  std::vector<NodeId> stranded_;  // nodes left with no free neighbour, to repair
  struct Found {
    NodeId node;           // an even node of the repair's search
    std::uint32_t parent;  // the record of the even node above it (kNoParent: the root)
    std::uint8_t via;      // the index in the parent's row of the odd node between them
  };
  std::vector<Found> found_;  // the repair's even nodes in the order reached
  std::vector<NodeId> seen_;  // every node marked kSeen
};

}  // namespace

std::optional<std::uint32_t> ordered_sweep(NeighbourTable& table,
                                           std::pmr::vector<EdgeId>* mate_edge,
                                           std::uint32_t repair_budget) {
  if (!order_is_local(table)) return std::nullopt;
  return OrderedSweep(table, mate_edge, repair_budget).run();
}

}  // namespace petersen
