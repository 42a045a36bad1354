#pragma once
// The shared entry of perfect_matching (ds, gw, frink) and perfect_matching_avoiding.

#include "petersen/matching/avoiding.hpp"

namespace petersen::reduction {

/// perfect_matching_avoiding without the validation at the door: `graph` must be bridgeless.
ReductionResult match_by_reductions(const CubicGraph& graph, EdgeId forbidden,
                                    const ReductionOptions& options);

}  // namespace petersen::reduction
