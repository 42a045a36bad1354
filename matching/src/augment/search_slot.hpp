#pragma once
// One node's state in the alternating forest (alternating_forest.hpp), on its own so that a
// NeighbourTable can keep it beside the node's neighbours.

#include <cstdint>

#include "petersen/graph/cubic_graph.hpp"

namespace petersen::augment_detail {

enum Label : std::uint32_t { unlabelled = 0, even = 1, odd = 2, bridged = 3 };
inline constexpr std::uint32_t kNone = 0xFFFFFFFFu;

/// One node's search state: `mate` is its mate node (kNoNode when free). `tag` is tree << 4 | side
/// << 3 | mark << 2 | label (0: never labelled). `link` is, for an odd node, the edge it was
/// labelled over; for a bridged node, its bridge, with `side` telling which end is on its side;
/// for an even node (not a root), the even node two steps up its tree (the pred of its mate), so a
/// blossom walk climbs one slot per step. `base` is the disjoint-set parent; a set's root is its
/// blossom's base. A fresh slot, before any search: {mate, 0, kNone, the node itself}.
struct alignas(16) Slot {
  NodeId mate;
  std::uint32_t tag;
  std::uint32_t link;
  NodeId base;
};

}  // namespace petersen::augment_detail
