#include <algorithm>
#include <cstddef>
#include <vector>

#include "blossom_solver.hpp"

namespace petersen::weighted_detail {

std::uint32_t BlossomSolver::find_nested(NodeId v, std::int64_t& below) {
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
  // outside in), and a shortcut to the top would die with each level, so that every later walk
  // went up parent by parent again (on rocker-arm-sub3's dual 273M walk steps against 19.8M).
  const auto [last, at_last] = walked_.back();
  up_[last] = {sum - at_last, x, rec_[x].generation};
  for (std::size_t i = 0; i + 1 < walked_.size(); ++i) {
    const auto [w, at] = walked_[i];
    up_[w] = {at_last - at, last, rec_[last].generation};
  }
  below = sum;
  return x;
}

// Appends the nodes of blossom b to out.
void BlossomSolver::leaves(std::uint32_t b, std::vector<NodeId>& out) const {
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
std::uint32_t BlossomSolver::child_holding(std::uint32_t b, NodeId v) const {
  std::uint32_t c = v;
  while (rec_[c].parent != b) c = rec_[c].parent;
  return c;
}

// A freed id if there is one (the last freed first), else the next fresh one, whose entries
// are appended here (the arrays hold ids_ without reallocating: see the constructor).
std::uint32_t BlossomSolver::new_blossom() {
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

void BlossomSolver::free_blossom(std::uint32_t b) {
  children_[b - n_].clear();
  conn_[b - n_].clear();
  rec_[b].label = kUnlabelled;
  rec_[b].parent = kNone;
  rec_[b].y = 0;
  ++rec_[b].generation;
  free_ids_.push_back(b);
}

// Removes top-level unlabelled blossom b of dual zero, and its children of dual zero.
void BlossomSolver::dissolve(std::uint32_t b) {
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
void BlossomSolver::shrink(NodeId u, NodeId v, EdgeId e) {
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
void BlossomSolver::expand_odd(std::uint32_t b) {
  ++stats_.blossoms_expanded;
  // The cycle is swapped out into scratch vectors, which hand their (cleared) buffers to the
  // freed id: moving it out would leave the id without capacity, and shrink's pushes into it
  // would reallocate (malloc, free and the copies: 4 % of the instructions, armadillo's dual).
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

// Edge `along` joins even node s to node `across` in another tree: flips the path from s up
// to its root.
void BlossomSolver::augment_from(NodeId s, EdgeId along, NodeId across) {
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
// finding that child afresh at each level would walk the nested blossoms again from the node
// (fertility-sub3's dual nests over 100 deep).
void BlossomSolver::rebase(std::uint32_t b, NodeId v) {
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

}  // namespace petersen::weighted_detail
