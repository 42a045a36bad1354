#pragma once
// The state of the exact minimum-cost perfect matching solver (min_cost_matching.cpp) and its hot
// small functions, which stay inline here. Edmonds' primal-dual algorithm, growing the
// alternating trees of all free nodes at once, on the graph renumbered in breadth-first order
// (breadth_first_order.hpp). Its parts, one file each:
//   blossom_start.cpp           the initial duals, the greedy start, tight-edge augmentation
//   blossom_short_searches.cpp  short single-tree searches with half cycles (Blossom V's start)
//   blossom_forest.cpp          the event forest: labels, scans, the event loop, tree release
//   blossom_structure.cpp       blossoms: shortcuts, shrink, expand, dissolve, rebase, augment
//   blossom_certificate.cpp     the matching and its dual certificate in the input's ids
//
// Duals are in the odd-cut form (see min_cost_matching.hpp) on doubled costs C(e) = 2·cost(e),
// so every dual stays an integer: every root's dual is made even, tree edges are tight, and all
// labelled blossoms move by the same amount, so all labelled nodes have dual sums of one parity
// and the slack of an edge between two even nodes, which shrinks twice as fast as the others,
// is even.
//
// Blossoms: ids 0..n-1 are the nodes (trivial blossoms), ids n.. the shrunk odd cycles. A
// nontrivial blossom keeps its children in cycle order from its base child c0, and conn[i], the
// edge from child i to child i+1 (mod k), oriented (x in child i, y in child i+1); the edges
// conn[1], conn[3], .. are matched, conn[0], conn[2], .. not.
//
// Finding a node's outermost blossom and its dual sum (every set holding it) walks parents, with
// path compression: each blossom x (nodes included) keeps a shortcut up[x] to an ancestor and the
// duals from x up to it (exclusive), which are frozen while that ancestor lives (only top-level
// blossoms' duals move, and x's chain below it is not top-level). A freed blossom id bumps its
// generation, which invalidates the shortcuts naming it. Shrinking and dissolving so touch no
// node: updating every node of a new blossom makes shrinking quadratic (listing blossom nodes
// would take most of the time on the 7k-triangle bunny), and plain parent walks without
// compression take a quarter of the time on fertility-sub3, whose blossoms nest deeply.
//
// The forest labels top-level blossoms even or odd (each with its tree) and keeps one clock,
// delta: a labelled blossom's dual is its stored value plus (even) or minus (odd) delta, the
// stored value being offset by the clock when the label is set (an unlabelled blossom stores its
// dual as it is). The priority queue holds when each constraint meets zero: an edge from an even to
// an unlabelled blossom (its slack, at rate 1), an edge between two even blossoms (half its
// slack: a blossom to shrink within a tree, an augmenting path between two trees), an odd
// blossom's dual (to expand it). Entries are not removed when they go stale; each is checked
// when it comes out (the earliest key is never later than the true next event, since every
// event that speeds up is queued again at its new time: a blossom becoming even is scanned, an
// expanded odd blossom's children are scanned, a released tree's parked edges are queued). An
// edge from an even blossom into another tree's odd one waits in that tree's parked list
// instead, until the tree is released.

#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "breadth_first_order.hpp"
#include "chain_pool.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "radix_queue.hpp"

namespace petersen::weighted_detail {

inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;
/// A sum of up to n costs: n/2 matched edges of up to 2^40 each pass 2^63 from n = 2^24 on.
__extension__ using WideCost = __int128;

class BlossomSolver {
 public:
  /// Node duals at the cheapest cost at each node, every node free (blossom_start.cpp).
  /// The per-node arrays are allocated from `memory`.
  BlossomSolver(const BreadthFirstAdjacency& graph, MinCostStats& stats,
                std::pmr::memory_resource* memory);

  // ---- the start (blossom_start.cpp, blossom_short_searches.cpp), each optional

  /// Blossom V's greedy start: each free node raises its dual and takes a tight free edge.
  void greedy_start();
  /// Grows the matching to a maximum matching of the tight edges.
  void augment_tight();
  /// Short single-tree searches with a label budget, in two parts on `threads` threads.
  void short_searches(std::uint32_t threads);
  /// The nodes left free by the start.
  std::uint32_t free_nodes() const;

  /// Grows the alternating trees of all free nodes at once until none is left
  /// (blossom_forest.cpp). Throws GraphError when there is no perfect matching.
  [[gnu::noinline]] void run();

  /// The matching and the dual certificate in the input's ids, after run(); returns the
  /// matching's exact total cost (blossom_certificate.cpp).
  [[nodiscard]] WideCost write_result(std::span<const NodeId> new_node,
                                      MinCostResult& result) const;

