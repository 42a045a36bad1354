#include "euler_tour_forest.hpp"

namespace petersen::detail {

namespace {
constexpr std::uint8_t kVertexBit = 4;
}

EttNode EulerTourForest::make_node(std::uint32_t owner, bool vertex) {
  left_.push_back(kNoEtt);
  right_.push_back(kNoEtt);
  parent_.push_back(kNoEtt);
  count_.push_back(vertex ? 1 : 0);
  owner_.push_back(owner);
  own_.push_back(vertex ? kVertexBit : 0);
  aggregate_.push_back(0);
  return static_cast<EttNode>(left_.size() - 1);
}

EttNode EulerTourForest::make_vertex(std::uint32_t owner) {
  return make_node(owner, true);
}

EttNode EulerTourForest::make_arc(std::uint32_t owner) {
  if (free_.empty()) return make_node(owner, false);
  const EttNode a = free_.back();
  free_.pop_back();
  left_[a] = right_[a] = parent_[a] = kNoEtt;
  owner_[a] = owner;
  own_[a] = aggregate_[a] = 0;
  return a;
}

void EulerTourForest::update(EttNode x) {
  std::uint32_t c = (own_[x] & kVertexBit) ? 1 : 0;
  std::uint8_t a = own_[x] & 3;
  if (EttNode l = left_[x]; l != kNoEtt) c += count_[l], a |= aggregate_[l];
  if (EttNode r = right_[x]; r != kNoEtt) c += count_[r], a |= aggregate_[r];
  count_[x] = c;
  aggregate_[x] = a;
}

void EulerTourForest::rotate(EttNode x) {
  const EttNode y = parent_[x], z = parent_[y];
  if (left_[y] == x) {
    left_[y] = right_[x];
    if (right_[x] != kNoEtt) parent_[right_[x]] = y;
    right_[x] = y;
  } else {
    right_[y] = left_[x];
    if (left_[x] != kNoEtt) parent_[left_[x]] = y;
    left_[x] = y;
  }
  parent_[y] = x;
  parent_[x] = z;
  if (z != kNoEtt) (left_[z] == y ? left_[z] : right_[z]) = x;
  update(y);
  update(x);
}

void EulerTourForest::splay(EttNode x) {
  while (parent_[x] != kNoEtt) {
    const EttNode y = parent_[x], z = parent_[y];
    if (z != kNoEtt) rotate((left_[y] == x) == (left_[z] == y) ? y : x);
    rotate(x);
  }
}

EttNode EulerTourForest::root(EttNode x) {
  splay(x);
  return x;
}

bool EulerTourForest::same_tree(EttNode x, EttNode y) {
  splay(x);
  EttNode r = y;
  while (parent_[r] != kNoEtt) r = parent_[r];
  splay(y);  // pays for the walk
  return r == x;
}

EttNode EulerTourForest::join(EttNode a, EttNode b) {
  if (a == kNoEtt) return b;
  if (b == kNoEtt) return a;
  EttNode m = a;
  while (right_[m] != kNoEtt) m = right_[m];
  splay(m);
  right_[m] = b;
  parent_[b] = m;
  update(m);
  return m;
}

EttNode EulerTourForest::detach_left(EttNode x) {
  const EttNode l = left_[x];
  if (l != kNoEtt) parent_[l] = kNoEtt, left_[x] = kNoEtt, update(x);
  return l;
}

EttNode EulerTourForest::detach_right(EttNode x) {
  const EttNode r = right_[x];
  if (r != kNoEtt) parent_[r] = kNoEtt, right_[x] = kNoEtt, update(x);
  return r;
}

EttNode EulerTourForest::reroot(EttNode x) {
  splay(x);
  const EttNode before = detach_left(x);
  return join(x, before);
}

void EulerTourForest::link(EttNode x, EttNode y, EttNode xy, EttNode yx) {
  const EttNode tx = reroot(x);
  const EttNode ty = reroot(y);
  join(join(join(tx, xy), ty), yx);
}

void EulerTourForest::cut(EttNode a, EttNode b) {
  // The tour is P a Q b R or P b Q a R; Q is one side, P R the other.
  splay(a);
  const EttNode before_a = detach_left(a), after_a = detach_right(a);
  EttNode r = b;
  while (parent_[r] != kNoEtt) r = parent_[r];
  splay(b);
  const EttNode before_b = detach_left(b), after_b = detach_right(b);
  if (r == after_a) {
    join(before_a, after_b);  // P = before_a, Q = before_b, R = after_b
  } else {
    join(before_b, after_a);  // P = before_b, Q = after_b, R = after_a
  }
}

void EulerTourForest::set_flag(EttNode x, int bit, bool on) {
  splay(x);
  own_[x] = static_cast<std::uint8_t>(on ? own_[x] | (1u << bit) : own_[x] & ~(1u << bit));
  update(x);
}

EttNode EulerTourForest::find_flagged(EttNode r, int bit) {
  if (!((aggregate_[r] >> bit) & 1)) return kNoEtt;
  EttNode x = r;
  for (;;) {
    if (EttNode l = left_[x]; l != kNoEtt && ((aggregate_[l] >> bit) & 1)) {
      x = l;
    } else if ((own_[x] >> bit) & 1) {
      break;
    } else {
      x = right_[x];
    }
  }
  splay(x);
  return x;
}

}  // namespace petersen::detail
