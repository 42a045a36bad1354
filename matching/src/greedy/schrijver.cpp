// Schrijver's perfect matching of a regular bipartite graph (A. Schrijver, "Bipartite edge
// coloring in O(Δm) time", SIAM J. Comput. 28 (1998); Combinatorial Optimization, §18.4), for
// k = 3. Every edge starts with weight 1, so every node's edges weigh 3 in all. While some edge
// weighs 1 or 2 ("fractional"), a walk along fractional edges closes a cycle C; C is even (the
// graph is bipartite), so it splits into alternate edge sets M and N, named so that
// w(M) >= w(N); M gains and N loses α = min over N of w, which keeps every node's sum at 3 and
// takes at least one edge of N to 0. When no edge is fractional, the edges of weight 3 are a
// perfect matching.
//
// Why here: on a bipartite dual (the regular voxel plates) PS leaves its free nodes in patches
// of one colour and the augmentation pays about 0.14 n labels per path (bench/RESULTS.md, "Why
// the trees regrow"); this needs no augmentation at all.
// Cost: each cycle raises Σ w² by 2α(w(M) - w(N)) + α²|C| >= |C|, and Σ w² runs from m = 1.5 n
// (all ones) to 9 · n/2 = 4.5 n (the matching), so the cycles have at most 3 n edges in all. The
// walk keeps its path across cycles (only the cycle is cut off), so every step it takes either
// ends in a cycle or stays on the final path: O(n) steps, no search, no reset.
// An odd cycle cannot be split: the walk stops there and says so, before any matching is
// written, and the caller pairs by PS instead. On a graph that is not bipartite, a walk that
// meets even cycles only still ends with a perfect matching (nothing above needs bipartiteness
// but the splits); on every shared mesh the first odd cycle comes within a few hundred steps.
//
// State, in the table's search slots (one line per node, fresh again on return): `tag` holds the
// weights of the node's three edges, two bits each, in the order of its row, each XORed with 1 so
// that a fresh slot's tag (0) means every edge weighs 1; `link` holds the node's position on the
// walk's path (kNone when off it, as in a fresh slot). After the ordered sweep the state is fresh
// already, so the walk starts at once, and on an odd cycle the nodes it touched get the sweep's
// state back.

#include <algorithm>
#include <vector>

#include "greedy.hpp"
#include "neighbour_table.hpp"

namespace petersen {

namespace {

using augment_detail::kNone;

class Schrijver {
 public:
  Schrijver(NeighbourTable& table, std::pmr::vector<EdgeId>* mate_edge)
      : table_(table), mate_edge_(mate_edge) {}

  // False (mates untouched) when an odd cycle or a loop turned up; the slots' tag and link are
  // then fresh again when they were fresh on entry, else left dirty.
  bool run(bool state_is_fresh) {
    const NodeId n = table_.node_count();
    if (!state_is_fresh) clear_walk_state();
    for (NodeId s = 0; s < n; ++s) {
      if (fractional_edges(s) != 0 && !walk_from(s)) {
        if (state_is_fresh) put_fresh_state_back();
        return false;
      }
    }
    // Every edge weighs 0 or 3 now: the node's weight-3 edge is its matching edge.
    for (NodeId v = 0; v < n; ++v) {
      const std::uint32_t tag = weights(v);
      const int i = (tag & 3) == 3 ? 0 : (tag >> 2 & 3) == 3 ? 1 : 2;
      table_.start_search(v, i);
      const NodeId u = table_.neighbours(v)[i];
      if (mate_edge_ != nullptr && v < u)
        (*mate_edge_)[v] = (*mate_edge_)[u] = table_.graph_edge(3 * EdgeId{v} + i);
    }
    return true;
  }

 private:
  static constexpr std::uint32_t kAllOnes = 0b010101;  // weight 1 on each of the three edges

  // One node of the walk's path: the row indices, at that node, of the edge the walk came in by
  // and of the edge it left by (-1: none yet).
  struct Step {
    NodeId node;
    std::int8_t entered;
    std::int8_t left;
  };

  // Every node's tag and link as in a fresh slot: every edge weighs 1, no node on the path.
  void clear_walk_state() const {
    for (NodeId v = 0; v < table_.node_count(); ++v) clear_walk_state(v);
  }
  void clear_walk_state(NodeId v) const {
    table_.slot(v).tag = 0;
    table_.slot(v).link = kNone;
  }

