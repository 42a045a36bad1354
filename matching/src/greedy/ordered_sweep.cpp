// The ordered sweep: an initial pairing in the nodes' own order, for graphs whose numbering
// follows the surface (the bench's plates, meshes stored in a spatial order, some scanned
// meshes), tried in PS's place.
//   Nodes are taken in id order; a node still free is paired with the free neighbour that has
//   the fewest free neighbours left (the min-degree rule), and a node left with one free
//   neighbour is paired at once (Karp and Sipser's forced move; last in, first out). A node with
//   no free neighbour left stays unpaired.
// Why: PS's pass costs about two BFS passes (its priority sets, random draws and a rescan of each
// node leaving priority 0; a flat profile, no one hot spot), while the sweep reads each node's
// row and its neighbours' state bytes once, in the order of the rows. Where that order is local
// the pairing front is a line moving over the surface and strands no more nodes than PS (A2: 230
// against 690; B2: 514 against 550). petersen_bench, old and new alternated twice at load 4-5
// (bench/RESULTS.md, "Stop 17"): A2 0.288 and 0.311 s with PS against 0.082 and 0.133, B2 0.510
// and 0.434 against 0.135 and 0.132.
// Where the order jumps about (a subdivided mesh numbers each level's triangles after the
// coarser ones: fertility-sub3's median neighbour gap is 0.75 n), the front breaks into pieces
// everywhere and strands 1-3 % of the nodes (armadillo-sub2 17,174 against PS's 390), so the
// sweep refuses such an order before touching anything: it runs only when the median, over
// nodes sampled evenly, of a node's largest id distance to a neighbour is at most kLocalGap
// times √n. (A row-major grid's is about √n; the plates' 13-1,110, the subdivided meshes'
// 0.5-0.75 n.)

#include <algorithm>
#include <cmath>
#include <vector>

#include "greedy.hpp"
#include "neighbour_table.hpp"

namespace petersen {

namespace {

// The state byte, as in PS: bits 0-1 free-neighbour count, bit 4 out of play (paired or
// stranded), bit 5 paired, whose low bits then hold the index of the pairing edge in the row.
constexpr std::uint8_t kFreeMask = 3;
constexpr std::uint8_t kOut = 1 << 4;
constexpr std::uint8_t kPaired = 1 << 5;
constexpr std::uint8_t kStart = 3;

// The order counts as local up to this many √n of median largest gap. Measured (bench/RESULTS.md,
// "Stop 17"): the plates 0.01-1.9, where the sweep beat PS by 1.3-3.7x; homer 3.65, rocker-arm 1.2,
// fandisk 0.7, where it beat PS warm by 1.2-1.9x; nefertiti 4.62, where it left 544 nodes against
// PS's 82 and lost warm (15 against 12 ms); bunny 9.0, where it lost too.
constexpr double kLocalGap = 4.0;
constexpr std::uint32_t kSamples = 1024;

bool order_is_local(const NeighbourTable& table) {
  const std::uint32_t n = table.node_count();
  if (n == 0) return true;
  const std::uint32_t step = std::max<std::uint32_t>(1, n / kSamples);
  std::vector<std::uint32_t> gaps;
  gaps.reserve(n / step + 1);
  for (NodeId v = 0; v < n; v += step) {
    std::uint32_t widest = 0;
    for (NodeId u : table.neighbours(v)) widest = std::max(widest, u > v ? u - v : v - u);
    gaps.push_back(widest);
  }
  const auto middle = gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2);
  std::nth_element(gaps.begin(), middle, gaps.end());
  return *middle <= kLocalGap * std::sqrt(double(n));
}

class OrderedSweep {
 public:
  OrderedSweep(NeighbourTable& table, HugeVector<EdgeId>* mate)
      : table_(table), mate_(mate), state_(table.node_count(), kStart) {}

  std::uint32_t run() {
    const std::uint32_t n = table_.node_count();
    for (NodeId s = 0; s < n; ++s) {
      if (state_[s] & kOut) continue;
      pair_from(s);
      while (!forced_.empty()) {
        const NodeId v = forced_.back();
        forced_.pop_back();
        if (!(state_[v] & kOut)) pair_from(v);
      }
    }
    return table_.start_searches(
        [&](NodeId v) { return state_[v] & kPaired ? state_[v] & kFreeMask : -1; }, mate_);
  }

 private:
  std::span<const NodeId, 3> neighbours(NodeId v) const { return table_.neighbours(v); }

  // Pairs v, in play, with its free neighbour of fewest free neighbours; on ties, the one of
  // smallest id: the nearest to the front (every node before the sweep's position is out), so the
  // front stays straight. The first in the row instead left 2,938 nodes on B2 against 514, and
  // 12,642 on A2 against 230 (labels 13.1M and 1.49M against 2.3M and 1.18M; on the generated
  // plates the same within 10 %: bench/RESULTS.md, "Stop 17").
  void pair_from(NodeId v) {
    int best = -1;
    int best_free = kStart + 1;
    for (int i = 0; i < 3; ++i) {
      const NodeId u = neighbours(v)[i];
      const std::uint8_t s = state_[u];
      const int free = s & kFreeMask;
      if (s & kOut) continue;
      if (free < best_free || (free == best_free && u < neighbours(v)[best])) {
        best = i;
        best_free = free;
      }
    }
    if (best < 0) {  // every neighbour is out: v stays unpaired
      state_[v] |= kOut;
      return;
    }
    const NodeId u = neighbours(v)[best];
    state_[v] = static_cast<std::uint8_t>(kOut | kPaired | best);
    state_[u] = static_cast<std::uint8_t>(kOut | kPaired |
                                          table_.index_across(v, best, u, mate_ != nullptr));
    for (NodeId w : {v, u}) {
      for (NodeId z : neighbours(w)) {
        if (state_[z] & kOut) continue;
        const int free = --state_[z] & kFreeMask;
        if (free == 0) {
          state_[z] |= kOut;  // its last free neighbour was just taken
        } else if (free == 1) {
          forced_.push_back(z);
        }
      }
    }
  }

  NeighbourTable& table_;
  HugeVector<EdgeId>* mate_;  // nullptr: the matching is the table's state only
  std::vector<std::uint8_t> state_;
  std::vector<NodeId> forced_;  // nodes left with one free neighbour, to pair next
};

}  // namespace

std::optional<std::uint32_t> ordered_sweep(NeighbourTable& table, HugeVector<EdgeId>* mate_edge) {
  if (!order_is_local(table)) return std::nullopt;
  return OrderedSweep(table, mate_edge).run();
}

}  // namespace petersen
