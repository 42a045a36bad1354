#pragma once
// The fewest edges whose ends give every node of T an odd degree and every other node an even one
// (a minimum T-join), by Edmonds and Johnson's reduction to a minimum-cost perfect matching,
// solved by the project's own solver and proved minimal by its dual certificate.

#include <array>
#include <cstdint>
#include <vector>

#include "petersen/graph/cubic_graph.hpp"

namespace petersen::quad_detail {

/// A multigraph (parallel edges allowed, no loops) with the nodes of T marked; every edge costs 1.
struct TJoinGraph {
  std::uint32_t node_count = 0;
  std::vector<std::uint8_t> odd;             ///< per node: 1 when it is in T
  std::vector<std::array<NodeId, 2>> edges;  ///< each edge's two ends
};

struct TJoinResult {
  std::vector<EdgeId> join;        ///< the edges of a minimum T-join, ascending
  std::uint64_t gadget_nodes = 0;  ///< nodes of the matching the reduction builds
  std::uint64_t gadget_edges = 0;
  bool certified = false;  ///< the matching's certificate passed the independent check
};

/// A minimum T-join of `graph`. The reduction: every edge {u, v} becomes two port nodes joined
/// by an edge of cost 1 (matched: the edge is in the join); the ports of each node are joined
/// by edges of cost 0, plus one dummy port when the port count minus [node ∈ T] is odd, so that
/// a perfect matching leaves an odd number of a node's ports to their cost-1 edges exactly at
/// T. A node of more than four ports is first drawn out into a path of nodes of three ports
/// joined by edges of cost 0 (only the first in T), so no clique is larger than K4 plus a dummy:
/// O(E) gadget nodes and edges. min_cost_perfect_matching solves it and
/// verify_min_cost_perfect_matching checks its certificate, which proves |join| minimal.
/// Throws std::invalid_argument when a connected component holds an odd number of T nodes (no
/// T-join exists), std::logic_error when the certificate fails (a bug). The matching's cost:
/// O(n² m) in the worst case; on the shared meshes' threshold runs (a quarter of the faces in T)
/// it is most of --all-quad's time. `threads`: the matching's short searches (0: every core).
TJoinResult minimum_t_join(const TJoinGraph& graph, std::uint32_t threads = 1);

}  // namespace petersen::quad_detail