 private:
  // kHalf: a node on a half-integral odd cycle of the short searches (see short_search), whose
  // mate record then names its successor on the cycle; none is left when the forest starts.
  enum : std::uint8_t { kUnlabelled = 0, kEven = 1, kOdd = 2, kHalf = 3 };
  static constexpr Cost kNoCost = INT64_MAX;

  struct Conn {
    NodeId x, y;  // x in child i, y in child i + 1
    EdgeId e;
  };
  // An edge event carries the edge's ends and doubled cost (checking it then reads no edge
  // array), and its source: the tree of its even end when queued, with kBothEven when the other
  // end was even too (see step). An expand event names its blossom in `id`, and no ends. 24
  // bytes in all: the queue moves them.
  struct Event {
    Cost cost2;
    std::uint32_t id;  // an edge or a blossom
    NodeId u, v;       // kNone: an expand event
    std::uint32_t source;
  };
  static constexpr std::uint32_t kBothEven = 0x80000000u;

  // ---- duals

  [[gnu::always_inline]] std::int64_t current_dual(std::uint32_t b) const {
    switch (rec_[b].label) {
      case kEven:
        return rec_[b].y + delta_;
      case kOdd:
        return rec_[b].y - delta_;
      default:
        return rec_[b].y;
    }
  }
  // v's outermost blossom; the duals of the sets holding v below it go to `below`.
  // Most nodes scanned are their own top-level blossom: that case is inline, without the walk.
  [[gnu::always_inline]] std::uint32_t find(NodeId v, std::int64_t& below) {
    const std::uint32_t p = rec_[v].parent;
    if (p == kNone) [[likely]] {
      below = 0;
      return v;
    }
    // A node right inside a top-level blossom: its own dual is all there is below, and its
    // shortcut (another array, another miss) is not read or written.
    if (rec_[p].parent == kNone) {
      below = rec_[v].y;
      return p;
    }
    return find_nested(v, below);
  }
  // Out of line (blossom_structure.cpp), so that find stays small where it is inlined.
  [[gnu::noinline]] std::uint32_t find_nested(NodeId v, std::int64_t& below);
  std::uint32_t top(NodeId v) {
    std::int64_t below;
    return find(v, below);
  }

  // Stores b's current dual as it is; the caller unlabels b.
  void settle(std::uint32_t b) { rec_[b].y = current_dual(b); }

  // ---- the queue

  void push_edge(std::int64_t key, const Slot& slot, NodeId from, std::uint32_t source) {
    queue_.push(static_cast<std::uint64_t>(key), {slot.cost2, slot.edge, from, slot.other, source});
    ++stats_.queue_pushes;
  }
  void push_expand(std::int64_t key, std::uint32_t b) {
    queue_.push(static_cast<std::uint64_t>(key), {0, b, kNone, kNone, kNone});
    ++stats_.queue_pushes;
  }
  std::span<const Slot> slots_of(NodeId v) const { return graph_.slots_of(v); }

  void set_mate(NodeId v, EdgeId e, NodeId w) { rec_[v].mate = {e, w}; }

  // ---- blossom structure (blossom_structure.cpp)

  void leaves(std::uint32_t b, std::vector<NodeId>& out) const;
  std::uint32_t child_holding(std::uint32_t b, NodeId v) const;
  std::uint32_t new_blossom();
  void free_blossom(std::uint32_t b);
  void dissolve(std::uint32_t b);
  void shrink(NodeId u, NodeId v, EdgeId e);
  void expand_odd(std::uint32_t b);
  void augment_from(NodeId s, EdgeId along, NodeId across);
  void rebase(std::uint32_t b, NodeId v);

  // ---- labels, scans and the event loop (blossom_forest.cpp)

  void set_label(std::uint32_t b, std::uint8_t label, NodeId from, NodeId to, EdgeId e,
                 std::uint32_t tree);
  void label_even(std::uint32_t b, NodeId from, NodeId to, EdgeId e, std::uint32_t tree);
  void label_odd(std::uint32_t b, NodeId from, NodeId to, EdgeId e, std::uint32_t tree);
  void scan_even(std::uint32_t b);
  void scan_even_node(NodeId x);
  void scan_unlabelled(std::uint32_t b);
  void step();
  void release(std::uint32_t t);

  // ---- short searches (blossom_short_searches.cpp)

