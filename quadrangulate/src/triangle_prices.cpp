#include "petersen/quadrangulate/triangle_prices.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace petersen {

std::pmr::vector<Cost> triangle_prices(std::uint32_t node_count, std::span<const NodeId> edge_ends,
                                       std::span<const Cost> costs, Cost price,
                                       std::pmr::memory_resource* memory) {
  constexpr Cost kNone = std::numeric_limits<Cost>::max();
  const std::size_t m = costs.size();
  std::pmr::vector<Cost> cheapest(node_count, kNone, memory);
  for (std::size_t e = 0; e < m; ++e) {
    for (int k = 0; k < 2; ++k) {
      Cost& c = cheapest[edge_ends[2 * e + k]];
      c = std::min(c, costs[e]);
    }
  }
  // Per node: its regret, the least extra its pairs cost their other ends, and the worst of its
  // neighbours' cheapest pairs (cheapest[] of an end of an edge is finite).
  std::pmr::vector<Cost> regret(node_count, kNone, memory);
  std::pmr::vector<Cost> worst_neighbour(node_count, std::numeric_limits<Cost>::min(), memory);
  for (std::size_t e = 0; e < m; ++e) {
    const NodeId a = edge_ends[2 * e], b = edge_ends[2 * e + 1];
    regret[a] = std::min(regret[a], costs[e] - cheapest[b]);
    regret[b] = std::min(regret[b], costs[e] - cheapest[a]);
    worst_neighbour[a] = std::max(worst_neighbour[a], cheapest[b]);
    worst_neighbour[b] = std::max(worst_neighbour[b], cheapest[a]);
  }
  const double regret_at_least = kOwnTriangleRegretShare * static_cast<double>(price);
  const double neighbours_at_most = kOwnTriangleNeighbourShare * static_cast<double>(price);
  const Cost lowered = std::llround(kOwnTrianglePriceShare * static_cast<double>(price));
  std::pmr::vector<Cost> prices(node_count, price, memory);
  for (NodeId v = 0; v < node_count; ++v) {
    if (regret[v] != kNone && static_cast<double>(regret[v]) >= regret_at_least &&
        static_cast<double>(worst_neighbour[v]) <= neighbours_at_most) {
      prices[v] = lowered;
    }
  }
  return prices;
}

}  // namespace petersen
