#include "euler_tour_forest.hpp"

#include <stdexcept>
#include <vector>

namespace petersen::detail {

namespace {
constexpr std::uint32_t kVertexBit = 4;
}

EttNode EulerTourForest::make_node(std::uint32_t owner, bool vertex) {
  nodes_.push_back({kNoEtt, kNoEtt, kNoEtt, vertex ? (1u << kCountShift | kVertexBit) : 0});
  owner_.push_back(owner);
  return static_cast<EttNode>(nodes_.size() - 1);
}

EttNode EulerTourForest::make_vertex(std::uint32_t owner) {
  if (++vertices_ >= 1u << (32 - kCountShift))
    throw std::length_error("EulerTourForest: more than 2^27 - 1 vertex nodes");
  return make_node(owner, true);
}

EttNode EulerTourForest::make_arc(std::uint32_t owner) {
  if (free_.empty()) return make_node(owner, false);
  const EttNode a = free_.back();
  free_.pop_back();
  nodes_[a] = Node{};
  owner_[a] = owner;
  return a;
}

void EulerTourForest::update(EttNode x) {
  Node& n = nodes_[x];
  const std::uint32_t own = n.meta & kOwnMask;
  const std::uint32_t l = n.child[0] == kNoEtt ? 0 : nodes_[n.child[0]].meta;
  const std::uint32_t r = n.child[1] == kNoEtt ? 0 : nodes_[n.child[1]].meta;
  const std::uint32_t c = (own >> 2) + (l >> kCountShift) + (r >> kCountShift);  // own >> 2: vertex
  const std::uint32_t a = (own & 3) | (((l | r) >> kAggregateShift) & 3);
  n.meta = c << kCountShift | a << kAggregateShift | own;
}

void EulerTourForest::splay(EttNode x) {
  // Only the nodes a step moves down are updated on the way (updating both ends of every
  // rotation would be 23 % of ds's instructions on armadillo's dual). x, which ends with
  // the whole tree below it, takes the old root's count and flags: no update of x at all.
  Node& nx = nodes_[x];
  if (nx.parent == kNoEtt) return;
  std::uint32_t whole;  // the old root's meta
  for (;;) {
    const EttNode y = nx.parent;
    Node& ny = nodes_[y];
    const EttNode z = ny.parent;
    if (z == kNoEtt) {
      whole = ny.meta;
      const int s = ny.child[1] == x ? 1 : 0;
      const EttNode moved = nx.child[1 - s];
      ny.child[s] = moved;
      if (moved != kNoEtt) nodes_[moved].parent = y;
      nx.child[1 - s] = y;
      ny.parent = x;
      nx.parent = kNoEtt;
      update(y);
      break;
    }
    // A zig-zig or zig-zag written at once, the shapes of its two rotations: z's parent w is
    // rewritten once, not twice.
    Node& nz = nodes_[z];
    const EttNode w = nz.parent;
    if (w != kNoEtt)
      nodes_[w].child[nodes_[w].child[1] == z ? 1 : 0] = x;
    else
      whole = nz.meta;
    nx.parent = w;
    const int s = nz.child[1] == y ? 1 : 0;  // y's side below z
    if ((ny.child[1] == x ? 1 : 0) == s) {
      const EttNode b = nx.child[1 - s], c = ny.child[1 - s];
      nx.child[1 - s] = y;
      ny.parent = x;
      ny.child[s] = b;
      if (b != kNoEtt) nodes_[b].parent = y;
      ny.child[1 - s] = z;
      nz.parent = y;
      nz.child[s] = c;
      if (c != kNoEtt) nodes_[c].parent = z;
      update(z);  // below y now
      update(y);
    } else {
      const EttNode a = nx.child[s], b = nx.child[1 - s];
      nx.child[s] = y;
      nx.child[1 - s] = z;
      ny.parent = x;
      nz.parent = x;
      ny.child[1 - s] = a;
      if (a != kNoEtt) nodes_[a].parent = y;
      nz.child[s] = b;
      if (b != kNoEtt) nodes_[b].parent = z;
      update(y);
      update(z);
    }
    if (w == kNoEtt) break;
  }
  nx.meta = (whole & ~kOwnMask) | (nx.meta & kOwnMask);
}

EttNode EulerTourForest::root(EttNode x) {
  splay(x);
  return x;
}

bool EulerTourForest::same_tree(EttNode x, EttNode y) {
  // x, the root after its splay, is no longer one after y's exactly when they share a tree: the
  // same two splays as walking from y to its root first, without the walk.
  splay(x);
  splay(y);
  return x == y || nodes_[x].parent != kNoEtt;
}

EttNode EulerTourForest::join(EttNode a, EttNode b) {
  if (a == kNoEtt) return b;
  if (b == kNoEtt) return a;
  EttNode m = a;
  while (nodes_[m].child[1] != kNoEtt) m = nodes_[m].child[1];
  splay(m);
  nodes_[m].child[1] = b;
  nodes_[b].parent = m;
  update(m);
  return m;
}

EttNode EulerTourForest::detach_left(EttNode x) {
  const EttNode l = nodes_[x].child[0];
  if (l != kNoEtt) nodes_[l].parent = kNoEtt, nodes_[x].child[0] = kNoEtt, update(x);
  return l;
}

EttNode EulerTourForest::detach_right(EttNode x) {
  const EttNode r = nodes_[x].child[1];
  if (r != kNoEtt) nodes_[r].parent = kNoEtt, nodes_[x].child[1] = kNoEtt, update(x);
  return r;
}

EttNode EulerTourForest::reroot(EttNode x) {
  // L x R becomes x R L, with x at the root and no left subtree: one join (of R and L).
  splay(x);
  const EttNode before = nodes_[x].child[0], after = nodes_[x].child[1];
  if (before != kNoEtt) nodes_[before].parent = kNoEtt;
  if (after != kNoEtt) nodes_[after].parent = kNoEtt;
  const EttNode rest = join(after, before);
  nodes_[x].child[0] = kNoEtt;
  nodes_[x].child[1] = rest;
  if (rest != kNoEtt) nodes_[rest].parent = x;
  update(x);
  return x;
}

void EulerTourForest::link(EttNode x, EttNode y, EttNode xy, EttNode yx) {
  // The tour (x R L) xy (y R' L') yx as a tree without walking it: xy at the root, the x side on
  // its left, yx on its right with the y side on yx's left. Rerooting x and then joining the
  // pieces one after another would walk and splay the right spine three more times, making link
  // 20 % of ds's instructions (armadillo's dual).
  const EttNode tx = reroot(x), ty = reroot(y);
  nodes_[yx].child[0] = ty;
  nodes_[ty].parent = yx;
  update(yx);
  nodes_[xy].child[0] = tx;
  nodes_[tx].parent = xy;
  nodes_[xy].child[1] = yx;
  nodes_[yx].parent = xy;
  update(xy);
}

void EulerTourForest::cut(EttNode a, EttNode b) {
  // The tour is P a Q b R or P b Q a R; Q is one side, P R the other.
  splay(a);
  const EttNode before_a = detach_left(a), after_a = detach_right(a);
  // b lies after a when a's right part, a root, is b or no longer a root once b is splayed (no
  // walk from b to its root).
  splay(b);
  const bool b_after_a = after_a != kNoEtt && (after_a == b || nodes_[after_a].parent != kNoEtt);
  const EttNode before_b = detach_left(b), after_b = detach_right(b);
  if (b_after_a) {
    join(before_a, after_b);  // P = before_a, Q = before_b, R = after_b
  } else {
    join(before_b, after_a);  // P = before_b, Q = after_b, R = after_a
  }
}

EttNode EulerTourForest::build(const std::vector<EttNode>& tour) {
  if (tour.empty()) return kNoEtt;
  // Each range's middle node is its subtree's root; nodes are listed parents first, so the
  // aggregates are computed in the reverse order, children first.
  struct Range {
    std::uint32_t lo, hi;
    EttNode parent;
    bool right;
  };
  std::vector<Range> ranges = {{0, static_cast<std::uint32_t>(tour.size()), kNoEtt, false}};
  std::vector<EttNode> order;
  order.reserve(tour.size());
  while (!ranges.empty()) {
    const Range r = ranges.back();
    ranges.pop_back();
    if (r.lo >= r.hi) continue;
    const std::uint32_t mid = r.lo + (r.hi - r.lo) / 2;
    const EttNode x = tour[mid];
    nodes_[x].parent = r.parent;
    if (r.parent != kNoEtt) (r.right ? nodes_[r.parent].child[1] : nodes_[r.parent].child[0]) = x;
    order.push_back(x);
    ranges.push_back({r.lo, mid, x, false});
    ranges.push_back({mid + 1, r.hi, x, true});
  }
  for (auto it = order.rbegin(); it != order.rend(); ++it) update(*it);
  return order.front();
}

void EulerTourForest::set_flag(EttNode x, int bit, bool on) {
  splay(x);
  std::uint32_t& meta = nodes_[x].meta;
  meta = on ? meta | (1u << bit) : meta & ~(1u << bit);
  update(x);
}

EttNode EulerTourForest::find_flagged(EttNode r, int bit) {
  if (!((aggregate(r) >> bit) & 1)) return kNoEtt;
  EttNode x = r;
  for (;;) {
    if (EttNode l = nodes_[x].child[0]; l != kNoEtt && ((aggregate(l) >> bit) & 1)) {
      x = l;
    } else if ((own(x) >> bit) & 1) {
      break;
    } else {
      x = nodes_[x].child[1];
    }
  }
  splay(x);
  return x;
}

}  // namespace petersen::detail
