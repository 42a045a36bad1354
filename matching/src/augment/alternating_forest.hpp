#pragma once
// The alternating forest of Tarjan's augmenting-path procedure (paper §3.1, reference [21]),
// shared by the cubic and the general (CSR) entry points: any Graph with incident_edges(v),
// other_end(e, v) and endpoints(e). A cubic graph is searched through its NeighbourTable, whose
// edges are half-edges: it also names the graph edge behind each (graph_edge), shows where a
// node's neighbours lie (neighbours), and keeps the search state itself (slot).
//
// Roots are free nodes, labelled even. Scanning an even node x along a non-matching edge to y:
//   y unlabelled and free        -> augmenting path (single-root searches);
//   y unlabelled and matched     -> y odd (pred edge remembered), mate(y) even;
//   y odd                        -> nothing;
//   y even in another tree       -> augmenting path;
//   y even in the same tree, in another blossom -> shrink the blossom.
// Shrinking makes the blossom's odd nodes even ("bridged"), remembers the bridge (x, y) with the
// end on that node's side, and links every node to the blossom's base in a disjoint-set forest.
// A path is recovered by Tarjan's rule without recursion; only its non-matching edges are
// collected, since they are exactly the new matching edges on it.
//
// A tree dies when its root gets matched; a node of a dead tree counts as unlabelled, so several
// trees can grow at once and keep growing after two of them augmented. An even node that met an
// odd node of another tree is remembered in that tree's blocked list and queued again when that
// tree dies, so when the queue runs dry the forest is a complete Edmonds forest: no augmenting
// path is left.
//
// Layout, for the cost per label: everything a scan reads or writes about a node (its mate node,
// label, tree, link and blossom base) sits in one 16-byte slot, so touching a node costs one
// cache line, and stepping from an odd node to its mate needs no edge lookup. The slots are set
// up from the matching in one pass on entry (for a NeighbourTable, before: PS writes them as it
// writes the matching); the caller's mate edges are written only where an augmenting path flips
// them. Trees are numbered 0..k-1, and a tree's death is one byte in a k-byte array, not a walk
// over it. The breadth-first queue is the exact order of the coming scans, so it is read ahead
// in stages, each prefetching what the next stage will dereference: rows or incidence lists,
// then edge ends (if apart from the rows), then neighbour slots, then the slots of the
// neighbours' mates.

#include <algorithm>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "petersen/graph/memory.hpp"
#include "petersen/matching/augment.hpp"
#include "search_slot.hpp"

namespace petersen::augment_detail {

/// Most trees one forest can hold (the tree number has the tag's top 28 bits).
inline constexpr int kTreeShift = 4;
inline constexpr std::uint32_t kSide = 8;
inline constexpr std::uint32_t kMaxTrees = 1u << (32 - kTreeShift);

template <class Graph>
class AlternatingForest {
  static constexpr bool kStateInGraph = requires(const Graph& g) { g.slot(NodeId{}); };

 public:
  /// Reads the matching (mate edge per node), which each augmentation then updates; the free
  /// nodes, in id order, become free_nodes(). Throws std::length_error past kMaxTrees free nodes.
  /// A graph that keeps the search state (NeighbourTable) must hold fresh slots for `mate`.
  AlternatingForest(const Graph& graph, std::pmr::vector<EdgeId>& mate, AugmentStats& stats)
      : graph_(graph),
        mate_edge_(&mate),
        stats_(stats),
        n_(mate.size()),
        slot_(kStateInGraph ? RawArray<Slot>() : make_raw_array<Slot>(n_)) {
    if constexpr (kStateInGraph) {
      for (NodeId v = 0; v < n_; ++v)
        if (mate[v] == kNoEdge) free_.push_back(v);
    } else {
      // A mate read through its mate edge's ends is a random access: the ends of the edge
      // kReadAhead nodes on are prefetched, so the misses overlap instead of queueing.
      constexpr NodeId kReadAhead = 16;
      for (NodeId v = 0; v < n_; ++v) {
        if constexpr (requires { graph.edge_ends(); }) {
          if (v + kReadAhead < n_ && mate[v + kReadAhead] != kNoEdge)
            __builtin_prefetch(&graph.edge_ends()[2 * std::size_t{mate[v + kReadAhead]}]);
        }
        const bool free = mate[v] == kNoEdge;
        slot(v) = {free ? kNoNode : graph.other_end(mate[v], v), 0, kNone, v};
        if (free) free_.push_back(v);
      }
    }
    make_trees();
  }

