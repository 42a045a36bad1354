#pragma once
// Edmonds' primal-dual algorithm for minimum-cost perfect matching, growing the alternating
// trees of all free nodes at once, on any Graph with incident_edges(v), other_end(e, v) and
// endpoints(e).
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
// delta: a labelled blossom's dual is its stored value plus (even) or minus (odd) the time since
// its label. The priority queue holds when each constraint meets zero: an edge from an even to
// an unlabelled blossom (its slack, at rate 1), an edge between two even blossoms (half its
// slack: a blossom to shrink within a tree, an augmenting path between two trees), an odd
// blossom's dual (to expand it). Entries are not removed when they go stale; each is checked
// when it comes out (the earliest key is never later than the true next event, since every
// event that speeds up is queued again at its new time: a blossom becoming even is scanned, an
// expanded odd blossom's children are scanned, a released tree's odd blossoms are scanned).

#include <algorithm>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "petersen/matching/augment.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "radix_queue.hpp"

namespace petersen::weighted_detail {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

template <class Graph>
class BlossomSolver {
 public:
  BlossomSolver(const Graph& graph, std::span<const Cost> costs, HugeVector<EdgeId>& mate,
                MinCostStats& stats)
      : graph_(graph),
        cost_(costs),
        mate_(mate),
        stats_(stats),
        n_(graph.node_count()),
        ids_(std::size_t{n_} + n_ / 2 + 1),
        y_(ids_, 0),
        since_(ids_, 0),
        label_(ids_, kUnlabelled),
        parent_(ids_, kNone),
        base_(ids_),
        tree_from_(ids_, kNone),
        tree_to_(ids_, kNone),
        tree_edge_(ids_, kNoEdge),
        tree_(ids_, kNone),
        mark_(ids_, 0),
        generation_(ids_, 0),
        up_(ids_, kNone),
        up_generation_(ids_, 0),
        up_sum_(ids_, 0),
        children_(ids_ - n_),
        conn_(ids_ - n_) {
    mate_.assign(n_, kNoEdge);
    for (NodeId v = 0; v < n_; ++v) base_[v] = v;
    for (std::uint32_t b = static_cast<std::uint32_t>(ids_); b-- > n_;) free_ids_.push_back(b);
    // y_v = the cheapest cost at v (C/2): feasible whatever the signs of the costs.
    for (NodeId v = 0; v < n_; ++v) {
      if (graph_.incident_edges(v).empty())
        throw GraphError("node " + std::to_string(v) + " has no edge: no perfect matching");
      Cost cheapest = kNoCost;
      for (EdgeId e : graph_.incident_edges(v)) cheapest = std::min(cheapest, cost_[e]);
      y_[v] = cheapest;
    }
  }

  /// Blossom V's greedy start: each free node in id order raises y_v by its smallest slack and
  /// takes a tight edge to a free neighbour; then augment_tight.
  void greedy_start() {
    for (NodeId v = 0; v < n_; ++v) {
      if (mate_[v] != kNoEdge) continue;
      Cost least = kNoCost;
      for (EdgeId e : graph_.incident_edges(v)) {
        least = std::min(least, 2 * cost_[e] - y_[v] - y_[graph_.other_end(e, v)]);
      }
      y_[v] += least;
      for (EdgeId e : graph_.incident_edges(v)) {
        const NodeId w = graph_.other_end(e, v);
        if (mate_[w] == kNoEdge && 2 * cost_[e] - y_[v] - y_[w] == 0) {
          mate_[v] = mate_[w] = e;
          break;
        }
      }
    }
    augment_tight();
  }

  /// Grows the matching to a maximum matching of the tight edges by the project's cardinality
  /// augmentation (augment_matching on a CsrGraph of the tight edges): every edge it matches is
  /// tight, so the duals stay feasible and complementary, and fewer trees are left to grow.
  void augment_tight() {
    std::vector<std::array<NodeId, 2>> ends;
    std::vector<EdgeId> original;
    for (EdgeId e = 0; e < graph_.edge_count(); ++e) {
      const auto [a, b] = graph_.endpoints(e);
      if (2 * cost_[e] - y_[a] - y_[b] != 0) continue;
      ends.push_back({a, b});
      original.push_back(e);
    }
    const CsrGraph tight = CsrGraph::from_edges(n_, ends);
    Matching matching(n_);
    for (EdgeId i = 0; i < original.size(); ++i) {
      const auto [a, b] = ends[i];
      if (mate_[a] == original[i]) matching.mate_edge[a] = matching.mate_edge[b] = i;
    }
    augment_matching(tight, matching, Augment::local);
    for (NodeId v = 0; v < n_; ++v) {
      const EdgeId i = matching.mate_edge[v];
      mate_[v] = i == kNoEdge ? kNoEdge : original[i];
    }
  }

