// PS, Puli and Segal's heuristic (paper §3.1). Priorities, as the paper defines them:
//   3: zero or one free edge;  0: three free edges;
//   1: two free edges, both shared with priority-0 nodes;  2: two free edges otherwise.
// An edge is free while both its nodes are unpaired. A node's free-edge count only falls and a
// neighbour never returns to priority 0, so a node's priority only rises (0 → 1 → 2 → 3, steps
// may be skipped). Hence each set is a stack with lazy deletion: a node is pushed when it enters a
// set, at most once per set, and an entry whose node has moved on is dropped when drawn — O(1)
// amortised per operation, flat arrays, no heap.
// Set 0 is never stored: it is every node still at priority 0, drawn by a cursor that walks the
// nodes cyclically from a seeded start (it is drawn from only when sets 1–3 are empty, about once
// per component, since pairing a node puts its neighbours into sets 1–3).
//
// Cost: a node's whole state is one byte (free-edge count, priority, out of play), so every test
// of a neighbour reads one byte array that stays in cache. A node's neighbourhood is scanned once
// when it leaves priority 0 (its free edges fall from 3 to 2): that one pass both decides between
// priorities 1 and 2 and moves its priority-1 neighbours to 2 (they no longer share both free
// edges with priority-0 nodes). Every other change is a counter decrement.
// The neighbours are read from a NeighbourTable, three per node side by side, so a scan reads one
// line instead of an incidence list and three edges' ends (the scans of the nodes leaving
// priority 0 dominated the profile, stalled on exactly those loads).

#include <array>
#include <span>
#include <vector>

#include "greedy.hpp"
#include "neighbour_table.hpp"
#include "petersen/graph/seeded_random.hpp"

namespace petersen {

namespace {

// The state byte: bits 0-1 free-edge count, bits 2-3 priority, bit 4 out of play (paired, or
// left unpaired with no free edge). A node in play with three free edges is 0b00011.
// Out of play, the low bits are dead; a paired node (kPaired) keeps there the index of its
// pairing edge among its three, for the mate pass at the end, which is then sequential.
constexpr std::uint8_t kFreeMask = 3;
constexpr std::uint8_t kPriorityMask = 3 << 2;
constexpr std::uint8_t kOut = 1 << 4;
constexpr std::uint8_t kPaired = 1 << 5;
constexpr std::uint8_t kStart = 3;

class PuliSegal {
 public:
  PuliSegal(NeighbourTable& table, std::pmr::vector<EdgeId>* mate, std::uint64_t seed)
      : table_(table),
        mate_(mate),
        state_(table.node_count(), kStart),
        random_(seed),
        cursor_(table.node_count() == 0 ? 0 : random_.below(table.node_count())) {}

  // Returns the number of nodes left unpaired.
  std::uint32_t run() {
    for (NodeId v = draw(); v != kNoNode; v = draw()) {
      // A highest-priority neighbour over a free edge (the first one met on ties).
      int best = -1;
      int best_priority = -1;
      for (int i = 0; i < 3; ++i) {
        const std::uint8_t s = state_[neighbours(v)[i]];
        __builtin_prefetch(neighbours(neighbours(v)[i]).data());  // u's, and the other losers'
        if (!(s & kOut) && priority(s) > best_priority) {
          best = i;
          best_priority = priority(s);
        }
      }
      if (best < 0) {  // every neighbour is paired: v stays unpaired
        state_[v] |= kOut;
        continue;
      }
      state_[v] = static_cast<std::uint8_t>(kOut | kPaired | best);
      const NodeId u = neighbours(v)[best];
      state_[u] = static_cast<std::uint8_t>(kOut | kPaired |
                                            table_.index_across(v, best, u, mate_ != nullptr));
      // The neighbours that lose a free edge, their incidence lists and edge ends fetched
      // together before any is updated, so the cache misses overlap instead of queueing.
      std::array<NodeId, 6> losers;
      int count = 0;
      for (NodeId w : {v, u}) {
        for (NodeId z : neighbours(w)) {
          if (state_[z] & kOut) continue;
          losers[count++] = z;
          __builtin_prefetch(neighbours(z).data());
        }
      }
      for (int i = 0; i < count; ++i) lose_free_edge(losers[i]);
    }
    return table_.start_searches(
        [&](NodeId v) { return state_[v] & kPaired ? state_[v] & kFreeMask : -1; }, mate_);
  }

