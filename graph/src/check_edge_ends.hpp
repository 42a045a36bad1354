#pragma once
// The one check every graph constructor makes of an edge before using its ends as indices, so
// the three constructors name a bad edge in the same words.

#include <cstddef>
#include <string>

#include "petersen/graph/cubic_graph.hpp"

namespace petersen::graph_detail {

/// Throws GraphError naming edge e if an end is not below node_count or the edge is a loop.
inline void check_edge_ends(EdgeId e, NodeId a, NodeId b, std::size_t node_count) {
  if (a >= node_count || b >= node_count) {
    throw GraphError("edge " + std::to_string(e) + " has an endpoint out of range (" +
                     std::to_string(a) + ", " + std::to_string(b) + "; " +
                     std::to_string(node_count) + " nodes)");
  }
  if (a == b)
    throw GraphError("edge " + std::to_string(e) + " is a loop at node " + std::to_string(a));
}

}  // namespace petersen::graph_detail
