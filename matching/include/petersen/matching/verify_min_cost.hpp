#pragma once
// The independent check of a minimum-cost matching's certificate (min_cost_matching.hpp): it
// shares no code with the solver and proves optimality by weak duality, in exact arithmetic.

#include <cstdint>
#include <memory_resource>
#include <span>
#include <string>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/matching/matching.hpp"
#include "petersen/matching/min_cost_matching.hpp"

namespace petersen {

/// What the certificate check found: ok() or the first problem, with the node, edge or set.
struct CertificateCheck {
  std::string problem;
  bool ok() const { return problem.empty(); }
};

// Each check's scratch (its doubled graph is as large as the solver's) comes from `memory`.

/// Checks that `matching` is a perfect matching of the graph given by its edge ends (edge e
/// joins edge_ends[2e] and edge_ends[2e+1]; CubicGraph::edge_ends and CsrGraph::edge_ends), that
/// its cost is `total_cost`, and that `certificate` proves it minimum: the set forest has no
/// cycle, every set is odd, of 3+ nodes, unequal to its subsets, with a value >= 0; every edge's
/// reduced cost 2·cost(e) − (sum of the values of the sets with exactly one end of e) is >= 0
/// and 0 on matched edges; every set with a positive value holds (|S| − 1)/2 matched edges; and
/// the values sum to 2·total_cost. In 128-bit integers. O(n + m·d + s log s) for s sets nested
/// at most d deep.
CertificateCheck verify_min_cost_perfect_matching(
    std::uint32_t node_count, std::span<const NodeId> edge_ends, std::span<const Cost> costs,
    const Matching& matching, Cost total_cost, const MatchingCertificate& certificate,
    std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// Checks a min_cost_matching result: rebuilds the doubled graph H (see min_cost_matching.hpp)
/// with v–v' at 2·price(v) (`unmatched_cost`: one price per node, or one for all) and its
/// perfect matching M ∪ M' ∪ {v–v' : v free in M} from `matching`, checks that `total` is the
/// matched costs plus the prices of the free nodes, and checks the certificate on H with total
/// 2·total. Then no matching of any size has a smaller cost plus prices. In 128-bit integers.
CertificateCheck verify_min_cost_matching(
    std::uint32_t node_count, std::span<const NodeId> edge_ends, std::span<const Cost> costs,
    std::span<const Cost> unmatched_cost, const Matching& matching, Cost total,
    const MatchingCertificate& certificate,
    std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// Checks a min_cost_maximum_matching result: rebuilds the doubled graph H and its perfect
/// matching M ∪ M' ∪ {v–v' : v free in M} from `matching` (see min_cost_matching.hpp), checks
/// that `unmatched_cost` is at least 1 + ν̄·(max(0, max cost) − min(0, min cost)), ν̄ the
/// lesser of half the nodes an edge (not a loop) touches and the number of such edges, and checks
/// the certificate on H with total 2·total_cost + K·(free nodes). Then `matching` is of maximum
/// size and, among those, of minimum cost.
CertificateCheck verify_min_cost_maximum_matching(
    std::uint32_t node_count, std::span<const NodeId> edge_ends, std::span<const Cost> costs,
    const Matching& matching, Cost total_cost, Cost unmatched_cost,
    const MatchingCertificate& certificate,
    std::pmr::memory_resource* memory = std::pmr::get_default_resource());

}  // namespace petersen
