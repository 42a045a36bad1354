#pragma once
// Edmonds' primal-dual algorithm for minimum-cost perfect matching, growing the alternating
// trees of all free nodes at once, on the graph renumbered in breadth-first order
// (breadth_first_order.hpp).
//
// Duals are in the odd-cut form (see min_cost_matching.hpp) on doubled costs C(e) = 2·cost(e),
// so every dual stays an integer: every root's dual is made even, tree edges are tight, and all
// labelled blossoms move by the same amount, so all labelled nodes have dual sums of one parity
// and the slack of an edge between two even nodes, which shrinks twice as fast as the others,
// is even.
//
// Blossoms: ids 0..n-1 are the nodes (trivial blossoms), ids n.. the shrunk odd cycles. A
// nontrivial blossom keeps its children in cycle order from its base child c0, and conn[i], the
// edge from child i to child i+1 (mod k), oriented (x in child i, y in child i+1); the edges
// conn[1], conn[3], .. are matched, conn[0], conn[2], .. not.
//
// Finding a node's outermost blossom and its dual sum (every set holding it) walks parents, with
// path compression: each blossom x (nodes included) keeps a shortcut up[x] to an ancestor and the
// duals from x up to it (exclusive), which are frozen while that ancestor lives (only top-level
// blossoms' duals move, and x's chain below it is not top-level). A freed blossom id bumps its
// generation, which invalidates the shortcuts naming it. Shrinking and dissolving so touch no
// node: updating every node of a new blossom made the first version quadratic (60 % of its time
// on the 7k-triangle bunny listed blossom nodes), and plain parent walks without compression
// took 27 % of the time on fertility-sub3, whose blossoms nest deeply.
//
// The forest labels top-level blossoms even or odd (each with its tree) and keeps one clock,
// delta: a labelled blossom's dual is its stored value plus (even) or minus (odd) delta, the
// stored value being offset by the clock when the label is set (an unlabelled blossom stores its
// dual as it is). The priority queue holds when each constraint meets zero: an edge from an even to
// an unlabelled blossom (its slack, at rate 1), an edge between two even blossoms (half its
// slack: a blossom to shrink within a tree, an augmenting path between two trees), an odd
// blossom's dual (to expand it). Entries are not removed when they go stale; each is checked
// when it comes out (the earliest key is never later than the true next event, since every
// event that speeds up is queued again at its new time: a blossom becoming even is scanned, an
// expanded odd blossom's children are scanned, a released tree's parked edges are queued). An
// edge from an even blossom into another tree's odd one waits in that tree's parked list
// instead, until the tree is released.

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <iterator>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "breadth_first_order.hpp"
#include "chain_pool.hpp"
#include "petersen/graph/parallel.hpp"
#include "petersen/matching/augment.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "radix_queue.hpp"

