#include "petersen/matching/avoiding.hpp"

#include <string>

#include "petersen/graph/connectivity.hpp"
#include "reduction/match_by_reductions.hpp"

namespace petersen {

ReductionResult perfect_matching_avoiding(const CubicGraph& graph, EdgeId forbidden,
                                          const ReductionOptions& options) {
  if (forbidden != kNoEdge && forbidden >= graph.edge_count())
    throw GraphError("perfect_matching_avoiding: forbidden edge " + std::to_string(forbidden) +
                     " is out of range (the graph has " + std::to_string(graph.edge_count()) +
                     " edges)");
  validate_bridgeless(graph);
  return reduction::match_by_reductions(graph, forbidden, options);
}

}  // namespace petersen
