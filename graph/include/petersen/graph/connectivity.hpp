#pragma once
// Connectivity and bridges of a cubic multigraph, found iteratively in linear time.

#include <optional>

#include "petersen/graph/cubic_graph.hpp"

namespace petersen {

/// Number of connected components. O(n).
std::uint32_t count_components(const CubicGraph& graph);

/// Component id (0-based, in order of smallest node) of every node. O(n).
std::vector<std::uint32_t> component_ids(const CubicGraph& graph);

/// Some bridge of the graph, if it has one. Parallel edges are never bridges. O(n), iterative
/// (explicit stack), so graphs of 10^8 nodes do not overflow the call stack.
std::optional<EdgeId> find_bridge(const CubicGraph& graph);

/// Throws GraphError naming a bridge (edge and endpoints) if the graph has one. O(n).
void validate_bridgeless(const CubicGraph& graph);

/// Throws GraphError if the graph is disconnected (naming the component count) or has a bridge
/// (naming the edge and its endpoints): Petersen's theorem needs both. O(n).
void validate_connected_bridgeless(const CubicGraph& graph);

}  // namespace petersen
