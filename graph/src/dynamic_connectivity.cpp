#include "petersen/graph/dynamic_connectivity.hpp"

#include <algorithm>
#include <bit>
#include <numeric>
#include <utility>

#include "euler_tour_forest.hpp"

namespace petersen {

using detail::EttNode;
using detail::kNoEtt;

namespace {
constexpr std::uint32_t kNone = 0xFFFFFFFFu;
constexpr int kNonTreeFlag = 0;  // a vertex node with non-tree edges of its level
constexpr int kTreeFlag = 1;     // an arc of a tree edge whose level is this forest's level
constexpr int kSampleSize = 8;   // non-tree edges tried before a search raises levels

}  // namespace

DynamicConnectivity::DynamicConnectivity(std::uint32_t node_count, std::uint32_t edge_capacity)
    : ett_(std::make_unique<detail::EulerTourForest>()),
      ends_(2 * std::size_t{edge_capacity}, kNoNode),
      level_(edge_capacity, 0),
      state_(edge_capacity, State::absent),
      next_(2 * std::size_t{edge_capacity}, kNone),
      prev_(2 * std::size_t{edge_capacity}, kNone),
      vertex_block_(node_count),
      arc_block_(edge_capacity) {
  // Vertex nodes of higher levels and arcs, with the arcs recycled, came to 8.2 nodes per vertex
  // on armadillo's dual and 7.9 on fertility-sub3's: reserved at once, the node arrays are not
  // copied as they grow (the copies would be a quarter of ds's fresh memory; untouched capacity
  // costs no memory).
  // The pool, with blocks recycled, ends at 10.8 and 12.7 entries per vertex on the same inputs.
  const std::size_t nodes = std::size_t{9} * node_count;
  ett_->reserve(nodes);
  head_.reserve(nodes);
  pool_.reserve(std::size_t{14} * node_count);
  for (NodeId v = 0; v < node_count; ++v) {
    const EttNode x = ett_->make_vertex(v);  // node v: see vertex_node
    vertex_block_[v] = {static_cast<std::uint32_t>(pool_.size()), 1};
    pool_.push_back(x);
  }
  head_.resize(node_count, kNone);
}

DynamicConnectivity::~DynamicConnectivity() = default;
DynamicConnectivity::DynamicConnectivity(DynamicConnectivity&&) noexcept = default;
DynamicConnectivity& DynamicConnectivity::operator=(DynamicConnectivity&&) noexcept = default;

void DynamicConnectivity::grow_block(Block& block, std::uint32_t i) {
  // Capacities are powers of two; a block given up (outgrown here, or its edge's arcs gone in
  // delete_edge) is handed out again for the next request of its size. Left behind, they would
  // be most of the pool: 39 entries per vertex on fertility-sub3's dual, grown by copying to
  // 134 MB.
  const std::uint32_t grown = std::bit_ceil(std::max(i + 1, 2 * block.capacity));
  std::vector<std::uint32_t>& spare = free_blocks_[std::countr_zero(grown)];
  std::uint32_t fresh;
  if (!spare.empty()) {
    fresh = spare.back();
    spare.pop_back();
    std::fill_n(pool_.begin() + fresh, grown, kNone);
  } else {
    fresh = static_cast<std::uint32_t>(pool_.size());
    pool_.resize(pool_.size() + grown, kNone);
  }
  std::copy_n(pool_.begin() + block.base, block.capacity, pool_.begin() + fresh);
  release_block(block);
  block = {fresh, grown};
}

void DynamicConnectivity::release_block(Block& block) {
  if (block.capacity != 0) free_blocks_[std::countr_zero(block.capacity)].push_back(block.base);
  block = {};
}

std::uint32_t DynamicConnectivity::vertex_node(NodeId v, int level) {
  // The constructor makes the level-0 nodes first, in vertex order, so v's is node v: connected()
  // and every level-0 update skip the pool's two dependent loads.
  if (level == 0) return v;
  Block& block = vertex_block_[v];
  reserve_block(block, static_cast<std::uint32_t>(level));
  if (const std::uint32_t x = pool_[block.base + level]; x != kNone) return x;
  const EttNode x = ett_->make_vertex(v);
  pool_[vertex_block_[v].base + level] = x;
  if (head_.size() <= x) head_.resize(std::size_t{x} + 1, kNone);
  return x;
}

std::uint32_t& DynamicConnectivity::arc(EdgeId e, int level, int direction) {
  Block& block = arc_block_[e];
  reserve_block(block, static_cast<std::uint32_t>(2 * level + 1));
  return pool_[block.base + 2 * level + direction];
}

void DynamicConnectivity::link_tree_edge(EdgeId e, int level) {
  const EttNode x = vertex_node(endpoint(e, 0), level);
  const EttNode y = vertex_node(endpoint(e, 1), level);
  const EttNode a = ett_->make_arc(e), b = ett_->make_arc(e);
  arc(e, level, 0) = a;
  arc(e, level, 1) = b;
  ett_->link(x, y, a, b);
  if (level == level_[e]) ett_->set_flag(a, kTreeFlag, true);
}

void DynamicConnectivity::add_non_tree(EdgeId e) {
  for (int side = 0; side < 2; ++side) {
    const EttNode x = vertex_node(endpoint(e, side), level_[e]);
    const std::uint32_t h = 2 * e + side;
    next_[h] = head_[x];
    prev_[h] = kNone;
    if (head_[x] != kNone) {
      prev_[head_[x]] = h;
    } else {
      ett_->set_flag(x, kNonTreeFlag, true);
    }
    head_[x] = h;
  }
}

void DynamicConnectivity::remove_non_tree(EdgeId e) {
  for (int side = 0; side < 2; ++side) {
    const EttNode x = vertex_node(endpoint(e, side), level_[e]);
    const std::uint32_t h = 2 * e + side;
    if (prev_[h] != kNone) {
      next_[prev_[h]] = next_[h];
    } else {
      head_[x] = next_[h];
    }
    if (next_[h] != kNone) prev_[next_[h]] = prev_[h];
    if (head_[x] == kNone) ett_->set_flag(x, kNonTreeFlag, false);
  }
}

bool DynamicConnectivity::insert_edge(EdgeId e, NodeId u, NodeId v) {
  ends_[2 * std::size_t{e}] = u;
  ends_[2 * std::size_t{e} + 1] = v;
  level_[e] = 0;
  if (u != v && !connected(u, v)) {
    state_[e] = State::tree;
    link_tree_edge(e, 0);
    return true;
  }
  state_[e] = State::non_tree;
  add_non_tree(e);
  return false;
}

void DynamicConnectivity::insert_all(std::span<const NodeId> ends) {
  const auto n = static_cast<std::uint32_t>(vertex_block_.size());
  const auto k = static_cast<EdgeId>(ends.size() / 2);
  // The forest insert_edge would choose, edge by edge: union-find in id order. Non-tree edges go
  // into their lists now, while every vertex node is alone (set_flag's splay is then free).
  std::vector<NodeId> uf(n);
  std::iota(uf.begin(), uf.end(), 0);
  const auto find = [&](NodeId x) {
    while (uf[x] != x) x = uf[x] = uf[uf[x]];
    return x;
  };
  std::vector<std::uint32_t> offset(std::size_t{n} + 1, 0);
  for (EdgeId e = 0; e < k; ++e) {
    const NodeId u = ends[2 * std::size_t{e}], v = ends[2 * std::size_t{e} + 1];
    ends_[2 * std::size_t{e}] = u;
    ends_[2 * std::size_t{e} + 1] = v;
    level_[e] = 0;
    const NodeId ru = find(u), rv = find(v);
    if (ru != rv) {
      uf[ru] = rv;
      state_[e] = State::tree;
      ++offset[u + 1];
      ++offset[v + 1];
    } else {
      state_[e] = State::non_tree;
      add_non_tree(e);
    }
  }
  // The tree edges at each vertex, then each tree's Euler tour by an iterative depth-first walk:
  // the vertex, and for each child edge its first arc, the child's tour, its second arc (the
  // order link() makes), the first arc flagged as a tree edge of its level.
  for (NodeId v = 0; v < n; ++v) offset[v + 1] += offset[v];
  std::vector<EdgeId> tree_edges(offset[n]);
  std::vector<std::uint32_t> fill(offset.begin(), offset.end() - 1);
  for (EdgeId e = 0; e < k; ++e)
    if (state_[e] == State::tree) {
      tree_edges[fill[ends_[2 * std::size_t{e}]]++] = e;
      tree_edges[fill[ends_[2 * std::size_t{e} + 1]]++] = e;
    }
  std::vector<std::uint8_t> seen(n, 0);
  std::vector<EttNode> tour;
  struct Frame {
    NodeId v;
    std::uint32_t next;
    EdgeId in;
  };
  std::vector<Frame> stack;
  for (NodeId root = 0; root < n; ++root) {
    if (seen[root] || offset[root] == offset[root + 1]) continue;
    seen[root] = 1;
    tour.assign(1, vertex_node(root, 0));
    stack.assign(1, {root, offset[root], kNoEdge});
    while (!stack.empty()) {
      Frame& top = stack.back();
      if (top.next == offset[top.v + 1]) {
        const EdgeId in = top.in;
        stack.pop_back();
        if (in == kNoEdge) continue;
        const EttNode b = ett_->make_arc(in);
        arc(in, 0, 1) = b;
        tour.push_back(b);
        continue;
      }
      const EdgeId e = tree_edges[top.next++];
      const NodeId w = endpoint(e, 0) ^ endpoint(e, 1) ^ top.v;
      if (seen[w]) continue;  // the edge to top.v's parent
      seen[w] = 1;
      const EttNode a = ett_->make_arc(e);
      arc(e, 0, 0) = a;
      ett_->set_flag(a, kTreeFlag, true);
      tour.push_back(a);
      tour.push_back(vertex_node(w, 0));
      stack.push_back({w, offset[w], e});  // `top` dangles from here on
    }
    ett_->build(tour);
  }
}

DynamicConnectivity::Deletion DynamicConnectivity::delete_edge(EdgeId e) {
  const State state = state_[e];
  if (state == State::non_tree) {
    remove_non_tree(e);
    state_[e] = State::absent;
    return {};
  }
  state_[e] = State::absent;
  ++replacement_searches_;
  const int top = level_[e];
  for (int i = 0; i <= top; ++i) {
    const EttNode a = arc(e, i, 0), b = arc(e, i, 1);
    ett_->cut(a, b);
    ett_->free_arc(a);
    ett_->free_arc(b);
    arc(e, i, 0) = arc(e, i, 1) = kNone;
  }
  release_block(arc_block_[e]);
  // HDT: search the levels from the edge's own downward; a replacement of level i is linked
  // into F_0..F_i.
  for (int i = top; i >= 0; --i) {
    if (const EdgeId r = replace(endpoint(e, 0), endpoint(e, 1), i); r != kNoEdge) return {true, r};
  }
  return {true, kNoEdge};
}

EdgeId DynamicConnectivity::replace(NodeId u, NodeId v, int level) {
  EttNode small = vertex_node(u, level), large = vertex_node(v, level);
  if (ett_->vertex_count(ett_->root(small)) > ett_->vertex_count(ett_->root(large)))
    std::swap(small, large);
  // Sampling (Iyer, Karger, Rahul and Thorup, JEA 2001): a few non-tree edges at the smaller
  // tree's first vertex that has any; one that reconnects is taken before any level is raised.
  if (const EttNode x = ett_->find_flagged(ett_->root(small), kNonTreeFlag); x != kNoEtt) {
    int budget = kSampleSize;
    for (std::uint32_t h = head_[x]; h != kNone && budget > 0; h = next_[h], --budget) {
      const EdgeId g = h / 2;
      const NodeId y = endpoint(g, 1 - static_cast<int>(h % 2));
      if (ett_->same_tree(vertex_node(y, level), small)) continue;
      remove_non_tree(g);
      state_[g] = State::tree;
      for (int i = 0; i <= level; ++i) link_tree_edge(g, i);
      return g;
    }
  }
  // The smaller tree's tree edges of this level rise one level (it is at most half as large).
  // Raising one changes only the forest a level up, so the arc just found and unflagged is still
  // its tree's splay root and the next search starts there: splaying `small` back up before
  // each search would be 2.8 % of ds's instructions (armadillo's dual).
  for (EttNode a, r = ett_->root(small); (a = ett_->find_flagged(r, kTreeFlag)) != kNoEtt; r = a) {
    const EdgeId f = ett_->owner(a);
    ett_->set_flag(a, kTreeFlag, false);
    level_[f] = static_cast<std::uint8_t>(level + 1);
    link_tree_edge(f, level + 1);
  }
  // Its non-tree edges of this level either reconnect or rise one level.
  for (EttNode x; (x = ett_->find_flagged(ett_->root(small), kNonTreeFlag)) != kNoEtt;) {
    while (head_[x] != kNone) {
      const std::uint32_t h = head_[x];
      const EdgeId g = h / 2;
      const NodeId y = endpoint(g, 1 - static_cast<int>(h % 2));
      remove_non_tree(g);
      if (!ett_->same_tree(vertex_node(y, level), small)) {
        state_[g] = State::tree;
        for (int i = 0; i <= level; ++i) link_tree_edge(g, i);
        return g;
      }
      level_[g] = static_cast<std::uint8_t>(level + 1);
      add_non_tree(g);
    }
  }
  return kNoEdge;
}

bool DynamicConnectivity::connected(NodeId u, NodeId v) {
  return u == v || ett_->same_tree(vertex_node(u, 0), vertex_node(v, 0));
}

}  // namespace petersen