  /// Over a graph that keeps the search state (a NeighbourTable on rows), the matching being
  /// that state alone: its fresh slots' mates. Augmentations update the slots only.
  AlternatingForest(const Graph& graph, AugmentStats& stats) requires(kStateInGraph)
      : graph_(graph), stats_(stats), n_(graph.node_count()) {
    for (NodeId v = 0; v < n_; ++v)
      if (slot(v).mate == kNoNode) free_.push_back(v);
    make_trees();
  }

  const std::vector<NodeId>& free_nodes() const { return free_; }

  /// After a complete growth (grow(false), or a single search that failed): the odd nodes of the
  /// living trees. No augmenting path is left then, so they are the set A of the Gallai–Edmonds
  /// decomposition, a Tutte–Berge witness of maximality. O(n).
  std::vector<NodeId> odd_nodes() const {
    std::vector<NodeId> odd_nodes;
    for (NodeId v = 0; v < n_; ++v) {
      const std::uint32_t tag = slot(v).tag;
      if (alive(tag) && label_of(tag) == odd) odd_nodes.push_back(v);
    }
    return odd_nodes;
  }
  bool is_free(NodeId v) const { return slot(v).mate == kNoNode; }

  /// Forgets every label and tree: the paper's O(n) reset before each search.
  void clear_all() {
    for (NodeId v = 0; v < n_; ++v) {
      slot(v).tag = 0;
      slot(v).base = v;
    }
    trees_ = 0;
    blocked_.clear();
    queue_.clear();
    head_ = 0;
  }

  /// Starts a tree at free node r.
  void add_root(NodeId r) {
    const std::uint32_t tree = trees_++;
    tree_alive_[tree] = 1;
    blocked_head_[tree] = kNone;
    slot(r).tag = tree << kTreeShift | even;
    slot(r).base = r;
    ++stats_.nodes_labelled;
    queue_.push_back(r);
  }

  /// Grows the forest breadth-first, augmenting whenever two trees meet or a tree reaches an
  /// unlabelled free node. Returns the number of augmentations; with `stop_at_first`, returns
  /// right after the first.
  std::uint64_t grow(bool stop_at_first) {
    std::uint64_t found = 0;
    while (head_ < queue_.size()) {
      prefetch_ahead();
      const NodeId x = queue_[head_++];
      const std::uint32_t tx = slot(x).tag;
      // x's tree died after x was queued, or x has since been labelled odd in another tree.
      if (!alive(tx) || label_of(tx) == odd) continue;
      const std::uint32_t tree = tx >> kTreeShift;
      // find(x), taken at x's first contact inside its tree and kept: x's blossom changes only
      // when x's own scan shrinks one (most contacts fall inside x's blossom: two finds each).
      NodeId x_base = kNoNode;
      for (EdgeId e : graph_.incident_edges(x)) {
        const NodeId y = far_end(e, x);
        // Any edge to x's mate (a parallel copy included) leads inside x's blossom or to its
        // odd parent: nothing to learn.
        if (y == slot(x).mate) continue;
        Slot& sy = slot(y);
        const std::uint32_t ty = sy.tag;
        if (!alive(ty)) {
          if (sy.mate == kNoNode) {
            augment(x, y, e);
          } else {
            // The common step, no blossom work: y odd, its mate z even, both in x's tree.
            const NodeId z = sy.mate;
            sy = {sy.mate, tree << kTreeShift | odd, e, y};
            Slot& sz = slot(z);
            sz = {sz.mate, tree << kTreeShift | even, x, z};
            stats_.nodes_labelled += 2;
            queue_.push_back(z);
            continue;
          }
        } else if (label_of(ty) == odd) {
          if (ty >> kTreeShift != tree) block(x, ty >> kTreeShift);
          continue;
        } else if (ty >> kTreeShift != tree) {
          augment(x, y, e);
        } else {
          if (x_base == kNoNode) x_base = find(x);
          if (x_base != find(y)) {
            shrink(x, y, e);
            x_base = kNoNode;
          }
          continue;
        }
        ++found;
        if (stop_at_first) return found;
        break;  // x's tree died with the augmentation
      }
      compact_queue();
    }
    return found;
  }

 private:
  struct Blocked {
    NodeId node;
    std::uint32_t next;
  };

