#pragma once
// The reduction engine: Frink's reductions under the forbidden-edge rule of Biedl, Bose, Demaine
// and Lubiw, iterative, with the reductions on an explicit stack, then O(1) lifts.

#include "petersen/matching/avoiding.hpp"
#include "reduction/chooser.hpp"

namespace petersen::reduction {

/// Reduces every component of `g` to a theta graph, matches it, and lifts the matching back
/// through every reduction. `g` must have room for one new edge per node. `component` and
/// `components` are g's component ids and count; `forbidden` (or kNoEdge) is never matched. The
/// chooser must be built on g's graph (same ids). Fills the counts and the reduce/lift times of
/// `stats`.
Matching reduce_and_lift(ReductionGraph g, std::span<const std::uint32_t> component,
                         std::uint32_t components, EdgeId forbidden, Chooser& chooser,
                         bool check_each_step, ReductionStats& stats);

}  // namespace petersen::reduction
