#include "greedy.hpp"

namespace petersen {

PsPlace pair_in_ps_place(NeighbourTable& table, std::pmr::vector<EdgeId>* mate_edge,
                         const PsPlaceOptions& options) {
  const std::optional<std::uint32_t> swept =
      options.ordered_sweep ? ordered_sweep(table, mate_edge, options.sweep_repair_budget)
                            : std::nullopt;
  if (swept == 0u) return {.ordered_sweep = true};
  if (options.bipartite_exact && schrijver(table, mate_edge, swept.has_value())) {
    return {.schrijver = true};
  }
  if (swept) return {.ordered_sweep = true, .unpaired = *swept};
  return {.unpaired = puli_segal(table, mate_edge, options.seed)};
}

}  // namespace petersen
