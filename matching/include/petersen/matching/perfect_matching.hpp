#pragma once
// The front door: one free function computing a perfect matching of a cubic bridgeless graph.

#include "petersen/matching/matching.hpp"
#include "petersen/matching/options.hpp"

namespace petersen {

struct PerfectMatchingResult {
  Matching matching;
  PerfectMatchingStats stats;
};

/// A perfect matching of a cubic bridgeless (multi)graph, by the chosen algorithm. Components are
/// matched independently. Throws GraphError if `options.validate` and the graph has a bridge.
PerfectMatchingResult perfect_matching(const CubicGraph& graph,
                                       const PerfectMatchingOptions& options = {});

}  // namespace petersen