  /// Grows the alternating trees of all free nodes at once until none is left. Throws
  /// GraphError when no event is left while a tree is: then there is no perfect matching.
  void run() {
    // Every root's dual is made even (lowering a free node's dual keeps every constraint), so
    // all labelled nodes share one parity and even-even slacks stay even (see the top).
    std::vector<NodeId> roots;
    for (NodeId v = 0; v < n_; ++v) {
      if (mate_[v] != kNoEdge) continue;
      roots.push_back(v);
      y_[v] -= y_[v] & 1;
    }
    tree_members_.resize(roots.size());
    alive_trees_ = roots.size();
    delta_ = 0;
    for (std::uint32_t t = 0; t < roots.size(); ++t) {
      label_even(top(roots[t]), kNone, roots[t], kNoEdge, t);
    }
    while (alive_trees_ > 0) step();
  }

  /// The dual solution; run() must have returned. O(n).
  MatchingCertificate certificate() const {
    MatchingCertificate c;
    c.node_dual.assign(y_.begin(), y_.begin() + n_);
    std::vector<std::uint32_t> index(ids_, kNoSet);
    for (std::uint32_t b = n_; b < ids_; ++b) {
      if (children_[b - n_].empty() || y_[b] == 0) continue;
      index[b] = static_cast<std::uint32_t>(c.set_dual.size());
      c.set_dual.push_back(y_[b]);
    }
    // above[x]: the innermost set strictly holding blossom x; filled by walking up to a known
    // entry (or the top), then back down the walked chain.
    constexpr std::uint32_t kUnknown = kNoSet - 1;
    std::vector<std::uint32_t> above(ids_, kUnknown);
    std::vector<std::uint32_t> chain;
    auto set_above = [&](std::uint32_t x) {
      chain.clear();
      for (std::uint32_t at = x; above[at] == kUnknown; at = parent_[at]) {
        if (parent_[at] == kNone) {
          above[at] = kNoSet;
          break;
        }
        chain.push_back(at);
      }
      for (std::size_t i = chain.size(); i-- > 0;) {
        const std::uint32_t p = parent_[chain[i]];
        above[chain[i]] = index[p] != kNoSet ? index[p] : above[p];
      }
      return above[x];
    };
    c.node_set.resize(n_);
    for (NodeId v = 0; v < n_; ++v) c.node_set[v] = set_above(v);
    c.set_parent.resize(c.set_dual.size());
    for (std::uint32_t b = n_; b < ids_; ++b)
      if (index[b] != kNoSet) c.set_parent[index[b]] = set_above(b);
    return c;
  }

 private:
  enum : std::uint8_t { kUnlabelled = 0, kEven = 1, kOdd = 2 };
  enum : std::uint32_t { kEdgeEvent = 0, kExpandEvent = 1 };
  static constexpr Cost kNoCost = INT64_MAX;

  struct Conn {
    NodeId x, y;  // x in child i, y in child i + 1
    EdgeId e;
  };
  struct Event {
    std::uint32_t id;  // an edge or a blossom
    std::uint32_t kind;
  };

  // ---- duals

  std::int64_t current_dual(std::uint32_t b) const {
    switch (label_[b]) {
      case kEven:
        return y_[b] + (delta_ - since_[b]);
      case kOdd:
        return y_[b] - (delta_ - since_[b]);
      default:
        return y_[b];
    }
  }
  // v's outermost blossom; the duals of the sets holding v below it go to `below`.
  std::uint32_t find(NodeId v, std::int64_t& below) {
    std::uint32_t x = v;
    std::int64_t sum = 0;
    walked_.clear();
    while (parent_[x] != kNone) {
      walked_.push_back({x, sum});
      if (up_[x] != kNone && generation_[up_[x]] == up_generation_[x]) {
        sum += up_sum_[x];
        x = up_[x];
      } else {
        sum += y_[x];
        x = parent_[x];
      }
    }
    for (auto [w, at] : walked_) {
      up_[w] = x;
      up_generation_[w] = generation_[x];
      up_sum_[w] = sum - at;
    }
    below = sum;
    return x;
  }
  std::uint32_t top(NodeId v) {
    std::int64_t below;
    return find(v, below);
  }