namespace petersen::weighted_detail {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;
/// A sum of up to n costs: n/2 matched edges of up to 2^40 each pass 2^63 from n = 2^24 on.
__extension__ using WideCost = __int128;

class BlossomSolver {
 public:
  BlossomSolver(const BreadthFirstAdjacency& graph, MinCostStats& stats)
      : graph_(graph),
        stats_(stats),
        n_(graph.node_count()),
        ids_(std::size_t{n_} + n_ / 2 + 1),
        rec_(n_),
        base_(n_),
        link_(n_),
        mark_(n_, 0),
        up_(n_) {
    // Blossom ids get their entries when first handed out (new_blossom): reserving leaves the
    // pages untouched, and few of the n/2 ids are ever used (freed ids are reused first), where
    // filling them all up front first-touched 116 bytes per id.
    rec_.reserve(ids_);
    base_.reserve(ids_);
    link_.reserve(ids_);
    mark_.reserve(ids_);
    up_.reserve(ids_);
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
  void greedy_start() {
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
  void augment_tight() {
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

  /// Short single-tree searches before the forest (see short_search), Blossom V's fractional
  /// start (Kolmogorov 2009, section 5.1) with a label budget: a search ends at another free
  /// node or at a node of a half cycle (augmenting), or where a tight edge closes an odd cycle
  /// in its own tree (a half cycle, close_half_cycle), or at its budget. Passes over the free
  /// nodes with a budget per search of 16, 128, 1,024, 8,192 and 65,536; a pass retries only the
  /// roots whose search ran out of budget (one that does often succeeds on a later pass, once
  /// the searches around have moved the duals). The half cycles left at the end each give one
  /// free node, with duals optimal for the matching polytope less its odd-set constraints and
  /// no blossom. Measured (petersen_weighted_speed, stop 24): where stop 23's searches stopped
  /// at a blossom, the forest's roots on the dual of rocker-arm-sub3 1,460 -> 300 (Blossom V's
  /// own count after its start; 676, 780, 98 and 1,524 on the other large meshes, the same as
  /// Blossom V's), its labels 3.60M -> 1.37M, for 10.8M labels of these searches instead of
  /// 9.3M; the solver 1.82 -> 1.00 s. Budgets doubling up to 1,024 left 886 roots there, 807 of
  /// them out of budget; a single pass at 65,536 took 15.5M labels and 1.15 s. With budgets
  /// doubling, 71 % of the searches' labels went to searches that ran out (rocker-arm-sub3's
  /// dual); growing 8x per pass the searches take 8.8M labels (fertility-sub3's 5.6M -> 4.5M)
  /// and leave the same roots; 4x and 16x did about as well.
  ///
  /// The searches run in two parts of the breadth-first numbering, [0, n/2) and [n/2, n), on
  /// `threads` threads (0: every core): a search stops, as at its budget, when it would read a
  /// node of the other part, and hands its root to a last round over the whole graph, after
  /// both parts. The parts share no node, so the result does not depend on the threads.
  void short_searches(std::uint32_t threads) {
    const NodeId half = n_ / 2;
    std::array<ShortPart, 2> parts = {ShortPart{.lo = 0, .hi = half, .stamp = stamp_},
                                      ShortPart{.lo = half, .hi = n_, .stamp = stamp_}};
    for (NodeId v = 0; v < n_; ++v) {
      if (rec_[v].mate.edge == kNoEdge) parts[v < half ? 0 : 1].roots.push_back(v);
    }
    // At most 16 labels a node in all (and one search's budget beyond, in each round): where
    // searches keep running out of budget (free nodes far from any partner or half cycle, which
    // the shared meshes' duals do not have: 2.0-9.7 labels a node there), a free node could cost
    // up to 131,071 labels before the forest takes over.
    run_parallel(threads, 2, [&](std::uint32_t i) {
      short_passes(parts[i], std::uint64_t{16} * (parts[i].hi - parts[i].lo));
    });
    ShortPart whole{.lo = 0, .hi = n_, .stamp = std::max(parts[0].stamp, parts[1].stamp)};
    std::merge(parts[0].handed_over.begin(), parts[0].handed_over.end(),
               parts[1].handed_over.begin(), parts[1].handed_over.end(),
               std::back_inserter(whole.roots));
    const std::uint64_t used = parts[0].labels + parts[1].labels;
    short_passes(whole, std::uint64_t{16} * n_ - std::min(used, std::uint64_t{16} * n_));
    stamp_ = whole.stamp;
    for (const ShortPart* part : {&parts[0], &parts[1], &whole}) {
      stats_.short_labels += part->labels;
      stats_.short_augmentations += part->augmentations;
      stats_.short_half_cycles += part->cycles.size();
      // The half cycles left each become matched edges and one free node, a root of the forest.
      for (NodeId b : part->cycles) {
        if (rec_[b].label == kHalf) break_cycle_at(b);
      }
    }
  }

  /// The nodes left free by the start (greedy_start, augment_tight, short_searches).
  std::uint32_t free_nodes() const {
    std::uint32_t free = 0;
    for (NodeId v = 0; v < n_; ++v) free += rec_[v].mate.edge == kNoEdge;
    return free;
  }

  /// Grows the alternating trees of all free nodes at once until none is left (write_result
  /// gives the matching). Throws GraphError when no event is left while a
  /// tree is: then there is no perfect matching. Out of line, so that a profile (callgrind
  /// --toggle-collect) can single out the search.
  [[gnu::noinline]] void run() {
    // Every root's dual is made even (lowering a free node's dual keeps every constraint), so
    // all labelled nodes share one parity and even-even slacks stay even (see the top).
    std::vector<NodeId> roots;
    for (NodeId v = 0; v < n_; ++v) {
      if (rec_[v].mate.edge != kNoEdge) continue;
      roots.push_back(v);
      rec_[v].y -= rec_[v].y & 1;
    }
    member_heads_.assign(roots.size(), kEnd);
    parked_heads_.assign(roots.size(), kEnd);
    if (roots.size() >= kBothEven) {  // an event's source holds a tree id below 2^31
      throw std::length_error("min-cost matching: " + std::to_string(roots.size()) +
                              " free nodes after the start, at most 2^31 - 1 supported");
    }
    alive_trees_ = roots.size();
    tree_alive_.assign(roots.size(), 1);
    delta_ = 0;
    for (std::uint32_t t = 0; t < roots.size(); ++t) {
      label_even(top(roots[t]), kNone, roots[t], kNoEdge, t);
    }
    while (alive_trees_ > 0) step();
  }

  /// The matching and the dual solution in the input's ids (input node v is node new_node[v]
  /// here); run() must have returned. Returns the matching's total cost, exact: the doubled
  /// graph of min_cost_maximum_matching may take it past 2^63 (n edges of cost up to 2^52), so
  /// the caller decides what it needs of it. O(n + blossoms). Written straight in the input's
  /// order, each node's record requested 16 nodes ahead: on rocker-arm-sub3's dual 27-32 ms,
  /// where a certificate in the solver's order, mapped, then the cost summed at the input's
  /// edges took 40-54 ms (1.4-2.4 ms against 2.0-2.9 on armadillo's).
  [[nodiscard]] WideCost write_result(std::span<const NodeId> new_node,
                                      MinCostResult& result) const {
    MatchingCertificate& c = result.certificate;
    const auto ids = static_cast<std::uint32_t>(rec_.size());  // the blossom ids ever used
    // index[b - n]: blossom b's set in the certificate (a blossom of dual zero has none).
    std::vector<std::uint32_t> index(ids - n_, kNoSet);
    for (std::uint32_t b = n_; b < ids; ++b) {
      if (children_[b - n_].empty() || rec_[b].y == 0) continue;
      index[b - n_] = static_cast<std::uint32_t>(c.set_dual.size());
      c.set_dual.push_back(rec_[b].y);
    }
    // The innermost set holding blossom b (b's own, if it has one): a walk up to a blossom
    // known or with a set (or past the top), whose answer the walked ones take.
    constexpr std::uint32_t kUnknown = kNoSet - 1;
    std::vector<std::uint32_t> holding(ids - n_, kUnknown);
    std::vector<std::uint32_t> chain;
    auto set_holding = [&](std::uint32_t b) {
      chain.clear();
      std::uint32_t found = kNoSet;
      for (std::uint32_t at = b; at != kNone; at = rec_[at].parent) {
        if (holding[at - n_] != kUnknown) {
          found = holding[at - n_];
          break;
        }
        if (index[at - n_] != kNoSet) {
          found = index[at - n_];
          holding[at - n_] = found;
          break;
        }
        chain.push_back(at);
      }
      for (std::uint32_t x : chain) holding[x - n_] = found;
      return found;
    };
    c.set_parent.resize(c.set_dual.size());
    for (std::uint32_t b = n_; b < ids; ++b) {
      if (index[b - n_] == kNoSet) continue;
      const std::uint32_t p = rec_[b].parent;
      c.set_parent[index[b - n_]] = p == kNone ? kNoSet : set_holding(p);
    }
    const auto n = static_cast<std::uint32_t>(new_node.size());
    result.matching = Matching(n);
    c.node_dual.resize(n);
    c.node_set.resize(n);
    for (NodeId v = 0; v < n; ++v) {
      if (v + 16 < n) __builtin_prefetch(&rec_[new_node[v + 16]]);
      const Record& r = rec_[new_node[v]];
      result.matching.mate_edge[v] = r.mate.edge;
      c.node_dual[v] = r.y;
      c.node_set[v] = r.parent == kNone ? kNoSet : set_holding(r.parent);
    }
    // The cost, from each matched edge's slot at its smaller end, in this order (the slots
    // are read in sequence).
    WideCost total = 0;
    for (NodeId v = 0; v < n_; ++v) {
      const Mate m = rec_[v].mate;
      if (m.node < v) continue;
      for (const Slot& slot : slots_of(v)) {
        if (slot.edge == m.edge) {
          total += slot.cost2 / 2;
          break;
        }
      }
    }
    return total;
  }

 private:
  // kHalf: a node on a half-integral odd cycle of the short searches (see short_search), whose
  // mate record then names its successor on the cycle; none is left when the forest starts.
  enum : std::uint8_t { kUnlabelled = 0, kEven = 1, kOdd = 2, kHalf = 3 };
  static constexpr Cost kNoCost = INT64_MAX;

  struct Conn {
    NodeId x, y;  // x in child i, y in child i + 1
    EdgeId e;
  };
  // An edge event carries the edge's ends and doubled cost (checking it then reads no edge
  // array), and its source: the tree of its even end when queued, with kBothEven when the other
  // end was even too (see step). An expand event names its blossom in `id`, and no ends. 24
  // bytes in all: the queue moves them.
  struct Event {
    Cost cost2;
    std::uint32_t id;  // an edge or a blossom
    NodeId u, v;       // kNone: an expand event
    std::uint32_t source;
  };
  static constexpr std::uint32_t kBothEven = 0x80000000u;

  // ---- duals

  [[gnu::always_inline]] std::int64_t current_dual(std::uint32_t b) const {
    switch (rec_[b].label) {
      case kEven:
        return rec_[b].y + delta_;
      case kOdd:
        return rec_[b].y - delta_;
      default:
        return rec_[b].y;
    }
  }
  // v's outermost blossom; the duals of the sets holding v below it go to `below`.
  // Most nodes scanned are their own top-level blossom: that case is inline, without the walk.
  [[gnu::always_inline]] std::uint32_t find(NodeId v, std::int64_t& below) {
    const std::uint32_t p = rec_[v].parent;
    if (p == kNone) [[likely]] {
      below = 0;
      return v;
    }
    // A node right inside a top-level blossom: its own dual is all there is below, and its
    // shortcut (another array, another miss) is not read or written.
    if (rec_[p].parent == kNone) {
      below = rec_[v].y;
      return p;
    }
    return find_nested(v, below);
  }
  [[gnu::noinline]] std::uint32_t find_nested(NodeId v, std::int64_t& below) {
    // Most walks take v's live shortcut to the top or to the blossom just below it: then no
    // shortcut needs writing again.
    if (const Shortcut& up = up_[v]; up.to != kNone && rec_[up.to].generation == up.generation) {
      const std::uint32_t above = rec_[up.to].parent;
      if (above == kNone) {
        below = up.sum;
        return up.to;
      }
      if (rec_[above].parent == kNone) {
        below = up.sum + rec_[up.to].y;
        return above;
      }
    }
    std::uint32_t x = v;
    std::int64_t sum = 0;
    walked_.clear();
    while (rec_[x].parent != kNone) {
      walked_.push_back({x, sum});
      const Shortcut& up = up_[x];
      if (up.to != kNone && rec_[up.to].generation == up.generation) {
        sum += up.sum;
        x = up.to;
      } else {
        sum += rec_[x].y;
        x = rec_[x].parent;
      }
    }
    // The walked nodes but the last point to the last, the one just below the top, not to the
    // top itself: odd blossoms are often expanded one level after another (a nest peeled from
    // outside in), and a shortcut to the top died with each level, so that every later walk went
    // up parent by parent again. On rocker-arm-sub3's dual after short searches with budgets
    // growing 4x per pass: 273M walk steps with shortcuts to the top, 19.8M with these; with
    // the 2x budgets kept, 11.2M -> 9.7M (fertility-sub3's: 2.8M -> 3.8M).
    const auto [last, at_last] = walked_.back();
    up_[last] = {sum - at_last, x, rec_[x].generation};
    for (std::size_t i = 0; i + 1 < walked_.size(); ++i) {
      const auto [w, at] = walked_[i];
      up_[w] = {at_last - at, last, rec_[last].generation};
    }
    below = sum;
    return x;
  }
  std::uint32_t top(NodeId v) {
    std::int64_t below;
    return find(v, below);
  }

  // Stores b's current dual as it is; the caller unlabels b.
  void settle(std::uint32_t b) { rec_[b].y = current_dual(b); }

  // ---- the queue

  void push_edge(std::int64_t key, const Slot& slot, NodeId from, std::uint32_t source) {
    queue_.push(static_cast<std::uint64_t>(key), {slot.cost2, slot.edge, from, slot.other, source});
    ++stats_.queue_pushes;
  }
  void push_expand(std::int64_t key, std::uint32_t b) {
    queue_.push(static_cast<std::uint64_t>(key), {0, b, kNone, kNone, kNone});
    ++stats_.queue_pushes;
  }
  std::span<const Slot> slots_of(NodeId v) const { return graph_.slots_of(v); }

  // ---- blossom structure

  // Appends the nodes of blossom b to out.
  void leaves(std::uint32_t b, std::vector<NodeId>& out) const {
    if (b < n_) {
      out.push_back(b);
      return;
    }
    std::vector<std::uint32_t>& stack = leaf_stack_;
    stack.assign(1, b);
    while (!stack.empty()) {
      const std::uint32_t c = stack.back();
      stack.pop_back();
      if (c < n_) {
        out.push_back(c);
      } else {
        for (std::uint32_t d : children_[c - n_]) stack.push_back(d);
      }
    }
  }

  // The child of blossom b that holds node v.
  std::uint32_t child_holding(std::uint32_t b, NodeId v) const {
    std::uint32_t c = v;
    while (rec_[c].parent != b) c = rec_[c].parent;
    return c;
  }

  // A freed id if there is one (the last freed first), else the next fresh one, whose entries
  // are appended here (the arrays hold ids_ without reallocating: see the constructor).
  std::uint32_t new_blossom() {
    if (free_ids_.empty()) {
      const auto b = static_cast<std::uint32_t>(rec_.size());
      rec_.emplace_back();
      base_.push_back(0);
      link_.emplace_back();
      mark_.push_back(0);
      up_.emplace_back();
      children_.emplace_back();
      conn_.emplace_back();
      return b;
    }
    const std::uint32_t b = free_ids_.back();
    free_ids_.pop_back();
    return b;
  }
  void free_blossom(std::uint32_t b) {
    children_[b - n_].clear();
    conn_[b - n_].clear();
    rec_[b].label = kUnlabelled;
    rec_[b].parent = kNone;
    rec_[b].y = 0;
    ++rec_[b].generation;
    free_ids_.push_back(b);
  }

  // ---- labels

  // Labels unlabelled b without scanning it (the caller scans once every label around is set).
  void set_label(std::uint32_t b, std::uint8_t label, NodeId from, NodeId to, EdgeId e,
                 std::uint32_t tree) {
    rec_[b].label = label;
    rec_[b].y += label == kEven ? -delta_ : delta_;  // so that current_dual(b) is unchanged
    link_[b] = {from, to, e};
    rec_[b].tree = tree;
    members_.push(member_heads_[tree], b);
    ++stats_.nodes_labelled;
  }
  void label_even(std::uint32_t b, NodeId from, NodeId to, EdgeId e, std::uint32_t tree) {
    set_label(b, kEven, from, to, e, tree);
    scan_even(b);
  }
  void label_odd(std::uint32_t b, NodeId from, NodeId to, EdgeId e, std::uint32_t tree) {
    set_label(b, kOdd, from, to, e, tree);
    if (b >= n_) push_expand(delta_ + current_dual(b), b);
  }

  // Queues every edge from the nodes of blossom b (now even, b itself or inside the even blossom
  // just shrunk) to an even or unlabelled blossom. Lists b's
  // nodes: per-blossom lists of leaving edges, merged on shrink, were 5x slower on armadillo's
  // dual (a blossom of a cubic graph has about as many leaving edges as nodes).
  void scan_even(std::uint32_t b) {
    // Most blossoms turning even are single nodes: scanned without listing leaves (the list's
    // push_back was 5 % of the solver's instructions on armadillo's dual, callgrind).
    if (b < n_) {
      ++stats_.even_scans;
      scan_even_node(b);
      return;
    }
    scratch_.clear();
    leaves(b, scratch_);
    stats_.even_scans += scratch_.size();
    for (NodeId x : scratch_) scan_even_node(x);
  }
  void scan_even_node(NodeId x) {
    std::int64_t below_x, below_w;
    const std::uint32_t bx = find(x, below_x);
    const std::int64_t room = -below_x - current_dual(bx);  // the slack less 2·cost
    // The neighbours' records are requested together: each is a likely cache miss, and the
    // loop below would otherwise wait for them one at a time. A node's mate, which a grow into
    // an unlabelled neighbour reads next, is in its record.
    for (const Slot& slot : slots_of(x)) __builtin_prefetch(&rec_[slot.other]);
    for (const Slot& slot : slots_of(x)) {
      const std::uint32_t bw = find(slot.other, below_w);
      if (bw == bx) continue;
      if (rec_[bw].label == kOdd) {
        if (rec_[bw].tree != rec_[bx].tree)
          parked_.push(parked_heads_[rec_[bw].tree],
                       {slot.cost2, slot.edge, x, slot.other, rec_[bx].tree});
        continue;
      }
      const std::int64_t s = slot.cost2 + room - below_w - current_dual(bw);
      if (rec_[bw].label == kEven) {
        push_edge(delta_ + s / 2, slot, x, rec_[bx].tree | kBothEven);
      } else {
        push_edge(delta_ + s, slot, x, rec_[bx].tree);
      }
    }
  }

  // Queues every edge from (now unlabelled) blossom b to an even blossom.
  void scan_unlabelled(std::uint32_t b) {
    scratch_.clear();
    leaves(b, scratch_);
    stats_.released_scans += scratch_.size();
    for (NodeId x : scratch_) {
      std::int64_t below_x, below_w;
      const std::uint32_t bx = find(x, below_x);
      const std::int64_t room = -below_x - current_dual(bx);  // the slack less 2·cost
      for (const Slot& slot : slots_of(x)) {
        const std::uint32_t bw = find(slot.other, below_w);
        if (rec_[bw].label != kEven) continue;
        push_edge(delta_ + slot.cost2 + room - below_w - current_dual(bw), slot, x, rec_[bw].tree);
      }
    }
  }

  // ---- short searches

  struct ShortEvent {
    std::int64_t key;  // the search's clock when the edge turns tight
    Cost cost2;
    EdgeId edge;
    NodeId u, w;  // u even
    bool operator>(const ShortEvent& other) const { return key > other.key; }
  };
  // The short searches of one part of the nodes, [lo, hi): its roots (free nodes, in id order),
  // its own search stamp, heap and labels. Only its searches read or write its nodes' records,
  // marks and links.
  struct ShortPart {
    NodeId lo = 0, hi = 0;
    std::uint32_t stamp = 0;            // mark_[v] == stamp: v is labelled in the current search
    std::vector<NodeId> roots{};        // free nodes, in id order
    std::vector<NodeId> handed_over{};  // roots whose search met a node of another part
    std::vector<ShortEvent> heap{};
    std::vector<NodeId> labelled{};
    std::vector<NodeId> cycles{};  // a node of each half cycle closed (some since broken)
    std::uint64_t labels = 0, augmentations = 0;
  };
  enum class ShortEnd : std::uint8_t { done, budget, other_part };

  // Passes over part.roots with budgets 16, 128, .., kMostBudget (see short_searches), until
  // the part's searches have given `most` labels.
  static constexpr std::uint32_t kMostBudget = 65536;
  void short_passes(ShortPart& part, std::uint64_t most) {
    for (std::uint32_t budget = 16; budget <= kMostBudget && !part.roots.empty(); budget *= 8) {
      std::size_t left = 0;
      for (NodeId r : part.roots) {
        if (part.labels >= most) break;              // the forest takes the rest
        if (rec_[r].mate.edge != kNoEdge) continue;  // matched by an earlier search
        switch (short_search(part, r, budget)) {
          case ShortEnd::done:
            break;
          case ShortEnd::budget:
            part.roots[left++] = r;
            break;
          case ShortEnd::other_part:
            part.handed_over.push_back(r);
            break;
        }
      }
      part.roots.resize(left);
    }
  }

  // One primal-dual search from free node `root` alone, on trivial blossoms only (it runs
  // before the forest, when there are no others): even nodes gain and odd nodes lose the
  // search's clock eps, the next event from a small binary heap. It augments at the first tight
  // edge to another free node or to a node of a half cycle, which it breaks (done); a tight edge
  // between two of its even nodes closes a half cycle (done); it stops without augmenting once
  // `budget` nodes are labelled (budget), or when it would read a node outside the part
  // (other_part). Half cycles are never labelled, and those a part's searches close lie in the
  // part. Stopping anywhere leaves the duals feasible and every matched, half-matched and tree
  // edge tight (every constraint that eps tightens has its entry in the heap, and eps never
  // passes the least; a node just labelled even stops the search before eps moves if one of its
  // edges leaves the part), so the forest starts from wherever the searches stopped.
  ShortEnd short_search(ShortPart& part, NodeId root, std::uint32_t budget) {
    const std::uint32_t stamp = ++part.stamp;
    part.heap.clear();
    part.labelled.clear();
    std::int64_t eps = 0;
    ShortEnd end = ShortEnd::done;
    std::optional<ShortEvent> closing;
    // An even root makes every even node's dual of one parity, so that an edge between two even
    // nodes turns tight at a whole clock (lowering a free node's dual keeps every constraint).
    rec_[root].y -= rec_[root].y & 1;
    auto in_tree = [&](NodeId v) { return mark_[v] == stamp; };
    // As in the forest, a labelled node stores y - eps (even) or y + eps (odd) from its label on.
    auto dual = [&](NodeId v) {
      if (!in_tree(v)) return rec_[v].y;
      return rec_[v].label == kEven ? rec_[v].y + eps : rec_[v].y - eps;
    };
    auto label = [&](NodeId v, std::uint8_t l) {
      mark_[v] = stamp;
      rec_[v].label = l;
      rec_[v].y += l == kEven ? -eps : eps;
      part.labelled.push_back(v);
      ++part.labels;
    };
    // False, pushing nothing, when one of u's edges leaves the part.
    auto scan = [&](NodeId u) {
      const std::span<const Slot> slots = slots_of(u);
      for (const Slot& slot : slots) {
        if (slot.other < part.lo || slot.other >= part.hi) return false;
      }
      const std::int64_t yu = dual(u);
      for (const Slot& slot : slots) {
        const NodeId w = slot.other;
        const bool labelled = in_tree(w);
        if (w == u || (labelled && rec_[w].label == kOdd)) continue;
        const std::int64_t s = slot.cost2 - yu - dual(w);
        part.heap.push_back({eps + (labelled ? s / 2 : s), slot.cost2, slot.edge, u, w});
        std::push_heap(part.heap.begin(), part.heap.end(), std::greater<>());
      }
      return true;
    };
    label(root, kEven);
    if (!scan(root)) end = ShortEnd::other_part;
    while (end == ShortEnd::done && !part.heap.empty()) {
      std::pop_heap(part.heap.begin(), part.heap.end(), std::greater<>());
      const ShortEvent event = part.heap.back();
      part.heap.pop_back();
      eps = event.key;
      const NodeId u = event.u, w = event.w;
      if (in_tree(w)) {
        if (rec_[w].label == kOdd) continue;                 // its slack no longer moves
        if (event.cost2 - dual(u) - dual(w) != 0) continue;  // keyed when w was unlabelled
        closing = event;                                     // a half cycle
        break;
      }
      if (rec_[w].label == kHalf) break_cycle_at(w);
      if (rec_[w].mate.edge == kNoEdge) {
        // Flip the path from u to the root; (u, w) and every tree edge on it are tight.
        NodeId at = u, across = w;
        EdgeId along = event.edge;
        for (;;) {
          const Mate old = rec_[at].mate;
          rec_[at].mate = {along, across};
          rec_[across].mate = {along, at};
          if (old.edge == kNoEdge) break;  // the root
          along = link_[old.node].edge;
          across = old.node;
          at = link_[old.node].from;
        }
        ++part.augmentations;
        break;
      }
      if (part.labelled.size() >= budget) {
        end = ShortEnd::budget;
        break;
      }
      // w is matched, and so is its mate z, unlabelled (labels come in matched pairs). w is in
      // the part (u's scan found every end of u's edges inside), z need not be.
      const NodeId z = rec_[w].mate.node;
      if (z < part.lo || z >= part.hi) {
        end = ShortEnd::other_part;
        break;
      }
      link_[w] = {u, w, event.edge};
      label(w, kOdd);
      label(z, kEven);
      if (!scan(z)) end = ShortEnd::other_part;
    }
    for (NodeId v : part.labelled) {
      rec_[v].y = dual(v);
      rec_[v].label = kUnlabelled;
    }
    if (closing) close_half_cycle(part, root, *closing);
    return end;
  }

  // The tight edge (u, w) joins two even nodes of root's search: flips the path from the root to
  // their lowest common ancestor b and makes the odd cycle b .. u w .. b a half cycle, each of
  // its edges matched by a half (Blossom V's fractional start, Kolmogorov 2009, section 5.1):
  // the root is covered, every node of the cycle by two halves, and the duals stay optimal for
  // the matching polytope without its odd-set constraints. The cycle's nodes are marked kHalf,
  // each one's mate record naming its successor; a later search reaching one breaks the cycle
  // (break_cycle_at), and short_searches breaks those left at its end, each leaving one free
  // node. The search's tree edges are still in link_ and the nodes' mates.
  void close_half_cycle(ShortPart& part, NodeId root, const ShortEvent& closing) {
    const NodeId u = closing.u, w = closing.w;
    const std::uint32_t stamp = ++part.stamp;
    auto parent = [&](NodeId z) { return link_[rec_[z].mate.node].from; };  // z even, not root
    for (NodeId z = u;; z = parent(z)) {
      mark_[z] = stamp;
      if (z == root) break;
    }
    NodeId b = w;
    while (mark_[b] != stamp) b = parent(b);
    if (b != root) {  // the stem: each odd node takes its tree parent as mate
      NodeId odd = rec_[b].mate.node;
      for (;;) {
        const TreeLink link = link_[odd];
        const Mate old = rec_[link.from].mate;
        rec_[odd].mate = {link.edge, link.from};
        rec_[link.from].mate = {link.edge, odd};
        if (old.edge == kNoEdge) break;  // the root
        odd = old.node;
      }
    }
    // w's side runs up to b (each even node's successor is its mate already), u's side down
    // from b, then (u, w) closes the cycle.
    for (NodeId z = w; z != b;) {
      const NodeId odd = rec_[z].mate.node;
      rec_[odd].mate = {link_[odd].edge, link_[odd].from};
      z = link_[odd].from;
    }
    Mate below = rec_[u].mate;
    for (NodeId z = u; z != b;) {
      const NodeId odd = below.node, up = link_[odd].from;
      const Mate next = rec_[up].mate;
      rec_[odd].mate = {below.edge, z};
      rec_[up].mate = {link_[odd].edge, odd};
      z = up;
      below = next;
    }
    rec_[u].mate = {closing.edge, w};
    NodeId at = b;
    do {
      rec_[at].label = kHalf;
      at = rec_[at].mate.node;
    } while (at != b);
    part.cycles.push_back(b);
  }

  // Breaks w's half cycle: the path of the others, from w's successor round to its predecessor,
  // is matched in pairs of whole edges, and w is left to the caller, without a mate.
  void break_cycle_at(NodeId w) {
    NodeId at = rec_[w].mate.node;
    while (at != w) {
      const Mate next = rec_[at].mate;
      const NodeId after = rec_[next.node].mate.node;
      rec_[next.node].mate = {next.edge, at};
      rec_[at].label = rec_[next.node].label = kUnlabelled;
      at = after;
    }
    rec_[w].label = kUnlabelled;
    rec_[w].mate = {};
  }

  // ---- the forest

  // Takes the next event from the queue and acts on it.
  void step() {
    if (queue_.empty()) {
      throw GraphError("no perfect matching: " + std::to_string(alive_trees_) +
                       " alternating trees cannot grow");
    }
    Event event;
    const auto key = static_cast<std::int64_t>(queue_.pop(event));
    if (key > delta_) {
      delta_ = key;
      ++stats_.dual_updates;
    }
    if (event.u == kNone) {
      const std::uint32_t b = event.id;
      if (rec_[b].label != kOdd || rec_[b].parent != kNone) return;
      const std::int64_t d = current_dual(b);
      if (d > 0) {
        push_expand(delta_ + d, b);
      } else {
        expand_odd(b);
      }
      return;
    }
    // Queued from an even end to a node then not even, and that end's tree released since: the
    // event is stale, dropped without reading either end's record (a likely cache miss each).
    // Were the edge to matter again, another event covers it: an end labelled even again is
    // scanned again, and the other end, if labelled even while the first one was, queued its
    // own event (with kBothEven: such an event is kept, as its other end may still be even,
    // its edge now losing slack at rate 1 instead of 2 and its key too late).
    if ((event.source & kBothEven) == 0 && !tree_alive_[event.source]) return;
    const EdgeId e = event.id;
    NodeId u = event.u, v = event.v;
    std::int64_t below_u, below_v;
    std::uint32_t bu = find(u, below_u), bv = find(v, below_v);
    if (bu == bv) return;
    if (rec_[bu].label != kEven) {
      std::swap(u, v);
      std::swap(bu, bv);
      std::swap(below_u, below_v);
    }
    if (rec_[bu].label != kEven) return;
    if (rec_[bv].label == kOdd) {
      if (rec_[bv].tree != rec_[bu].tree) {
        event.source = rec_[bu].tree;
        parked_.push(parked_heads_[rec_[bv].tree], event);
      }
      return;
    }
    const std::int64_t s = event.cost2 - below_u - current_dual(bu) - below_v - current_dual(bv);
    if (rec_[bv].label == kEven) {
      if (s > 0) {
        event.source = rec_[bu].tree | kBothEven;
        queue_.push(static_cast<std::uint64_t>(delta_ + s / 2), event);
        ++stats_.queue_pushes;
      } else if (rec_[bu].tree == rec_[bv].tree) {
        shrink(u, v, e);
      } else {
        const std::uint32_t tu = rec_[bu].tree, tv = rec_[bv].tree;
        augment_from(u, e, v);
        augment_from(v, e, u);
        ++stats_.searches;
        release(tu);
        release(tv);
      }
    } else if (s > 0) {
      event.source = rec_[bu].tree;
      queue_.push(static_cast<std::uint64_t>(delta_ + s), event);
      ++stats_.queue_pushes;
    } else {
      // Every free node is a root, so an unlabelled blossom has a matched base.
      const NodeId b = bv < n_ ? bv : base_[bv];
      const EdgeId m = rec_[b].mate.edge;
      const NodeId z = rec_[b].mate.node;
      label_odd(bv, u, v, e, rec_[bu].tree);
      label_even(top(z), b, z, m, rec_[bu].tree);
    }
  }

  // Tree t augmented: its blossoms store their duals and lose their labels. The edges from
  // the even blossoms of other trees into its odd blossoms (whose slack did not move) now lose
  // slack at rate 1: they were parked with t when met (by a scan or coming out of the queue)
  // and are queued now, to be keyed when they come out. Scanning t's odd blossoms for them
  // instead read every neighbour of half of t's nodes (1.9M node scans on fertility-sub3's
  // dual, most of whose neighbours lie in t itself). The entries into
  // its even blossoms, keyed at rate 2, come out early and are queued again at rate 1 (scanning
  // the even ones too cost 4.1M node scans on fertility-sub3's dual, half of all). The blossoms
  // whose dual is zero dissolve: they constrain nothing.
  void release(std::uint32_t t) {
    --alive_trees_;
    tree_alive_[t] = 0;
    members_.drain(member_heads_[t], [&](std::uint32_t b) {
      if (rec_[b].label == kUnlabelled || rec_[b].parent != kNone || rec_[b].tree != t) return;
      settle(b);
      rec_[b].label = kUnlabelled;
      if (b >= n_ && rec_[b].y == 0) dissolvable_.push_back(b);  // nodes are most members
    });
    parked_.drain(parked_heads_[t], [&](const Event& event) {
      queue_.push(static_cast<std::uint64_t>(delta_), event);
      ++stats_.queue_pushes;
    });
    for (std::uint32_t b : dissolvable_) {
      if (rec_[b].parent == kNone && !children_[b - n_].empty()) dissolve(b);
    }
    dissolvable_.clear();
  }

  // Removes top-level unlabelled blossom b of dual zero, and its children of dual zero.
  void dissolve(std::uint32_t b) {
    std::vector<std::uint32_t>& stack = dissolve_stack_;
    stack.assign(1, b);
    while (!stack.empty()) {
      const std::uint32_t c = stack.back();
      stack.pop_back();
      for (std::uint32_t d : children_[c - n_]) {
        rec_[d].parent = kNone;
        if (d >= n_ && rec_[d].y == 0) stack.push_back(d);
      }
      free_blossom(c);
      ++stats_.blossoms_expanded;
    }
  }

  // Edge e = (u, v) joins two even blossoms of the tree: shrink the cycle through their nearest
  // common even ancestor into a new even blossom.
  void shrink(NodeId u, NodeId v, EdgeId e) {
    ++stats_.blossoms_shrunk;
    const std::uint32_t bu = top(u), bv = top(v);
    // Walk up from both sides alternately; the first blossom seen twice is the common one.
    ++stamp_;
    std::uint32_t a = bu, c = bv, lca = kNone;
    while (lca == kNone) {
      if (a != kNone) {
        if (mark_[a] == stamp_) {
          lca = a;
          break;
        }
        mark_[a] = stamp_;
        a = link_[a].edge == kNoEdge ? kNone : top(link_[top(link_[a].from)].from);
      }
      std::swap(a, c);
    }
    path_u_.clear();
    path_v_.clear();
    for (std::uint32_t x = bu; x != lca; x = top(link_[x].from)) path_u_.push_back(x);
    for (std::uint32_t x = bv; x != lca; x = top(link_[x].from)) path_v_.push_back(x);

    const std::uint32_t nb = new_blossom();
    std::vector<std::uint32_t>& ch = children_[nb - n_];
    std::vector<Conn>& conn = conn_[nb - n_];
    ch.reserve(1 + path_u_.size() + path_v_.size());
    conn.reserve(ch.capacity());
    ch.push_back(lca);
    for (std::size_t i = path_u_.size(); i-- > 0;) {
      const std::uint32_t x = path_u_[i];
      conn.push_back({link_[x].from, link_[x].to, link_[x].edge});
      ch.push_back(x);
    }
    conn.push_back({u, v, e});
    for (std::uint32_t x : path_v_) {
      ch.push_back(x);
      conn.push_back({link_[x].to, link_[x].from, link_[x].edge});
    }

    base_[nb] = base_[lca];
    rec_[nb].parent = kNone;
    rec_[nb].y = -delta_;  // a dual of zero, even from now on
    rec_[nb].label = kEven;
    link_[nb] = link_[lca];
    rec_[nb].tree = rec_[lca].tree;
    members_.push(member_heads_[rec_[lca].tree], nb);

    odd_children_.clear();
    for (std::uint32_t c2 : ch) {
      const bool was_odd = rec_[c2].label == kOdd;
      settle(c2);
      rec_[c2].label = kUnlabelled;
      rec_[c2].parent = nb;
      if (was_odd) odd_children_.push_back(c2);
    }
    for (std::uint32_t c2 : odd_children_) scan_even(c2);
  }

  // Odd blossom b's dual reached zero: its children along the even side of the cycle, from the
  // one the tree enters by to the base, take b's place in the tree; the others become unlabelled.
  void expand_odd(std::uint32_t b) {
    ++stats_.blossoms_expanded;
    // The cycle is swapped out into scratch vectors, which hand their (cleared) buffers to the
    // freed id: moving it out left the id without capacity, and shrink's pushes into it
    // reallocated (malloc, free and the copies: 4 % of the instructions, armadillo's dual).
    std::vector<std::uint32_t>& ch = expand_children_;
    std::vector<Conn>& conn = expand_conn_;
    ch.clear();
    conn.clear();
    ch.swap(children_[b - n_]);
    conn.swap(conn_[b - n_]);
    const std::size_t k = ch.size();
    const std::uint32_t entry = child_holding(b, link_[b].to);
    for (std::uint32_t c : ch) rec_[c].parent = kNone;
    const std::size_t j =
        static_cast<std::size_t>(std::find(ch.begin(), ch.end(), entry) - ch.begin());
    const auto [from, to, edge] = link_[b];
    const std::uint32_t tree = rec_[b].tree;
    free_blossom(b);

    // The path from the entry child to the base child: backward when j is even, else forward.
    ++stamp_;
    std::vector<std::uint32_t>& even_children = even_children_;
    even_children.clear();
    std::size_t i = j;
    mark_[ch[i]] = stamp_;
    label_odd(ch[i], from, to, edge, tree);
    bool next_even = true;
    while (i != 0) {
      std::size_t next;
      Conn c;
      if (j % 2 == 0) {
        next = i - 1;
        c = {conn[next].y, conn[next].x, conn[next].e};  // x on the side of ch[i]
      } else {
        next = (i + 1) % k;
        c = conn[i];
      }
      // c.x is in ch[i] (the tree parent), c.y in ch[next].
      mark_[ch[next]] = stamp_;
      if (next_even) {
        set_label(ch[next], kEven, c.x, c.y, c.e, tree);
        even_children.push_back(ch[next]);
      } else {
        label_odd(ch[next], c.x, c.y, c.e, tree);
      }
      next_even = !next_even;
      i = next;
    }
    for (std::uint32_t c : even_children) scan_even(c);
    for (std::uint32_t c : ch)
      if (mark_[c] != stamp_) scan_unlabelled(c);
  }

  // ---- augmentation

  void set_mate(NodeId v, EdgeId e, NodeId w) { rec_[v].mate = {e, w}; }

  // Edge `along` joins even node s to node `across` in another tree: flips the path from s up
  // to its root.
  void augment_from(NodeId s, EdgeId along, NodeId across) {
    for (;;) {
      const std::uint32_t bs = top(s);
      rebase(bs, s);
      set_mate(s, along, across);
      if (link_[bs].edge == kNoEdge) break;  // the root
      const std::uint32_t bt = top(link_[bs].from);
      rebase(bt, link_[bt].to);
      set_mate(link_[bt].to, link_[bt].edge, link_[bt].from);
      s = link_[bt].from;
      along = link_[bt].edge;
      across = link_[bt].to;
    }
  }

  // Makes node v the base of blossom b, flipping the matched edges on the even side of each
  // cycle between v's child and the base child, level by level (an explicit stack of (blossom,
  // node) to rebase). Each entry walks once from its node up to its blossom and rebases every
  // level of that walk, top down, the child holding the node being the blossom one step below:
  // finding that child afresh at each level walked the nested blossoms again from the node
  // (fertility-sub3's dual nests over 100 deep).
  void rebase(std::uint32_t b, NodeId v) {
    if (b < n_) return;
    rebase_stack_.assign(1, {b, v});
    while (!rebase_stack_.empty()) {
      const auto [outer, node] = rebase_stack_.back();
      rebase_stack_.pop_back();
      rebase_chain_.clear();
      for (std::uint32_t x = node; x != outer; x = rec_[x].parent) rebase_chain_.push_back(x);
      rebase_chain_.push_back(outer);
      for (std::size_t level = rebase_chain_.size() - 1; level > 0; --level) {
        const std::uint32_t blossom = rebase_chain_[level], c = rebase_chain_[level - 1];
        std::vector<std::uint32_t>& ch = children_[blossom - n_];
        std::vector<Conn>& conn = conn_[blossom - n_];
        const std::size_t k = ch.size();
        const std::size_t j =
            static_cast<std::size_t>(std::find(ch.begin(), ch.end(), c) - ch.begin());
        auto match = [&](std::size_t i) {
          const Conn& cn = conn[i];
          rec_[cn.x].mate = {cn.e, cn.y};
          rec_[cn.y].mate = {cn.e, cn.x};
          if (ch[i] >= n_) rebase_stack_.push_back({ch[i], cn.x});
          const std::uint32_t d = ch[(i + 1) % k];
          if (d >= n_) rebase_stack_.push_back({d, cn.y});
        };
        if (j % 2 == 0) {
          for (std::size_t i = 0; i + 1 < j; i += 2) match(i);
        } else {
          for (std::size_t i = j + 1; i < k; i += 2) match(i);
        }
        std::rotate(ch.begin(), ch.begin() + static_cast<std::ptrdiff_t>(j), ch.end());
        std::rotate(conn.begin(), conn.begin() + static_cast<std::ptrdiff_t>(j), conn.end());
        base_[blossom] = node;
      }
    }
  }

  const BreadthFirstAdjacency& graph_;
  // A node's matched edge and the node across it (the grow step reads both at once).
  struct Mate {
    EdgeId edge = kNoEdge;
    NodeId node = kNone;
  };
  MinCostStats& stats_;
  std::uint32_t n_;
  std::size_t ids_;  // the most ids: n nodes and n/2 blossoms (the arrays below are reserved so)
  // What finding a blossom and its current dual reads, in one cache line's half: the stored
  // dual y (offset by the clock while labelled, see the top), the parent blossom (kNone at the
  // top level), the tree of a labelled blossom, the generation its shortcuts are checked
  // against, the label, and a node's mate, which growing into an unlabelled node reads right
  // after its record. Separate arrays cost a cache miss each per neighbour scanned.
  struct alignas(32) Record {
    std::int64_t y = 0;
    std::uint32_t parent = kNone;
    std::uint32_t tree = kNone;
    std::uint32_t generation = 0;  // bumped when the blossom id is freed (see the top)
    Mate mate;                     // nodes only
    std::uint8_t label = kUnlabelled;
  };
  HugeVector<Record> rec_;
  HugeVector<NodeId> base_;
  // A labelled blossom's tree edge: `from` in the tree parent, `to` in this blossom; one record,
  // as labelling writes the three together and the walks up the tree read them together.
  struct TreeLink {
    NodeId from = kNone;
    NodeId to = kNone;
    EdgeId edge = kNoEdge;
  };
  HugeVector<TreeLink> link_;
  HugeVector<std::uint32_t> mark_;
  // The shortcuts (see the top): x's ancestor `to`, valid while to's generation is `generation`,
  // and the duals from x up to it; one record, read together on every walk.
  struct Shortcut {
    std::int64_t sum = 0;
    std::uint32_t to = kNone;
    std::uint32_t generation = 0;
  };
  HugeVector<Shortcut> up_;
  std::vector<std::pair<std::uint32_t, std::int64_t>> walked_;
  std::uint32_t stamp_ = 0;
  std::vector<std::vector<std::uint32_t>> children_;
  std::vector<std::vector<Conn>> conn_;
  std::vector<std::uint32_t> free_ids_;
  std::int64_t delta_ = 0;
  RadixQueue<Event> queue_;
  // Per tree: the blossoms labelled in it, and the edges from other trees' even blossoms into its
  // odd ones (see release); lists in two pools, the heads by tree.
  static constexpr std::uint32_t kEnd = ChainPool<std::uint32_t>::kEnd;
  ChainPool<std::uint32_t> members_;
  std::vector<std::uint32_t> member_heads_;
  ChainPool<Event> parked_;
  std::vector<std::uint32_t> parked_heads_;
  std::size_t alive_trees_ = 0;
  std::vector<std::uint8_t> tree_alive_;    // by tree: 0 once released
  std::vector<std::uint32_t> dissolvable_;  // release: its blossoms of dual zero
  std::vector<NodeId> scratch_;
  std::vector<std::uint32_t> odd_children_;
  std::vector<std::uint32_t> dissolve_stack_, expand_children_, even_children_;
  std::vector<Conn> expand_conn_;
  std::vector<std::uint32_t> path_u_, path_v_;
  mutable std::vector<std::uint32_t> leaf_stack_;
  std::vector<std::pair<std::uint32_t, NodeId>> rebase_stack_;
  std::vector<std::uint32_t> rebase_chain_;
};

}  // namespace petersen::weighted_detail
