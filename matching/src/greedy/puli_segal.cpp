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

#include <array>
#include <vector>

#include "greedy.hpp"
#include "seeded_random.hpp"

namespace petersen {

namespace {

constexpr std::uint8_t kOut = 4;  // paired, or left unpaired with no free edge

class PuliSegal {
 public:
  PuliSegal(const CubicGraph& graph, Matching& matching, std::uint64_t seed)
      : graph_(graph),
        mate_(matching.mate_edge),
        free_(graph.node_count(), 3),
        priority_(graph.node_count(), 0),
        random_(seed),
        cursor_(graph.node_count() == 0 ? 0 : random_.below(graph.node_count())) {}

  void run() {
    for (NodeId v = draw(); v != kNoNode; v = draw()) {
      // A highest-priority neighbour over a free edge (the first one met on ties).
      EdgeId best = kNoEdge;
      int best_priority = -1;
      for (EdgeId e : graph_.incident_edges(v)) {
        const NodeId u = graph_.other_end(e, v);
        if (mate_[u] == kNoEdge && priority_[u] > best_priority) {
          best = e;
          best_priority = priority_[u];
        }
      }
      priority_[v] = kOut;
      if (best == kNoEdge) continue;  // every neighbour is paired: v stays unpaired
      const NodeId u = graph_.other_end(best, v);
      priority_[u] = kOut;
      mate_[u] = mate_[v] = best;
      for (NodeId w : {v, u}) {
        for (EdgeId e : graph_.incident_edges(w)) {
          const NodeId z = graph_.other_end(e, w);
          if (mate_[z] != kNoEdge) continue;
          --free_[z];
          update(z);
        }
      }
    }
  }

 private:
  bool is_free(NodeId v) const { return mate_[v] == kNoEdge; }

  std::uint8_t priority_by_definition(NodeId v) const {
    if (free_[v] <= 1) return 3;
    if (free_[v] == 3) return 0;
    for (EdgeId e : graph_.incident_edges(v)) {
      const NodeId u = graph_.other_end(e, v);
      if (is_free(u) && priority_[u] != 0) return 2;
    }
    return 1;
  }

  void enter(NodeId v, std::uint8_t priority) {
    priority_[v] = priority;
    sets_[priority].push_back(v);
  }

  // v lost a free edge: move it, and if it left priority 0, its priority-1 neighbours lose that
  // status (they no longer share both free edges with priority-0 nodes).
  void update(NodeId v) {
    const std::uint8_t before = priority_[v];
    const std::uint8_t now = priority_by_definition(v);
    if (now == before) return;
    enter(v, now);
    if (before != 0) return;
    for (EdgeId e : graph_.incident_edges(v)) {
      const NodeId u = graph_.other_end(e, v);
      if (is_free(u) && priority_[u] == 1) enter(u, 2);
    }
  }

  // A node of the highest non-empty set, chosen uniformly at random within it; kNoNode when
  // every node is out.
  NodeId draw() {
    for (std::uint8_t p = 3; p >= 1; --p) {
      std::vector<NodeId>& set = sets_[p];
      while (!set.empty()) {
        const std::uint32_t k = random_.below(static_cast<std::uint32_t>(set.size()));
        const NodeId v = set[k];
        set[k] = set.back();
        set.pop_back();
        if (priority_[v] == p) return v;
      }
    }
    const std::uint32_t n = graph_.node_count();
    while (scanned_ < n) {  // each node is met once: a node past the cursor never returns to 0
      const NodeId v = cursor_;
      cursor_ = cursor_ + 1 == n ? 0 : cursor_ + 1;
      ++scanned_;
      if (priority_[v] == 0) return v;
    }
    return kNoNode;
  }

  const CubicGraph& graph_;
  std::vector<EdgeId>& mate_;
  std::vector<std::uint8_t> free_;           // free edges at each node
  std::vector<std::uint8_t> priority_;       // 0..3, or kOut
  std::array<std::vector<NodeId>, 4> sets_;  // sets 1..3; set 0 is implicit (see above)
  SeededRandom random_;
  NodeId cursor_;
  std::uint32_t scanned_ = 0;
};

}  // namespace

void puli_segal(const CubicGraph& graph, Matching& matching, std::uint64_t seed) {
  PuliSegal(graph, matching, seed).run();
}

}  // namespace petersen