  Slot& slot(NodeId v) const {
    if constexpr (kStateInGraph) {
      return graph_.slot(v);
    } else {
      return slot_[v];
    }
  }
  // The end of x's incident edge e away from x.
  NodeId far_end(EdgeId e, NodeId x) const {
    if constexpr (requires { graph_.far_end(e); }) {
      return graph_.far_end(e);
    } else {
      return graph_.other_end(e, x);
    }
  }
  // The caller's edge behind the forest's edge e.
  EdgeId graph_edge(EdgeId e) const {
    if constexpr (requires { graph_.graph_edge(e); }) {
      return graph_.graph_edge(e);
    } else {
      return e;
    }
  }
  // Where the scan of v starts reading: its row of neighbours, else its incidence list.
  const void* row_of(NodeId v) const {
    if constexpr (requires { graph_.neighbours(v); }) {
      return graph_.neighbours(v).data();
    } else {
      return graph_.incident_edges(v).data();
    }
  }

  static Label label_of(std::uint32_t tag) { return static_cast<Label>(tag & 3); }
  bool alive(std::uint32_t tag) const {
    return label_of(tag) != unlabelled && tree_alive_[tag >> kTreeShift];
  }

  // Stage k reads what stage k+1 prefetched (kStride queue entries earlier), so each line has
  // about kStride scans to arrive: x's slot and row (neighbours or incidence list), x's edge ends
  // (for a graph that keeps them apart from the row), the slots of x's neighbours, the slots of
  // their mates.
  // Always inlined: g++ 12's mod-ref analysis takes a prefetch-only function for one without
  // effects and drops the call.
  [[gnu::always_inline]] void prefetch_ahead() const {
    constexpr std::size_t kStride = 4;
    const std::size_t size = queue_.size();
    if (head_ + 4 * kStride < size) {
      const NodeId v = queue_[head_ + 4 * kStride];
      __builtin_prefetch(&slot(v));
      __builtin_prefetch(row_of(v));
    }
    if constexpr (requires { graph_.edge_ends(); }) {  // a graph that shows its edge-end array
      if (head_ + 3 * kStride < size) {
        const NodeId v = queue_[head_ + 3 * kStride];
        for (EdgeId e : graph_.incident_edges(v))
          __builtin_prefetch(&graph_.edge_ends()[2 * std::size_t{e}]);
      }
    }
    if (head_ + 2 * kStride < size) {
      const NodeId v = queue_[head_ + 2 * kStride];
      for (EdgeId e : graph_.incident_edges(v)) __builtin_prefetch(&slot(far_end(e, v)));
    }
    if (head_ + kStride < size) {
      const NodeId v = queue_[head_ + kStride];
      for (EdgeId e : graph_.incident_edges(v)) {
        const NodeId m = slot(far_end(e, v)).mate;
        if (m != kNoNode) __builtin_prefetch(&slot(m));
      }
    }
  }

  // One tree per free node, at most kMaxTrees.
  void make_trees() {
    if (free_.size() > kMaxTrees) throw std::length_error("augment_matching: too many free nodes");
    tree_alive_.resize(free_.size());
    blocked_head_.resize(free_.size());
  }

  // The consumed front of the queue is dropped once it is half the queue, so the queue holds
  // about what is still to scan, not every label ever given.
  void compact_queue() {
    if (head_ < 4096 || 2 * head_ < queue_.size()) return;
    queue_.erase(queue_.begin(), queue_.begin() + static_cast<std::ptrdiff_t>(head_));
    head_ = 0;
  }

  // Base of v's blossom (path halving).
  NodeId find(NodeId v) {
    while (slot(v).base != v) {
      slot(v).base = slot(slot(v).base).base;
      v = slot(v).base;
    }
    return v;
  }

  void set_mark(NodeId v) { slot(v).tag |= 4; }
  bool marked(NodeId v) const { return slot(v).tag & 4; }

  // Edge e = (x, y) joins two even nodes of one tree in different blossoms: walk up from both
  // bases alternately to the first common base b, then make every odd node on the two paths even.
  // A base's link is the even node two steps up, so each step is one slot and one find.
  void shrink(NodeId x, NodeId y, EdgeId e) {
    ++stats_.blossoms;
    NodeId u = find(x), w = find(y), b = kNoNode;
    while (b == kNoNode) {
      if (u != kNoNode) {
        if (marked(u)) {
          b = u;
        } else {
          set_mark(u);
          walked_.push_back(u);
          u = slot(u).mate == kNoNode ? kNoNode : find(slot(u).link);
        }
      }
      std::swap(u, w);
    }
    for (NodeId v : walked_) slot(v).tag &= ~4u;
    walked_.clear();
    bridge(find(x), b, x, e);
    bridge(find(y), b, y, e);
  }

