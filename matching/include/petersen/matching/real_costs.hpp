#pragma once
// Real costs as the integers the exact matching solvers take: exactly when a power of two makes
// every cost an integer within the solver's range, otherwise rounded with the rounding stated, so
// that an optimum certified on the integers carries a bound on its distance from the real one.

#include <cstdint>
#include <span>

#include "petersen/graph/memory.hpp"
#include "petersen/matching/min_cost_matching.hpp"

namespace petersen {

/// Integer costs for real ones: costs[e] = round(real[e] · 2^exponent).
struct IntegerCosts {
  std::pmr::vector<Cost> costs;
  int exponent = 0;   ///< of the scale 2^exponent (negative for costs past the limit)
  bool exact = true;  ///< every real[e] · 2^exponent was an integer: nothing rounded
  double rounding = 0;  ///< the largest |costs[e] · 2^−exponent − real[e]|, at most 2^−exponent / 2

  /// How much more than the real optimum a matching optimal on `costs` may cost in real terms:
  /// it and a real optimum, each of at most `matching_edges` edges, err by at most `rounding`
  /// per edge. 0 when exact.
  double gap_bound(std::uint64_t matching_edges) const {
    return 2 * static_cast<double>(matching_edges) * rounding;
  }
};

/// The smallest power of two that makes every cost an integer, when the largest |cost| times it
/// stays within `limit` (exact: binary doubles such as 2.5 or 3.0, or any integers within the
/// limit); otherwise the largest power of two that keeps the largest |cost| within `limit`, and
/// every cost rounded to the nearest integer (ties away from zero). `limit` is at most kMaxCost;
/// a caller whose solver needs headroom (min_cost_maximum_matching's K) passes less. Throws
/// std::invalid_argument naming the first cost that is not finite, or for a limit below 1. O(m).
IntegerCosts integer_costs(std::span<const double> costs, Cost limit = kMaxCost);

/// The largest |cost| integer_costs may give for min_cost_maximum_matching on a graph whose
/// matchings have at most `largest_matching` edges: its unmatched cost K = 1 + largest_matching ·
/// (cost range) must stay below 2^52, whatever the costs' signs. kMaxCost for 0 or 1 edges,
/// then less. O(1).
Cost maximum_matching_cost_limit(std::uint64_t largest_matching);

}  // namespace petersen
