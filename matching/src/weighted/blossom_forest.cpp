#include <stdexcept>
#include <string>
#include <vector>

#include "blossom_solver.hpp"

namespace petersen::weighted_detail {

/// Grows the alternating trees of all free nodes at once until none is left (write_result
/// gives the matching). Throws GraphError when no event is left while a tree is: then there is no
/// perfect matching. Declared noinline, so that a profiler can single out the search.
void BlossomSolver::run() {
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

// Takes the next event from the queue and acts on it.
void BlossomSolver::step() {
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
// and are queued now, to be keyed when they come out. Scanning t's odd blossoms for them would
// read every neighbour of half of t's nodes (1.9M node scans on fertility-sub3's dual, most of
// whose neighbours lie in t itself). The entries into its even blossoms, keyed at rate 2, come
// out early and are queued again at rate 1 (scanning the even ones too would cost 4.1M node
// scans on fertility-sub3's dual, half of all). The blossoms whose dual is zero dissolve: they
// constrain nothing.
void BlossomSolver::release(std::uint32_t t) {
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

// Labels unlabelled b without scanning it (the caller scans once every label around is set).
void BlossomSolver::set_label(std::uint32_t b, std::uint8_t label, NodeId from, NodeId to, EdgeId e,
                              std::uint32_t tree) {
  rec_[b].label = label;
  rec_[b].y += label == kEven ? -delta_ : delta_;  // so that current_dual(b) is unchanged
  link_[b] = {from, to, e};
  rec_[b].tree = tree;
  members_.push(member_heads_[tree], b);
  ++stats_.nodes_labelled;
}

void BlossomSolver::label_even(std::uint32_t b, NodeId from, NodeId to, EdgeId e,
                               std::uint32_t tree) {
  set_label(b, kEven, from, to, e, tree);
  scan_even(b);
}

void BlossomSolver::label_odd(std::uint32_t b, NodeId from, NodeId to, EdgeId e,
                              std::uint32_t tree) {
  set_label(b, kOdd, from, to, e, tree);
  if (b >= n_) push_expand(delta_ + current_dual(b), b);
}

// Queues every edge from the nodes of blossom b (now even, b itself or inside the even blossom
// just shrunk) to an even or unlabelled blossom. Lists b's nodes: per-blossom lists of leaving
// edges, merged on shrink, are 5x slower on armadillo's dual (a blossom of a cubic graph has
// about as many leaving edges as nodes).
void BlossomSolver::scan_even(std::uint32_t b) {
  // Most blossoms turning even are single nodes: scanned without listing leaves (the list's
  // push_back would be 5 % of the solver's instructions on armadillo's dual).
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

void BlossomSolver::scan_even_node(NodeId x) {
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
void BlossomSolver::scan_unlabelled(std::uint32_t b) {
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

}  // namespace petersen::weighted_detail
