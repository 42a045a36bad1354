#include <algorithm>
#include <array>
#include <functional>
#include <iterator>
#include <optional>

#include "blossom_solver.hpp"
#include "petersen/graph/parallel.hpp"

namespace petersen::weighted_detail {

/// Short single-tree searches before the forest (see short_search), Blossom V's fractional
/// start (Kolmogorov 2009, section 5.1) with a label budget: a search ends at another free
/// node or at a node of a half cycle (augmenting), or where a tight edge closes an odd cycle
/// in its own tree (a half cycle, close_half_cycle), or at its budget. Passes over the free
/// nodes with a budget per search of 16, 128, 1,024, 8,192 and 65,536; a pass retries only the
/// roots whose search ran out of budget (one that does often succeeds on a later pass, once
/// the searches around have moved the duals). The half cycles left at the end each give one
/// free node, with duals optimal for the matching polytope less its odd-set constraints and
/// no blossom. The half cycles are the reason for these searches (petersen_weighted_speed):
/// searches that stop at a blossom instead leave the forest 1,460 roots on rocker-arm-sub3's
/// dual where these leave 300 (Blossom V's own count after its start; 676, 780, 98 and 1,524 on
/// the other large meshes, the same as Blossom V's), and the solver takes 1.82 s there against
/// 1.00. The budgets grow 8x per pass: budgets doubling up to 1,024 leave 886 roots, 807 of them
/// out of budget; a single pass at 65,536 takes 15.5M labels and 1.15 s; budgets doubling
/// all the way spend 71 % of the labels on searches that run out, where 8x takes 8.8M labels
/// and leaves the same roots (4x and 16x do about as well).
///
/// The searches run in two parts of the breadth-first numbering, [0, n/2) and [n/2, n), on
/// `threads` threads (0: every core): a search stops, as at its budget, when it would read a
/// node of the other part, and hands its root to a last round over the whole graph, after
/// both parts. The parts share no node, so the result does not depend on the threads.
void BlossomSolver::short_searches(std::uint32_t threads) {
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
  std::merge(parts[0].handed_over.begin(), parts[0].handed_over.end(), parts[1].handed_over.begin(),
             parts[1].handed_over.end(), std::back_inserter(whole.roots));
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

void BlossomSolver::short_passes(ShortPart& part, std::uint64_t most) {
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
BlossomSolver::ShortEnd BlossomSolver::short_search(ShortPart& part, NodeId root,
                                                    std::uint32_t budget) {
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
void BlossomSolver::close_half_cycle(ShortPart& part, NodeId root, const ShortEvent& closing) {
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
void BlossomSolver::break_cycle_at(NodeId w) {
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

}  // namespace petersen::weighted_detail