  // Notes v, just put on the walk's path (the walk changes only such nodes' tags and links), up
  // to kTouchedCap nodes: an odd cycle met within them is undone node by node.
  void touch(NodeId v) {
    if (touched_.size() <= kTouchedCap) touched_.push_back(v);
  }
  void put_fresh_state_back() {
    if (touched_.size() > kTouchedCap) return clear_walk_state();
    for (NodeId v : touched_) clear_walk_state(v);
  }
  // v's three weights, two bits each (the slot stores them XORed with kAllOnes).
  std::uint32_t weights(NodeId v) const { return table_.slot(v).tag ^ kAllOnes; }
  std::uint32_t weight(NodeId v, int i) const { return weights(v) >> (2 * i) & 3; }
  // Bit 2i set when v's i-th edge weighs 1 or 2 (its two bits differ).
  std::uint32_t fractional_edges(NodeId v) const {
    const std::uint32_t tag = weights(v);
    return (tag ^ tag >> 1) & kAllOnes;
  }
  void add(NodeId v, int i, int delta) const {
    table_.slot(v).tag =
        static_cast<std::uint32_t>(static_cast<int>(weights(v)) + (delta << (2 * i))) ^ kAllOnes;
  }

  // The index, in u's row, of the edge that is v's i-th (u = v's i-th neighbour): across
  // parallel edges, the k-th copy in v's row is the k-th in u's.
  int reverse(NodeId v, int i, NodeId u) const {
    const auto from = table_.neighbours(v);
    int copy = 0;
    for (int j = 0; j < i; ++j) copy += from[j] == u;
    const auto to = table_.neighbours(u);
    for (int j = 0; j < 3; ++j) {
      if (to[j] == v && copy-- == 0) return j;
    }
    return -1;  // unreachable on a valid table: v's neighbour u names v back
  }

  // Walks from s until s has no fractional edge left. False on an odd cycle or a loop.
  bool walk_from(NodeId s) {
    path_.assign(1, {s, -1, -1});
    table_.slot(s).link = 0;
    touch(s);
    while (true) {
      Step& top = path_.back();
      const NodeId v = top.node;
      // A fractional edge other than the one the walk came in by: one exists whenever the
      // incoming edge is fractional, since v's three weights sum to 3.
      std::uint32_t choices = fractional_edges(v);
      if (top.entered >= 0) choices &= ~(1u << (2 * top.entered));
      if (choices == 0) {  // only at s: s is done
        table_.slot(s).link = kNone;
        return true;
      }
      const int next = __builtin_ctz(choices) / 2;
      const NodeId u = table_.neighbours(v)[next];
      if (u == v) return false;  // a loop
      // u's row and slot are two misses on the walk's one chain of loads: issued together.
      __builtin_prefetch(table_.neighbours(u).data());
      const std::uint32_t at = table_.slot(u).link;
      top.left = static_cast<std::int8_t>(next);
      const int back = reverse(v, next, u);
      if (at == kNone) {
        table_.slot(u).link = static_cast<std::uint32_t>(path_.size());
        path_.push_back({u, static_cast<std::int8_t>(back), -1});
        touch(u);
        continue;
      }
      // The cycle path_[at..], closed by v's edge `next` back to u: odd means not bipartite.
      if ((path_.size() - at) % 2 != 0) return false;
      cancel(at, back);
      for (std::size_t k = at + 1; k < path_.size(); ++k) table_.slot(path_[k].node).link = kNone;
      path_.resize(at + 1);
    }
  }

  // Moves weight around the cycle path_[at..], closed by the last node's left edge, which is
  // path_[at]'s `closing_back`-th: edges at even places (from path_[at]) form one set, odd
  // places the other; the heavier set gains what the lighter one's lightest edge weighs.
  void cancel(std::size_t at, int closing_back) {
    const std::size_t length = path_.size() - at;
    std::uint32_t sum[2] = {0, 0}, least[2] = {3, 3};
    for (std::size_t k = 0; k < length; ++k) {
      const std::uint32_t w = weight(path_[at + k].node, path_[at + k].left);
      sum[k % 2] += w;
      least[k % 2] = std::min(least[k % 2], w);
    }
    const std::size_t gains = sum[0] >= sum[1] ? 0 : 1;
    const int alpha = static_cast<int>(least[1 - gains]);
    for (std::size_t k = 0; k < length; ++k) {
      const int delta = k % 2 == gains ? alpha : -alpha;
      add(path_[at + k].node, path_[at + k].left, delta);
      if (k + 1 < length) {
        add(path_[at + k + 1].node, path_[at + k + 1].entered, delta);
      } else {
        add(path_[at].node, closing_back, delta);
      }
    }
  }

  NeighbourTable& table_;
  std::pmr::vector<EdgeId>* mate_edge_;  // nullptr: the matching is the table's state only
  std::vector<Step> path_;
  // Up to kTouchedCap + 1 entries, the last meaning "more": the odd cycle comes within a few
  // hundred steps on every shared mesh, where a pass over every slot costs time in proportion to
  // the graph (the 10^8-triangle plate's initial pairing: 2.36-2.38 s so, 2.43-2.51 s with the
  // pass, two alternated runs each).
  static constexpr std::size_t kTouchedCap = std::size_t{1} << 16;
  std::vector<NodeId> touched_;
};

}  // namespace

bool schrijver(NeighbourTable& table, std::pmr::vector<EdgeId>* mate_edge, bool state_is_fresh) {
  return Schrijver(table, mate_edge).run(state_is_fresh);
}

}  // namespace petersen
