#pragma once
// Unpaired triangles moved to the border of their part by alternating paths, so that the repair,
// which looks only near the cuts, finds them there.

#include <cstdint>
#include <span>

#include "petersen/graph/csr_graph.hpp"
#include "petersen/matching/matching.hpp"

namespace petersen::partition_detail {

struct MoveStats {
  std::uint64_t moved = 0;     ///< free nodes that handed their freedom to a border node
  std::uint64_t stranded = 0;  ///< free nodes off the border that no search took there
};

/// For each free node u not on the border: a breadth-first search over even-length alternating
/// paths from u (an unmatched edge to x, then x's matched edge to y) for a border node y; the
/// path is flipped, so that u is matched and y is free, and the matching keeps its size. A path
/// that would repeat a node (it ran through an odd cycle) is not flipped and the search goes on.
/// Any augmenting path of the whole mesh from u leaves the part through a border node it reaches
/// this way, so a maximum matching loses nothing. The searches stop once they have given `budget`
/// labels in all (the free nodes left are stranded). O(budget), plus 8 bytes per node of search
/// state.
MoveStats move_to_border(const CsrGraph& graph, Matching& matching,
                         std::span<const std::uint8_t> on_border, std::uint64_t budget);

}  // namespace petersen::partition_detail
