#pragma once
// A matching of a cubic graph, and the verifier every algorithm's answer goes through.

#include <span>
#include <string>

#include "petersen/graph/csr_graph.hpp"
#include "petersen/graph/cubic_graph.hpp"

namespace petersen {

/// The matched edge of each node, or kNoEdge. Both ends of a matched edge name it.
struct Matching {
  std::pmr::vector<EdgeId> mate_edge;

  Matching() = default;
  /// Every node free, the array allocated from `memory`.
  explicit Matching(std::uint32_t node_count,
                    std::pmr::memory_resource* memory = std::pmr::get_default_resource())
      : mate_edge(node_count, kNoEdge, memory) {}

  bool is_matched(NodeId v) const { return mate_edge[v] != kNoEdge; }
  /// Matches edge e = {a, b}; both ends must be free.
  void match(const CubicGraph& graph, EdgeId e) {
    auto [a, b] = graph.endpoints(e);
    mate_edge[a] = mate_edge[b] = e;
  }
  std::uint32_t unmatched_count() const;
};

/// What the verifier found; `ok` is true exactly when the matching is perfect and consistent.
struct MatchingCheck {
  enum class Problem {
    none,
    wrong_size,
    edge_out_of_range,
    not_incident,
    inconsistent,
    unmatched,
    bad_witness,  ///< a Tutte set names a node out of range or twice
    not_maximum,  ///< the Tutte set does not prove the matching maximum
  };
  Problem problem = Problem::none;
  NodeId node = kNoNode;
  EdgeId edge = kNoEdge;
  std::string message;
  bool ok() const { return problem == Problem::none; }
};

/// Checks that `matching` is a perfect matching of `graph`: every node names an incident edge in
/// range whose other end names the same edge. Reports the first problem with its node and edge.
/// O(n).
MatchingCheck verify_perfect_matching(const CubicGraph& graph, const Matching& matching);

/// Like verify_perfect_matching but unmatched nodes are allowed (a valid, possibly partial,
/// matching). O(n).
MatchingCheck verify_matching(const CubicGraph& graph, const Matching& matching);
/// The same check on a general graph. O(n).
MatchingCheck verify_matching(const CsrGraph& graph, const Matching& matching);

/// Checks that `partner` (a node per node, perfect_partners) is a perfect matching of the cubic
/// graph whose neighbour rows are `rows` (rows[3v..3v+2]: v's neighbours): every node's partner
/// is in range, is one of its neighbours, and has it as its own partner. Reports the first
/// problem with its node (`edge` names the partner). O(n).
MatchingCheck verify_perfect_partners(std::span<const NodeId> rows,
                                      std::span<const NodeId> partner);

}  // namespace petersen