  // Stores b's current dual, so its label can change.
  void settle(std::uint32_t b) {
    y_[b] = current_dual(b);
    since_[b] = delta_;
  }

  // ---- the queue

  void push(std::int64_t key, std::uint32_t id, std::uint32_t kind) {
    queue_.push(static_cast<std::uint64_t>(key), {id, kind});
    ++stats_.queue_pushes;
  }

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
    while (parent_[c] != b) c = parent_[c];
    return c;
  }

  std::uint32_t new_blossom() {
    const std::uint32_t b = free_ids_.back();
    free_ids_.pop_back();
    return b;
  }
  void free_blossom(std::uint32_t b) {
    children_[b - n_].clear();
    conn_[b - n_].clear();
    label_[b] = kUnlabelled;
    parent_[b] = kNone;
    y_[b] = 0;
    ++generation_[b];
    free_ids_.push_back(b);
  }

  // ---- labels

  // Labels b without scanning it (the caller scans once every label around is set).
  void set_label(std::uint32_t b, std::uint8_t label, NodeId from, NodeId to, EdgeId e,
                 std::uint32_t tree) {
    label_[b] = label;
    since_[b] = delta_;
    tree_from_[b] = from;
    tree_to_[b] = to;
    tree_edge_[b] = e;
    tree_[b] = tree;
    tree_members_[tree].push_back(b);
    ++stats_.nodes_labelled;
  }
  void label_even(std::uint32_t b, NodeId from, NodeId to, EdgeId e, std::uint32_t tree) {
    set_label(b, kEven, from, to, e, tree);
    scan_even(b);
  }
  void label_odd(std::uint32_t b, NodeId from, NodeId to, EdgeId e, std::uint32_t tree) {
    set_label(b, kOdd, from, to, e, tree);
    if (b >= n_) push(delta_ + y_[b], b, kExpandEvent);
  }

