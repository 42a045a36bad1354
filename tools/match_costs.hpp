#pragma once
// The costs of `petersen match` as the exact solvers take them, and their totals as the file's
// numbers: exact for integers and decimals that a power of ten makes integers within 2^40,
// rounded at a power of two (the tolerance stated) for any others.

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "petersen/io/read_graph.hpp"
#include "petersen/matching/real_costs.hpp"

namespace petersen::cli {

/// The solver's integer costs for a graph file's costs; weights (`negate`) are costs negated.
struct SolverCosts {
  std::vector<std::int64_t> costs;
  std::uint32_t decimals = 0;           ///< exact: costs are the file's numbers · 10^decimals
  std::optional<IntegerCosts> rounded;  ///< otherwise: rounded at 2^exponent
  bool negated = false;

  /// The doubles that were rounded (as weights when negated), when rounded.
  std::vector<double> reals;

  /// The total of the matched edges (mate_edge as AnyGraphCheapestMatching has it, `total` the
  /// solver's integer total) as the file's numbers, as weights when negated: exact decimals, or
  /// the sum of the doubles (in long double).
  std::string text(std::int64_t total, const std::vector<std::uint32_t>& mate_edge,
                   const GraphFile& graph) const;
  /// The most a total can be off the real optimum (0 when exact), for a matching of at most
  /// `matching_edges` edges.
  double gap_bound(std::uint64_t matching_edges) const;
};

/// The file's costs (negated for weights), exact when they fit: within kMaxCost and, when
/// `largest_matching` > 0 (the objectives among maximum matchings, whose doubled graph prices a
/// free node above any cost difference, K = 1 + largest_matching · (cost range) < 2^52), that
/// too; otherwise rounded at the power of two that keeps them so, the doubles' own distance from
/// the file's decimals (half an ulp) counted in the tolerance.
SolverCosts solver_costs(const GraphFile& graph, bool negate, std::uint64_t largest_matching);

}  // namespace petersen::cli
