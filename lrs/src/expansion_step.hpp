#pragma once
// The expansion step of LRS (paper §3.3.1, Algorithms 3.1–3.4): undo the contractions, flipping
// safely flippable edges, and pair the expanded triangles as it goes.

#include <cstdint>
#include <span>
#include <vector>

#include "edge_contraction.hpp"
#include "petersen/graph/memory.hpp"
#include "petersen/matching/matching.hpp"

namespace petersen::lrs {

/// Per-edge state of the expansion (edge ids of the triangulation).
enum EdgeState : std::uint8_t {
  kFlipped = 1,  ///< the paper's flipped(e): K holds the flip of this edge of T
  kMatched = 2,  ///< e is in M: its dual pairs the two faces of K on either side of it
};

struct ExpansionResult {
  std::pmr::vector<std::uint8_t> edge_state;  ///< EdgeState bits per edge id
  std::uint32_t flipped_edges = 0;            ///< edges flipped in K at the end
  std::uint32_t matched_edges = 0;            ///< |M|
  std::uint64_t unflips = 0;                  ///< Algorithm 3.2's unflips of [x, y]
  /// How often each branch ran: Algorithm 3.1 line 7 (neither split edge in M), then Algorithms
  /// 3.2, 3.3 and 3.4.
  std::uint64_t cases[4] = {0, 0, 0, 0};
};

/// Algorithm 3.1: undoes `stack` (from contract_to_irreducible) from the back with vertex splits
/// on `tri`, which must be the irreducible T′ those contractions left. The splits act on K itself,
/// T with some edges flipped (edge ids keep naming the same edges of T; a flipped edge holds its
/// flip), so at the end `tri` is K: the input's vertices and face count, the same surface, and
/// flipped edges marked kFlipped. M pairs every face of K except the faces of T′ (Proposition
/// 3.3). Throws std::logic_error if the paper's invariant fails (a split edge flipped, or a
/// degree-3 vertex whose side holds anything but the flip of [x, y]). O(E).
ExpansionResult expand_and_match(Triangulation& tri, std::span<const ContractionRecord> stack);

}  // namespace petersen::lrs