 private:
  static int priority(std::uint8_t s) { return (s & kPriorityMask) >> 2; }
  std::span<const NodeId, 3> neighbours(NodeId v) const { return table_.neighbours(v); }

  void enter(NodeId v, std::uint8_t state, int p) {
    state_[v] = static_cast<std::uint8_t>((state & ~kPriorityMask) | p << 2);
    sets_[p].push_back(v);
  }

  // z, in play, lost a free edge.
  void lose_free_edge(NodeId z) {
    const std::uint8_t s = state_[z] - 1;
    if ((s & kFreeMask) <= 1) {  // priority 3
      if (priority(s) == 3) {
        state_[z] = s;
      } else {
        enter(z, s, 3);
      }
      return;
    }
    // Three free edges became two: z leaves priority 0 (the one pass over its neighbours).
    int now = 1;
    std::array<NodeId, 3> demoted;
    int demotions = 0;
    for (NodeId w : neighbours(z)) {
      const std::uint8_t sw = state_[w];
      if (sw & kOut) continue;
      if (priority(sw) == 0) {
        // w lies just past the pairing front, where the next pairings happen (set 2, the
        // front, holds about 20 nodes on armadillo-sub2's dual): its list is fetched now, while
        // it is one load away, instead of as a miss in the chain draw → mate → loser.
        __builtin_prefetch(neighbours(w).data());
        continue;
      }
      now = 2;
      if (priority(sw) == 1) demoted[demotions++] = w;
    }
    enter(z, s, now);
    for (int i = 0; i < demotions; ++i) {
      if (priority(state_[demoted[i]]) == 1) enter(demoted[i], state_[demoted[i]], 2);
    }
  }

  // A node of the highest non-empty set, chosen uniformly at random within it; kNoNode when
  // every node is out.
  NodeId draw() {
    for (int p = 3; p >= 1; --p) {
      std::vector<NodeId>& set = sets_[p];
      while (!set.empty()) {
        const std::uint32_t k = random_.below(static_cast<std::uint32_t>(set.size()));
        const NodeId v = set[k];
        set[k] = set.back();
        set.pop_back();
        if (!(state_[v] & kOut) && priority(state_[v]) == p) return v;
      }
    }
    const std::uint32_t n = table_.node_count();
    while (scanned_ < n) {  // each node is met once: a node past the cursor never returns to 0
      const NodeId v = cursor_;
      cursor_ = cursor_ + 1 == n ? 0 : cursor_ + 1;
      ++scanned_;
      if (state_[v] == kStart) return v;
    }
    return kNoNode;
  }

  NeighbourTable& table_;
  std::pmr::vector<EdgeId>* mate_;           // nullptr: the matching is the table's state only
  std::vector<std::uint8_t> state_;          // see kFreeMask, kPriorityMask, kOut
  std::array<std::vector<NodeId>, 4> sets_;  // sets 1..3; set 0 is implicit (see above)
  SeededRandom random_;
  NodeId cursor_;
  std::uint32_t scanned_ = 0;
};

}  // namespace

std::uint32_t puli_segal(NeighbourTable& table, std::pmr::vector<EdgeId>* mate_edge,
                         std::uint64_t seed) {
  return PuliSegal(table, mate_edge, seed).run();
}

void puli_segal(const CubicGraph& graph, Matching& matching, std::uint64_t seed) {
  NeighbourTable table(graph);
  puli_segal(table, &matching.mate_edge, seed);
}

}  // namespace petersen
