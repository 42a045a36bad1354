#pragma once
// The splay core of link-cut trees (Sleator and Tarjan, J. Comput. Syst. Sci. 26, 1983), shared by
// LinkCutTree (the ds chooser's F_0 mirror) and the gw chooser's CoverForest, which differ only in
// the lazy flags a push hands down: both splay with the same steps, so both get the same shapes.

#include <cstdint>
#include <vector>

namespace petersen::detail {

/// A link-cut node in 16 bytes, four to a cache line: a splay step reads x, its parent and
/// grandparent, one line each. The two high bits of `up` are lazy flags of the node's subtree
/// (bit 31: its children are to be swapped; bit 30: the user's), `data` is the user's.
struct LinkCutNode {
  std::uint32_t child[2];  // left (toward the root of the preferred path), right
  std::uint32_t up;        // splay parent, or path parent for a splay root; flags in bits 30, 31
  std::uint32_t data;
};

inline constexpr std::uint32_t kLinkCutReversed = 1u << 31, kLinkCutUserFlag = 1u << 30;
inline constexpr std::uint32_t kLinkCutIdMask = kLinkCutUserFlag - 1;
inline constexpr std::uint32_t kLinkCutNil = kLinkCutIdMask;  // no node: fewer than 2^30 - 1 nodes

/// Splay and access over a LinkCutNode array. `Push` is `void(LinkCutNode* nodes, uint32_t x)`:
/// it hands x's lazy flags to x's children and clears them (x's `up` then holds its parent alone);
/// it is called only for nodes with a flag or below one.
template <class Push>
class LinkCutSplay {
 public:
  explicit LinkCutSplay(Push push = {}) : push_(push) {}

  static std::uint32_t parent(const LinkCutNode* t, std::uint32_t x) {
    return t[x].up & kLinkCutIdMask;
  }
  static void set_parent(LinkCutNode* t, std::uint32_t x, std::uint32_t p) {
    t[x].up = (t[x].up & ~kLinkCutIdMask) | p;
  }

  /// Whether x is the root of its splay tree (its `up` is a path parent or none).
  static bool is_splay_root(const LinkCutNode* t, std::uint32_t x) {
    const std::uint32_t p = parent(t, x);
    return p == kLinkCutNil || (t[p].child[0] != x && t[p].child[1] != x);
  }

  /// Makes x the root of its splay tree, x and every node above it pushed.
  void splay(LinkCutNode* t, std::uint32_t x) {
    // The climb records the path; pushing it top-down puts the children where the steps read
    // them; and the steps take x's parent and grandparent from the record, since after each
    // double step x's parent is the grandparent's old parent (no dependent load per step).
    // Only the nodes from the highest one with a flag down need a push.
    path_.clear();
    std::size_t flagged = 0;  // 1 + the index of the highest node with a flag, 0 if none
    for (std::uint32_t y = x;;) {
      path_.push_back(y);
      const std::uint32_t up = t[y].up, p = up & kLinkCutIdMask;
      if (up & ~kLinkCutIdMask) flagged = path_.size();
      if (p == kLinkCutNil || (t[p].child[0] != y && t[p].child[1] != y)) break;
      y = p;
    }
    for (std::size_t i = flagged; i-- > 0;) push_(t, path_[i]);
    const std::size_t depth = path_.size() - 1;
    std::size_t i = 0;
    for (; i + 2 <= depth; i += 2) step(t, x, path_[i + 1], path_[i + 2], i + 2 == depth);
    if (i < depth) zig(t, x, path_[i + 1]);
  }

  /// Makes the path from x's tree root to x preferred, x at the root of its splay tree, and
  /// returns the last node where the path was switched (the lca with the previous access).
  std::uint32_t access(LinkCutNode* t, std::uint32_t x) {
    std::uint32_t last = kLinkCutNil;
    for (std::uint32_t y = x; y != kLinkCutNil; y = parent(t, y)) {
      splay(t, y);
      t[y].child[1] = last;
      last = y;
    }
    splay(t, x);
    return last;
  }

 private:
  // One zig-zig or zig-zag: the two rotations' outcome written at once (z's old parent is
  // rewritten once, not twice). x, y and z are pushed: their flags are clear. The shapes are those
  // of two rotations, so the ds and gw choosers choose as before.
  static void step(LinkCutNode* t, std::uint32_t x, std::uint32_t y, std::uint32_t z,
                   bool z_is_root) {
    LinkCutNode &nx = t[x], &ny = t[y], &nz = t[z];
    const std::uint32_t w = nz.up;  // z's parent, or its path parent when z is the splay root
    if (!z_is_root) {
      LinkCutNode& nw = t[w];
      nw.child[nw.child[1] == z ? 1 : 0] = x;
    }
    nx.up = w;
    const int s = nz.child[1] == y ? 1 : 0;  // y's side below z
    if ((ny.child[1] == x ? 1 : 0) == s) {
      // zig-zig: z, y, x in a line become x, y, z.
      const std::uint32_t b = nx.child[1 - s], c = ny.child[1 - s];
      nx.child[1 - s] = y;
      ny.up = x;
      ny.child[s] = b;
      if (b != kLinkCutNil) set_parent(t, b, y);
      ny.child[1 - s] = z;
      nz.up = y;
      nz.child[s] = c;
      if (c != kLinkCutNil) set_parent(t, c, z);
    } else {
      // zig-zag: x rises between y and z.
      const std::uint32_t a = nx.child[s], b = nx.child[1 - s];
      nx.child[s] = y;
      nx.child[1 - s] = z;
      ny.up = x;
      nz.up = x;
      ny.child[1 - s] = a;
      if (a != kLinkCutNil) set_parent(t, a, y);
      nz.child[s] = b;
      if (b != kLinkCutNil) set_parent(t, b, z);
    }
  }

  // The last single rotation, y the splay root.
  static void zig(LinkCutNode* t, std::uint32_t x, std::uint32_t y) {
    LinkCutNode &nx = t[x], &ny = t[y];
    const int s = ny.child[1] == x ? 1 : 0;
    nx.up = ny.up;
    const std::uint32_t moved = nx.child[1 - s];
    ny.child[s] = moved;
    if (moved != kLinkCutNil) set_parent(t, moved, y);
    nx.child[1 - s] = y;
    ny.up = x;
  }

  [[no_unique_address]] Push push_;
  std::vector<std::uint32_t> path_;  // scratch: the splayed node's path to its splay root
};

}  // namespace petersen::detail
