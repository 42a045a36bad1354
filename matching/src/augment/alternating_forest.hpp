#pragma once
// The alternating forest of Tarjan's augmenting-path procedure (paper §3.1, reference [21]),
// shared by the cubic and the general (CSR) entry points: any Graph with incident_edges(v),
// other_end(e, v) and endpoints(e).
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

#include <algorithm>
#include <memory>
#include <numeric>
#include <utility>
#include <vector>

#include "petersen/matching/augment.hpp"

namespace petersen::augment_detail {

enum Label : std::uint8_t { unlabelled = 0, even = 1, odd = 2, bridged = 3 };
inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

template <class Graph>
class AlternatingForest {
 public:
  AlternatingForest(const Graph& graph, std::vector<EdgeId>& mate, AugmentStats& stats)
      : graph_(graph),
        mate_(mate),
        stats_(stats),
        label_(std::make_unique<Label[]>(mate.size())),
        mark_(std::make_unique<std::uint32_t[]>(mate.size())),
        root_(std::make_unique_for_overwrite<NodeId[]>(mate.size())),
        base_(std::make_unique_for_overwrite<NodeId[]>(mate.size())),
        pred_edge_(std::make_unique_for_overwrite<EdgeId[]>(mate.size())),
        bridge_edge_(std::make_unique_for_overwrite<EdgeId[]>(mate.size())),
        bridge_side_(std::make_unique_for_overwrite<NodeId[]>(mate.size())),
        blocked_head_(std::make_unique_for_overwrite<std::uint32_t[]>(mate.size())) {}

  /// Forgets every label: the paper's O(n) reset before each search.
  void clear_all() {
    std::fill_n(label_.get(), mate_.size(), unlabelled);
    std::fill_n(mark_.get(), mate_.size(), 0u);
    std::iota(base_.get(), base_.get() + mate_.size(), NodeId{0});
    blocked_.clear();
    queue_.clear();
    head_ = 0;
    stamp_ = 0;
  }

  /// Starts a tree at free node r.
  void add_root(NodeId r) {
    give(r, even, r);
    blocked_head_[r] = kNone;
    queue_.push_back(r);
  }

  /// Grows the forest breadth-first, augmenting whenever two trees meet or a tree reaches an
  /// unlabelled free node. Returns the number of augmentations; with `stop_at_first`, returns
  /// right after the first.
  std::uint64_t grow(bool stop_at_first) {
    std::uint64_t found = 0;
    while (head_ < queue_.size()) {
      const NodeId x = queue_[head_++];
      // x's tree died after x was queued, or x has since been labelled odd in another tree.
      if (!alive(x) || label_[x] == odd) continue;
      for (EdgeId e : graph_.incident_edges(x)) {
        if (e == mate_[x]) continue;
        const NodeId y = graph_.other_end(e, x);
        if (!alive(y)) {
          if (mate_[y] == kNoEdge) {
            augment(x, y, e);
          } else {
            const NodeId z = graph_.other_end(mate_[y], y);
            give(y, odd, root_[x]);
            pred_edge_[y] = e;
            give(z, even, root_[x]);
            queue_.push_back(z);
            continue;
          }
        } else if (label_[y] == odd) {
          if (root_[y] != root_[x]) block(x, root_[y]);
          continue;
        } else if (root_[y] != root_[x]) {
          augment(x, y, e);
        } else {
          if (find(x) != find(y)) shrink(x, y, e);
          continue;
        }
        ++found;
        if (stop_at_first) return found;
        break;  // x's tree died with the augmentation
      }
    }
    return found;
  }

 private:
  NodeId mate_node(NodeId v) const { return graph_.other_end(mate_[v], v); }
  // The even node that labelled odd node o.
  NodeId pred(NodeId o) const { return graph_.other_end(pred_edge_[o], o); }
  bool alive(NodeId v) const { return label_[v] != unlabelled && mate_[root_[v]] == kNoEdge; }

  void give(NodeId v, Label label, NodeId root) {
    label_[v] = label;
    root_[v] = root;
    base_[v] = v;
    ++stats_.nodes_labelled;
  }

  // Base of v's blossom (path halving).
  NodeId find(NodeId v) {
    while (base_[v] != v) {
      base_[v] = base_[base_[v]];
      v = base_[v];
    }
    return v;
  }