  // Queues every edge from the nodes of blossom b (now even, b itself or inside the even blossom
  // just shrunk) to an even or unlabelled blossom. Lists b's
  // nodes: per-blossom lists of leaving edges, merged on shrink, were 5x slower on armadillo's
  // dual (a blossom of a cubic graph has about as many leaving edges as nodes).
  void scan_even(std::uint32_t b) {
    scratch_.clear();
    leaves(b, scratch_);
    stats_.even_scans += scratch_.size();
    for (NodeId x : scratch_) {
      std::int64_t below_x, below_w;
      const std::uint32_t bx = find(x, below_x);
      const std::int64_t room = -below_x - current_dual(bx);  // the slack less 2·cost
      for (EdgeId e : graph_.incident_edges(x)) {
        const NodeId w = graph_.other_end(e, x);
        const std::uint32_t bw = find(w, below_w);
        if (bw == bx || label_[bw] == kOdd) continue;
        const std::int64_t s = 2 * cost_[e] + room - below_w - current_dual(bw);
        push(delta_ + (label_[bw] == kEven ? s / 2 : s), e, kEdgeEvent);
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
      for (EdgeId e : graph_.incident_edges(x)) {
        const NodeId w = graph_.other_end(e, x);
        const std::uint32_t bw = find(w, below_w);
        if (label_[bw] != kEven) continue;
        push(delta_ + 2 * cost_[e] + room - below_w - current_dual(bw), e, kEdgeEvent);
      }
    }
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
    if (event.kind == kExpandEvent) {
      const std::uint32_t b = event.id;
      if (label_[b] != kOdd || parent_[b] != kNone) return;
      const std::int64_t d = current_dual(b);
      if (d > 0) {
        push(delta_ + d, b, kExpandEvent);
      } else {
        expand_odd(b);
      }
      return;
    }
    const EdgeId e = event.id;
    auto [u, v] = graph_.endpoints(e);
    std::int64_t below_u, below_v;
    std::uint32_t bu = find(u, below_u), bv = find(v, below_v);
    if (bu == bv) return;
    if (label_[bu] != kEven) {
      std::swap(u, v);
      std::swap(bu, bv);
      std::swap(below_u, below_v);
    }
    if (label_[bu] != kEven || label_[bv] == kOdd) return;
    const std::int64_t s = 2 * cost_[e] - below_u - current_dual(bu) - below_v - current_dual(bv);
    if (label_[bv] == kEven) {
      if (s > 0) {
        push(delta_ + s / 2, e, kEdgeEvent);
      } else if (tree_[bu] == tree_[bv]) {
        shrink(u, v, e);
      } else {
        const std::uint32_t tu = tree_[bu], tv = tree_[bv];
        augment_from(u, e);
        augment_from(v, e);
        ++stats_.searches;
        release(tu);
        release(tv);
      }
    } else if (s > 0) {
      push(delta_ + s, e, kEdgeEvent);
    } else {
      // Every free node is a root, so an unlabelled blossom has a matched base.
      const NodeId b = base_[bv];
      const EdgeId m = mate_[b];
      const NodeId z = graph_.other_end(m, b);
      label_odd(bv, u, v, e, tree_[bu]);
      label_even(top(z), b, z, m, tree_[bu]);
    }
  }

  // Tree t augmented: its blossoms store their duals and lose their labels. The edges from
  // the even blossoms of other trees into its odd blossoms had no entry (an even-odd slack does
  // not move) and now lose slack at rate 1, so the odd blossoms are scanned; the entries into
  // its even blossoms, keyed at rate 2, come out early and are queued again at rate 1 (scanning
  // the even ones too cost 4.1M node scans on fertility-sub3's dual, half of all). The blossoms
  // whose dual is zero dissolve: they constrain nothing.
  void release(std::uint32_t t) {
    --alive_trees_;
    released_.clear();
    for (std::uint32_t b : tree_members_[t]) {
      if (label_[b] == kUnlabelled || parent_[b] != kNone || tree_[b] != t) continue;
      const bool odd = label_[b] == kOdd;
      settle(b);
      label_[b] = kUnlabelled;
      released_.push_back(b);
      if (odd) scan_unlabelled(b);
    }
    std::vector<std::uint32_t>().swap(tree_members_[t]);
    for (std::uint32_t b : released_) {
      if (b >= n_ && parent_[b] == kNone && !children_[b - n_].empty() && y_[b] == 0) dissolve(b);
    }
  }

  // Removes top-level unlabelled blossom b of dual zero, and its children of dual zero.
  void dissolve(std::uint32_t b) {
    std::vector<std::uint32_t> stack{b};
    while (!stack.empty()) {
      const std::uint32_t c = stack.back();
      stack.pop_back();
      for (std::uint32_t d : children_[c - n_]) {
        parent_[d] = kNone;
        if (d >= n_ && y_[d] == 0) stack.push_back(d);
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
        a = tree_edge_[a] == kNoEdge ? kNone : top(tree_from_[top(tree_from_[a])]);
      }
      std::swap(a, c);
    }
    path_u_.clear();
    path_v_.clear();
    for (std::uint32_t x = bu; x != lca; x = top(tree_from_[x])) path_u_.push_back(x);
    for (std::uint32_t x = bv; x != lca; x = top(tree_from_[x])) path_v_.push_back(x);

    const std::uint32_t nb = new_blossom();
    std::vector<std::uint32_t>& ch = children_[nb - n_];
    std::vector<Conn>& conn = conn_[nb - n_];
    ch.push_back(lca);
    for (std::size_t i = path_u_.size(); i-- > 0;) {
      const std::uint32_t x = path_u_[i];
      conn.push_back({tree_from_[x], tree_to_[x], tree_edge_[x]});
      ch.push_back(x);
    }
    conn.push_back({u, v, e});
    for (std::uint32_t x : path_v_) {
      ch.push_back(x);
      conn.push_back({tree_to_[x], tree_from_[x], tree_edge_[x]});
    }

    base_[nb] = base_[lca];
    parent_[nb] = kNone;
    y_[nb] = 0;
    label_[nb] = kEven;
    since_[nb] = delta_;
    tree_from_[nb] = tree_from_[lca];
    tree_to_[nb] = tree_to_[lca];
    tree_edge_[nb] = tree_edge_[lca];
    tree_[nb] = tree_[lca];
    tree_members_[tree_[lca]].push_back(nb);

    odd_children_.clear();
    for (std::uint32_t c2 : ch) {
      const bool was_odd = label_[c2] == kOdd;
      settle(c2);
      label_[c2] = kUnlabelled;
      parent_[c2] = nb;
      if (was_odd) odd_children_.push_back(c2);
    }
    for (std::uint32_t c2 : odd_children_) scan_even(c2);
  }

  // Odd blossom b's dual reached zero: its children along the even side of the cycle, from the
  // one the tree enters by to the base, take b's place in the tree; the others become unlabelled.
  void expand_odd(std::uint32_t b) {
    ++stats_.blossoms_expanded;
    std::vector<std::uint32_t> ch = std::move(children_[b - n_]);
    std::vector<Conn> conn = std::move(conn_[b - n_]);
    const std::size_t k = ch.size();
    const std::uint32_t entry = child_holding(b, tree_to_[b]);
    for (std::uint32_t c : ch) parent_[c] = kNone;
    const std::size_t j =
        static_cast<std::size_t>(std::find(ch.begin(), ch.end(), entry) - ch.begin());
    const NodeId from = tree_from_[b], to = tree_to_[b];
    const EdgeId edge = tree_edge_[b];
    const std::uint32_t tree = tree_[b];
    free_blossom(b);

    // The path from the entry child to the base child: backward when j is even, else forward.
    ++stamp_;
    std::vector<std::uint32_t> even_children;
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

  // Edge `along` joins even node s to another tree: flips the path from s up to its root.
  void augment_from(NodeId s, EdgeId along) {
    for (;;) {
      const std::uint32_t bs = top(s);
      rebase(bs, s);
      mate_[s] = along;
      if (tree_edge_[bs] == kNoEdge) break;  // the root
      const std::uint32_t bt = top(tree_from_[bs]);
      rebase(bt, tree_to_[bt]);
      mate_[tree_to_[bt]] = tree_edge_[bt];
      s = tree_from_[bt];
      along = tree_edge_[bt];
    }
  }

  // Makes node v the base of blossom b, flipping the matched edges on the even side of each
  // cycle between v's child and the base child, level by level (an explicit stack).
  void rebase(std::uint32_t b, NodeId v) {
    if (b < n_) return;
    rebase_stack_.assign(1, {b, v});
    while (!rebase_stack_.empty()) {
      auto [blossom, node] = rebase_stack_.back();
      rebase_stack_.pop_back();
      std::vector<std::uint32_t>& ch = children_[blossom - n_];
      std::vector<Conn>& conn = conn_[blossom - n_];
      const std::size_t k = ch.size();
      const std::uint32_t c = child_holding(blossom, node);
      const std::size_t j =
          static_cast<std::size_t>(std::find(ch.begin(), ch.end(), c) - ch.begin());
      if (c >= n_) rebase_stack_.push_back({c, node});
      auto match = [&](std::size_t i) {
        const Conn& cn = conn[i];
        mate_[cn.x] = mate_[cn.y] = cn.e;
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

  const Graph& graph_;
  std::span<const Cost> cost_;
  HugeVector<EdgeId>& mate_;
  MinCostStats& stats_;
  std::uint32_t n_;
  std::size_t ids_;
  std::vector<std::int64_t> y_;
  std::vector<std::int64_t> since_;
  std::vector<std::uint8_t> label_;
  std::vector<std::uint32_t> parent_;
  std::vector<NodeId> base_;
  std::vector<NodeId> tree_from_;  // the node in the tree parent
  std::vector<NodeId> tree_to_;    // the node in this blossom
  std::vector<EdgeId> tree_edge_;
  std::vector<std::uint32_t> tree_;  // the tree of a labelled blossom
  std::vector<std::uint32_t> mark_;
  std::vector<std::uint32_t> generation_;
  std::vector<std::uint32_t> up_;  // the shortcuts (see the top)
  std::vector<std::uint32_t> up_generation_;
  std::vector<std::int64_t> up_sum_;
  std::vector<std::pair<std::uint32_t, std::int64_t>> walked_;
  std::uint32_t stamp_ = 0;
  std::vector<std::vector<std::uint32_t>> children_;
  std::vector<std::vector<Conn>> conn_;
  std::vector<std::uint32_t> free_ids_;
  std::int64_t delta_ = 0;
  RadixQueue<Event> queue_;
  std::vector<std::vector<std::uint32_t>> tree_members_;  // per tree: blossoms labelled in it
  std::size_t alive_trees_ = 0;
  std::vector<std::uint32_t> released_;
  std::vector<NodeId> scratch_;
  std::vector<std::uint32_t> odd_children_;
  std::vector<std::uint32_t> path_u_, path_v_;
  mutable std::vector<std::uint32_t> leaf_stack_;
  std::vector<std::pair<std::uint32_t, NodeId>> rebase_stack_;
};

}  // namespace petersen::weighted_detail