  // Makes the odd nodes between base u and base b even, bridged by e with `side` on their side.
  // The bridge takes the odd node's link (its pred edge, which collect() finds again among its
  // edges, from its mate's link), so a shrink writes only slots: a separate bridge array would
  // be an n-sized array faulted in page by page during the search.
  void bridge(NodeId u, NodeId b, NodeId side, EdgeId e) {
    const std::uint32_t side_bit = graph_.endpoints(e)[1] == side ? kSide : 0;
    while (u != b) {
      const NodeId o = slot(u).mate;
      slot(o).tag |= bridged | side_bit;
      slot(o).link = e;
      slot(o).base = b;
      const NodeId up = slot(u).link;
      slot(u).base = b;
      queue_.push_back(o);
      u = find(up);
    }
  }

  // Augments along e = (x, y) plus the tree paths from x and (if labelled) y to their roots;
  // both trees die, and the nodes they blocked are queued again.
  void augment(NodeId x, NodeId y, EdgeId e) {
    ++stats_.augmenting_paths;
    path_edges_.clear();
    path_edges_.push_back(e);
    const std::uint32_t tree_x = slot(x).tag >> kTreeShift;
    collect(x);
    const bool y_in_tree = alive(slot(y).tag);
    const std::uint32_t tree_y = slot(y).tag >> kTreeShift;
    if (y_in_tree) collect(y);
    for (EdgeId f : path_edges_) {
      auto [a, c] = graph_.endpoints(f);
      slot(a).mate = c;
      slot(c).mate = a;
      if (mate_edge_ != nullptr) (*mate_edge_)[a] = (*mate_edge_)[c] = graph_edge(f);
    }
    release(tree_x);
    if (y_in_tree) release(tree_y);
  }

  // Even node x met an odd node of tree t.
  void block(NodeId x, std::uint32_t t) {
    blocked_.push_back({x, blocked_head_[t]});
    blocked_head_[t] = static_cast<std::uint32_t>(blocked_.size() - 1);
  }

  // Tree t dies: its nodes count as unlabelled from now on, and what it blocked scans again.
  void release(std::uint32_t t) {
    tree_alive_[t] = 0;
    for (std::uint32_t i = blocked_head_[t]; i != kNone; i = blocked_[i].next)
      queue_.push_back(blocked_[i].node);
  }

  // Tarjan's path(v, w) from even node v up to its root w, an alternating path that starts
  // with v's matching edge; records its non-matching edges. For v even by its own label:
  //   path(v, w) = (v, mate v) + pred edge of mate v + path(pred(mate v), w);
  // for v bridged by (s, t), s on v's side:
  //   path(v, w) = (v, mate v) + reverse path(s, mate v) + (s, t) + path(t, w).
  // The root is the one node of the path with no mate, so "up to the root" is "up to a free
  // node"; the inner pieces end at the named node.
  void collect(NodeId v) {
    pending_.push_back({v, kNoNode});
    while (!pending_.empty()) {
      auto [from, to] = pending_.back();
      pending_.pop_back();
      while (from != to && slot(from).mate != kNoNode) {
        const NodeId m = slot(from).mate;
        if (label_of(slot(from).tag) == even) {
          // m's pred edge: its link while m is odd; a bridge took that link if m is bridged.
          const NodeId up = slot(from).link;
          path_edges_.push_back(label_of(slot(m).tag) == odd ? slot(m).link : edge_between(m, up));
          from = up;
        } else {
          const EdgeId edge = slot(from).link;
          const NodeId s = graph_.endpoints(edge)[(slot(from).tag & kSide) ? 1 : 0];
          path_edges_.push_back(edge);
          pending_.push_back({s, m});
          from = graph_.other_end(edge, s);
        }
      }
    }
  }

  // An edge joining m and w (any copy of a parallel edge: none of them is a matching edge here).
  EdgeId edge_between(NodeId m, NodeId w) const {
    for (EdgeId e : graph_.incident_edges(m))
      if (graph_.other_end(e, m) == w) return e;
    return kNoEdge;  // unreachable: m was labelled over an edge from w
  }

  const Graph& graph_;
  std::pmr::vector<EdgeId>* mate_edge_ = nullptr;  // nullptr: the matching is the slots' mates only
  AugmentStats& stats_;
  std::size_t n_;
  RawArray<Slot> slot_;  // unless the graph keeps the search state
  std::vector<NodeId> free_;
  std::vector<std::uint8_t> tree_alive_;     // per tree: its root is still free
  std::vector<std::uint32_t> blocked_head_;  // per tree: first entry of its blocked list
  std::uint32_t trees_ = 0;
  std::vector<Blocked> blocked_;
  std::vector<NodeId> queue_;
  std::size_t head_ = 0;
  std::vector<NodeId> walked_;
  std::vector<EdgeId> path_edges_;
  std::vector<std::pair<NodeId, NodeId>> pending_;
};

}  // namespace petersen::augment_detail