  struct ShortEvent {
    std::int64_t key;  // the search's clock when the edge turns tight
    Cost cost2;
    EdgeId edge;
    NodeId u, w;  // u even
    bool operator>(const ShortEvent& other) const { return key > other.key; }
  };
  // The short searches of one part of the nodes, [lo, hi): its roots (free nodes, in id order),
  // its own search stamp, heap and labels. Only its searches read or write its nodes' records,
  // marks and links.
  struct ShortPart {
    NodeId lo = 0, hi = 0;
    std::uint32_t stamp = 0;            // mark_[v] == stamp: v is labelled in the current search
    std::vector<NodeId> roots{};        // free nodes, in id order
    std::vector<NodeId> handed_over{};  // roots whose search met a node of another part
    std::vector<ShortEvent> heap{};
    std::vector<NodeId> labelled{};
    std::vector<NodeId> cycles{};  // a node of each half cycle closed (some since broken)
    std::uint64_t labels = 0, augmentations = 0;
  };
  enum class ShortEnd : std::uint8_t { done, budget, other_part };

  // Passes over part.roots with budgets 16, 128, .., kMostBudget (see short_searches), until
  // the part's searches have given `most` labels.
  static constexpr std::uint32_t kMostBudget = 65536;
  void short_passes(ShortPart& part, std::uint64_t most);
  ShortEnd short_search(ShortPart& part, NodeId root, std::uint32_t budget);
  void close_half_cycle(ShortPart& part, NodeId root, const ShortEvent& closing);
  void break_cycle_at(NodeId w);

  const BreadthFirstAdjacency& graph_;
  // A node's matched edge and the node across it (the grow step reads both at once).
  struct Mate {
    EdgeId edge = kNoEdge;
    NodeId node = kNone;
  };
  MinCostStats& stats_;
  std::uint32_t n_;
  std::size_t ids_;  // the most ids: n nodes and n/2 blossoms (the arrays below are reserved so)
  // What finding a blossom and its current dual reads, in one cache line's half: the stored
  // dual y (offset by the clock while labelled, see the top), the parent blossom (kNone at the
  // top level), the tree of a labelled blossom, the generation its shortcuts are checked
  // against, the label, and a node's mate, which growing into an unlabelled node reads right
  // after its record. Separate arrays cost a cache miss each per neighbour scanned.
  struct alignas(32) Record {
    std::int64_t y = 0;
    std::uint32_t parent = kNone;
    std::uint32_t tree = kNone;
    std::uint32_t generation = 0;  // bumped when the blossom id is freed (see the top)
    Mate mate;                     // nodes only
    std::uint8_t label = kUnlabelled;
  };
  std::pmr::vector<Record> rec_;
  std::pmr::vector<NodeId> base_;
  // A labelled blossom's tree edge: `from` in the tree parent, `to` in this blossom; one record,
  // as labelling writes the three together and the walks up the tree read them together.
  struct TreeLink {
    NodeId from = kNone;
    NodeId to = kNone;
    EdgeId edge = kNoEdge;
  };
  std::pmr::vector<TreeLink> link_;
  std::pmr::vector<std::uint32_t> mark_;
  // The shortcuts (see the top): x's ancestor `to`, valid while to's generation is `generation`,
  // and the duals from x up to it; one record, read together on every walk.
  struct Shortcut {
    std::int64_t sum = 0;
    std::uint32_t to = kNone;
    std::uint32_t generation = 0;
  };
  std::pmr::vector<Shortcut> up_;
  std::vector<std::pair<std::uint32_t, std::int64_t>> walked_;
  std::uint32_t stamp_ = 0;
  std::vector<std::vector<std::uint32_t>> children_;
  std::vector<std::vector<Conn>> conn_;
  std::vector<std::uint32_t> free_ids_;
  std::int64_t delta_ = 0;
  RadixQueue<Event> queue_;
  // Per tree: the blossoms labelled in it, and the edges from other trees' even blossoms into its
  // odd ones (see release); lists in two pools, the heads by tree.
  static constexpr std::uint32_t kEnd = ChainPool<std::uint32_t>::kEnd;
  ChainPool<std::uint32_t> members_;
  std::vector<std::uint32_t> member_heads_;
  ChainPool<Event> parked_;
  std::vector<std::uint32_t> parked_heads_;
  std::size_t alive_trees_ = 0;
  std::vector<std::uint8_t> tree_alive_;    // by tree: 0 once released
  std::vector<std::uint32_t> dissolvable_;  // release: its blossoms of dual zero
  std::vector<NodeId> scratch_;
  std::vector<std::uint32_t> odd_children_;
  std::vector<std::uint32_t> dissolve_stack_, expand_children_, even_children_;
  std::vector<Conn> expand_conn_;
  std::vector<std::uint32_t> path_u_, path_v_;
  mutable std::vector<std::uint32_t> leaf_stack_;
  std::vector<std::pair<std::uint32_t, NodeId>> rebase_stack_;
  std::vector<std::uint32_t> rebase_chain_;
};

}  // namespace petersen::weighted_detail