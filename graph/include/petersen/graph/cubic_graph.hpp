#pragma once
// A cubic multigraph in flat arrays: the foundation every matching algorithm works on.

#include <array>
#include <cstdint>
#include <functional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "petersen/graph/memory.hpp"

namespace petersen {

using NodeId = std::uint32_t;
using EdgeId = std::uint32_t;
inline constexpr NodeId kNoNode = 0xFFFFFFFFu;
inline constexpr EdgeId kNoEdge = 0xFFFFFFFFu;

/// Raised when a graph is not what an algorithm needs; the message names the node or edge.
struct GraphError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// A cubic multigraph: nodes 0..n-1, edges 0..3n/2-1, parallel edges allowed, no loops.
/// Endpoints of edge e are at edge_ends[2e], edge_ends[2e+1]; the three edges of node v are at
/// node_edges[3v..3v+2], in the order the edge list named them. Construction is O(n). Both arrays
/// are on the resource of the arrays given to from_incidence (memory.hpp), the default one from
/// from_edges.
class CubicGraph {
 public:
  CubicGraph() = default;

  /// Builds the graph from an edge list; throws GraphError naming the first node whose degree is
  /// not 3, the first loop, or the first endpoint out of range. Does not test connectivity or
  /// bridges (see validate_connected_bridgeless).
  static CubicGraph from_edges(std::uint32_t node_count,
                               std::span<const std::array<NodeId, 2>> edges);

  /// Builds the graph from both arrays at once, so the caller chooses the order of each node's
  /// three edges (the dual of a mesh lists triangle t's edges in the order of its corners). The
  /// arrays are taken over, not copied. Throws GraphError naming the first node slot or edge that
  /// disagrees: an edge out of range, a loop, an edge listed at a node that is not its endpoint,
  /// or an edge not listed exactly once at each end. O(n).
  static CubicGraph from_incidence(std::pmr::vector<EdgeId> node_edges,
                                   std::pmr::vector<NodeId> edge_ends);

  /// from_incidence without its checks, for arrays that form a cubic graph by construction (the
  /// dual of a triangulation's halfedge structure, lrs::Triangulation::dual_graph): the checks
  /// read edge_ends at every slot's edge, a random access that costs as much as building the
  /// arrays. The caller's tests check such arrays with from_incidence. O(1).
  static CubicGraph from_valid_incidence(std::pmr::vector<EdgeId> node_edges,
                                         std::pmr::vector<NodeId> edge_ends) {
    return CubicGraph(std::move(node_edges), std::move(edge_ends));
  }

  std::uint32_t node_count() const { return static_cast<std::uint32_t>(node_edges_.size() / 3); }
  std::uint32_t edge_count() const { return static_cast<std::uint32_t>(edge_ends_.size() / 2); }

  std::array<NodeId, 2> endpoints(EdgeId e) const {
    return {edge_ends_[2 * e], edge_ends_[2 * e + 1]};
  }
  /// The endpoint of e that is not v (v must be an endpoint of e).
  NodeId other_end(EdgeId e, NodeId v) const {
    return edge_ends_[2 * e] ^ edge_ends_[2 * e + 1] ^ v;
  }
  /// The three edges at v; a parallel edge appears once per copy.
  std::span<const EdgeId, 3> incident_edges(NodeId v) const {
    return std::span<const EdgeId, 3>(node_edges_.data() + 3 * std::size_t{v}, 3);
  }
  EdgeId incident_edge(NodeId v, int k) const { return node_edges_[3 * std::size_t{v} + k]; }
  /// The position k of e among v's three edges (e must be one of them).
  int edge_index(NodeId v, EdgeId e) const {
    const std::span<const EdgeId, 3> edges = incident_edges(v);
    return edges[0] == e ? 0 : edges[1] == e ? 1 : 2;
  }

  std::span<const NodeId> edge_ends() const { return edge_ends_; }
  std::span<const EdgeId> node_edges() const { return node_edges_; }

  /// Takes the graph apart into its neighbour rows: v's neighbours at [3v..3v+2], the k-th across
  /// its k-th incident edge (a parallel edge once per copy). They are written over the incidence
  /// lists in place and the edge list is freed, so a caller that needs only who is adjacent to
  /// whom (perfect_partners) holds 12 bytes per node instead of 24, and never both. O(n).
  std::pmr::vector<NodeId> into_neighbour_rows() &&;
  /// The same, with beside(edge_ends()) run on a second thread (given threads > 1; 0 means every
  /// core) while the rows are written, and before the edge list is freed: work that reads the
  /// edges, done on a core the rows leave idle. Its exception is rethrown here.
  std::pmr::vector<NodeId> into_neighbour_rows(
      std::uint32_t threads, const std::function<void(std::span<const NodeId>)>& beside) &&;
  /// The same rows written to `rows` (3 · node_count() entries), the graph kept. O(n).
  void write_neighbour_rows(NodeId* rows) const;

 private:
  // Moved in, so that they stay on the caller's resource (assigned, they would be copied to the
  // default one).
  CubicGraph(std::pmr::vector<EdgeId> node_edges, std::pmr::vector<NodeId> edge_ends)
      : edge_ends_(std::move(edge_ends)), node_edges_(std::move(node_edges)) {}

  std::pmr::vector<NodeId> edge_ends_;
  std::pmr::vector<EdgeId> node_edges_;
};

}  // namespace petersen
