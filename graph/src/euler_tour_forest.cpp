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
  std::uint32_t c = (own & kVertexBit) ? 1 : 0;
  std::uint32_t a = own & 3;
  if (n.left != kNoEtt) c += count(n.left), a |= aggregate(n.left);
  if (n.right != kNoEtt) c += count(n.right), a |= aggregate(n.right);
  n.meta = c << kCountShift | a << kAggregateShift | own;
}

void EulerTourForest::rotate(EttNode x) {
  Node& nx = nodes_[x];
  const EttNode y = nx.parent;
  Node& ny = nodes_[y];
  const EttNode z = ny.parent;
  if (ny.left == x) {
    ny.left = nx.right;
    if (nx.right != kNoEtt) nodes_[nx.right].parent = y;
    nx.right = y;
  } else {
    ny.right = nx.left;
    if (nx.left != kNoEtt) nodes_[nx.left].parent = y;
    nx.left = y;
  }
  ny.parent = x;
  nx.parent = z;
  if (z != kNoEtt) (nodes_[z].left == y ? nodes_[z].left : nodes_[z].right) = x;
  update(y);  // the node that went up is updated once, by splay, when it stops
}

void EulerTourForest::splay(EttNode x) {
  // Only the nodes a rotation moves down are updated on the way; x, which climbs, once at the
  // end: a zig-zig's middle node is updated when x passes it. Updating both ends of every
  // rotation was 23 % of ds's instructions (Callgrind, armadillo's dual).
  if (nodes_[x].parent == kNoEtt) return;
  do {
    const EttNode y = nodes_[x].parent, z = nodes_[y].parent;
    if (z != kNoEtt) rotate((nodes_[y].left == x) == (nodes_[z].left == y) ? y : x);
    rotate(x);
  } while (nodes_[x].parent != kNoEtt);
  update(x);
}

EttNode EulerTourForest::root(EttNode x) {
  splay(x);
  return x;
}

bool EulerTourForest::same_tree(EttNode x, EttNode y) {
  splay(x);
  EttNode r = y;
  while (nodes_[r].parent != kNoEtt) r = nodes_[r].parent;
  splay(y);  // pays for the walk
  return r == x;
}

EttNode EulerTourForest::join(EttNode a, EttNode b) {
  if (a == kNoEtt) return b;
  if (b == kNoEtt) return a;
  EttNode m = a;
  while (nodes_[m].right != kNoEtt) m = nodes_[m].right;
  splay(m);
  nodes_[m].right = b;
  nodes_[b].parent = m;
  update(m);
  return m;
}

EttNode EulerTourForest::detach_left(EttNode x) {
  const EttNode l = nodes_[x].left;
  if (l != kNoEtt) nodes_[l].parent = kNoEtt, nodes_[x].left = kNoEtt, update(x);
  return l;
}

EttNode EulerTourForest::detach_right(EttNode x) {
  const EttNode r = nodes_[x].right;
  if (r != kNoEtt) nodes_[r].parent = kNoEtt, nodes_[x].right = kNoEtt, update(x);
  return r;
}

EttNode EulerTourForest::reroot(EttNode x) {
  // L x R becomes x R L, with x at the root and no left subtree: one join (of R and L).
  splay(x);
  const EttNode before = nodes_[x].left, after = nodes_[x].right;
  if (before != kNoEtt) nodes_[before].parent = kNoEtt;
  if (after != kNoEtt) nodes_[after].parent = kNoEtt;
  const EttNode rest = join(after, before);
  nodes_[x].left = kNoEtt;
  nodes_[x].right = rest;
  if (rest != kNoEtt) nodes_[rest].parent = x;
  update(x);
  return x;
}

void EulerTourForest::link(EttNode x, EttNode y, EttNode xy, EttNode yx) {
  // The tour (x R L) xy (y R' L') yx as a tree without walking it: xy at the root, the x side on
  // its left, yx on its right with the y side on yx's left. Rerooting x and then joining the
  // pieces one after another walked and splayed the right spine three more times: link was 20 %
  // of ds's instructions (Callgrind, armadillo's dual).
  const EttNode tx = reroot(x), ty = reroot(y);
  nodes_[yx].left = ty;
  nodes_[ty].parent = yx;
  update(yx);
  nodes_[xy].left = tx;
  nodes_[tx].parent = xy;
  nodes_[xy].right = yx;
  nodes_[yx].parent = xy;
  update(xy);
}

void EulerTourForest::cut(EttNode a, EttNode b) {
  // The tour is P a Q b R or P b Q a R; Q is one side, P R the other.
  splay(a);
  const EttNode before_a = detach_left(a), after_a = detach_right(a);
  EttNode r = b;
  while (nodes_[r].parent != kNoEtt) r = nodes_[r].parent;
  splay(b);
  const EttNode before_b = detach_left(b), after_b = detach_right(b);
  if (r == after_a) {
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
    if (r.parent != kNoEtt) (r.right ? nodes_[r.parent].right : nodes_[r.parent].left) = x;
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
    if (EttNode l = nodes_[x].left; l != kNoEtt && ((aggregate(l) >> bit) & 1)) {
      x = l;
    } else if ((own(x) >> bit) & 1) {
      break;
    } else {
      x = nodes_[x].right;
    }
  }
  splay(x);
  return x;
}

}  // namespace petersen::detail
