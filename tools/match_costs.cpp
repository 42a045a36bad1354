#include "match_costs.hpp"

#include <algorithm>
#include <cinttypes>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace petersen::cli {

std::string SolverCosts::text(std::int64_t total, const std::vector<std::uint32_t>& mate_edge,
                              const GraphFile& graph) const {
  const std::int64_t shown = negated ? -total : total;
  if (rounded) {
    long double sum = 0;
    for (NodeId v = 0; v < mate_edge.size(); ++v) {
      const std::uint32_t e = mate_edge[v];
      if (e != kNoEdge && graph.edges[e][0] == v) sum += reals[e];
    }
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.17g", static_cast<double>(negated ? -sum : sum));
    return buffer;
  }
  std::string digits = std::to_string(shown < 0 ? -static_cast<std::uint64_t>(shown)
                                                : static_cast<std::uint64_t>(shown));
  if (decimals > 0) {
    if (digits.size() <= decimals) digits.insert(0, decimals + 1 - digits.size(), '0');
  }
  // Built by appends: GCC 12 gives a false -Wrestrict on string inserts and chains of +.
  std::string out(shown < 0 ? "-" : "");
  out.append(digits, 0, digits.size() - decimals);
  if (decimals > 0) {
    out.push_back('.');
    out.append(digits, digits.size() - decimals, decimals);
  }
  return out;
}

double SolverCosts::gap_bound(std::uint64_t matching_edges) const {
  return rounded ? rounded->gap_bound(matching_edges) : 0;
}

SolverCosts solver_costs(const GraphFile& graph, bool negate, std::uint64_t largest_matching) {
  SolverCosts result;
  result.negated = negate;
  constexpr std::int64_t kMaxK = std::int64_t{1} << 52;
  std::int64_t most = 0, least = 0;
  for (std::int64_t c : graph.costs) {
    most = std::max(most, negate ? -c : c);
    least = std::min(least, negate ? -c : c);
  }
  // In 128 bits: up to 2^31 · 2^41.
  __extension__ const __int128 k = 1 + static_cast<__int128>(largest_matching) * (most - least);
  if (graph.real_costs.empty() && k < kMaxK) {
    result.decimals = graph.cost_decimals;
    result.costs.reserve(graph.costs.size());
    for (std::int64_t c : graph.costs) result.costs.push_back(negate ? -c : c);
    return result;
  }
  // Too many digits, too large, or too far apart for exact integers: the doubles, rounded at a
  // power of two within the limit that keeps K below 2^52.
  std::vector<double> reals;
  reals.reserve(graph.edges.size());
  if (graph.real_costs.empty()) {
    for (std::int64_t c : graph.costs)
      reals.push_back(static_cast<double>(c) / std::pow(10.0, graph.cost_decimals));
  } else {
    reals = graph.real_costs;
  }
  double largest = 0;
  for (double& r : reals) {
    if (negate) r = -r;
    largest = std::max(largest, std::abs(r));
  }
  const std::int64_t limit = maximum_matching_cost_limit(largest_matching);
  result.rounded = integer_costs(reals, limit);
  result.reals = reals;
  result.rounded->exact = false;
  result.rounded->rounding += largest * 0x1p-53;  // each double is within half an ulp of the text
  result.costs.assign(result.rounded->costs.begin(), result.rounded->costs.end());
  return result;
}

}  // namespace petersen::cli
