#pragma once
// Brute-force bridge tests on the current reduced graph: the frink chooser and the debug mode.

#include <cstdint>

#include "reduction/reduction_graph.hpp"

namespace petersen::reduction {

/// True when the live graph, with the nodes of `step` (if not null) replaced by its new edges
/// (H1 when `h1`, else H2), is loopless and bridgeless with exactly `components` components. O(n).
bool is_connected_bridgeless(const ReductionGraph& graph, std::uint32_t components,
                             const Step* step = nullptr, bool h1 = true);

}  // namespace petersen::reduction