  // Edge e = (x, y) joins two even nodes of one tree in different blossoms: walk up from both
  // bases alternately to the first common base b, then make every odd node on the two paths even.
  void shrink(NodeId x, NodeId y, EdgeId e) {
    ++stats_.blossoms;
    ++stamp_;
    NodeId u = find(x), w = find(y), b = kNoNode;
    while (b == kNoNode) {
      if (u != kNoNode) {
        if (mark_[u] == stamp_) {
          b = u;
        } else {
          mark_[u] = stamp_;
          u = mate_[u] == kNoEdge ? kNoNode : find(pred(mate_node(u)));
        }
      }
      std::swap(u, w);
    }
    bridge(find(x), b, x, e);
    bridge(find(y), b, y, e);
  }

  // Makes the odd nodes between base u and base b even, bridged by e with `side` on their side.
  void bridge(NodeId u, NodeId b, NodeId side, EdgeId e) {
    while (u != b) {
      const NodeId o = mate_node(u);
      label_[o] = bridged;
      bridge_edge_[o] = e;
      bridge_side_[o] = side;
      base_[u] = base_[o] = b;
      queue_.push_back(o);
      u = find(pred(o));
    }
  }

  // Augments along e = (x, y) plus the tree paths from x and (if labelled) y to their roots;
  // both trees die, and the nodes they blocked are queued again.
  void augment(NodeId x, NodeId y, EdgeId e) {
    ++stats_.augmenting_paths;
    path_edges_.clear();
    path_edges_.push_back(e);
    collect(x, root_[x]);
    const bool y_in_tree = alive(y);
    if (y_in_tree) collect(y, root_[y]);
    for (EdgeId f : path_edges_) {
      auto [a, c] = graph_.endpoints(f);
      mate_[a] = mate_[c] = f;
    }
    release(root_[x]);
    if (y_in_tree) release(root_[y]);
  }

  // Even node x met an odd node of the tree rooted at r.
  void block(NodeId x, NodeId r) {
    blocked_.push_back({x, blocked_head_[r]});
    blocked_head_[r] = static_cast<std::uint32_t>(blocked_.size() - 1);
  }

  void release(NodeId r) {
    for (std::uint32_t i = blocked_head_[r]; i != kNone; i = blocked_[i].next)
      queue_.push_back(blocked_[i].node);
  }

  // Tarjan's path(v, w) from even node v up to its ancestor w, an alternating path that starts
  // with v's matching edge; records its non-matching edges. For v even by its own label:
  //   path(v, w) = (v, mate v) + pred edge of mate v + path(pred(mate v), w);
  // for v bridged by (s, t), s on v's side:
  //   path(v, w) = (v, mate v) + reverse path(s, mate v) + (s, t) + path(t, w).
  void collect(NodeId v, NodeId w) {
    pending_.push_back({v, w});
    while (!pending_.empty()) {
      auto [from, to] = pending_.back();
      pending_.pop_back();
      while (from != to) {
        const NodeId m = mate_node(from);
        if (label_[from] == even) {
          path_edges_.push_back(pred_edge_[m]);
          from = pred(m);
        } else {
          const NodeId s = bridge_side_[from];
          path_edges_.push_back(bridge_edge_[from]);
          pending_.push_back({s, m});
          from = graph_.other_end(bridge_edge_[from], s);
        }
      }
    }
  }

  const Graph& graph_;
  std::vector<EdgeId>& mate_;
  AugmentStats& stats_;
  std::unique_ptr<Label[]> label_;
  std::unique_ptr<std::uint32_t[]> mark_;  // stamp of the last blossom walk that met this base
  std::unique_ptr<NodeId[]> root_;
  std::unique_ptr<NodeId[]> base_;       // disjoint-set parent; a root of it is a blossom base
  std::unique_ptr<EdgeId[]> pred_edge_;  // odd node: the edge it was labelled over
  std::unique_ptr<EdgeId[]> bridge_edge_;
  std::unique_ptr<NodeId[]> bridge_side_;
  std::unique_ptr<std::uint32_t[]> blocked_head_;  // root: first entry of its blocked list
  struct Blocked {
    NodeId node;
    std::uint32_t next;
  };
  std::vector<Blocked> blocked_;
  std::vector<NodeId> queue_;
  std::size_t head_ = 0;
  std::uint32_t stamp_ = 0;
  std::vector<EdgeId> path_edges_;
  std::vector<std::pair<NodeId, NodeId>> pending_;
};

}  // namespace petersen::augment_detail
