#include "petersen/matching/perfect_partners.hpp"

#include <stdexcept>
#include <string>

#include "augment/augment_cubic.hpp"
#include "greedy/greedy.hpp"
#include "petersen/graph/stopwatch.hpp"

namespace petersen {

PartnerResult perfect_partners(std::span<const NodeId> rows, const PartnerOptions& options) {
  if (options.algorithm != Algorithm::automatic && options.algorithm != Algorithm::ps) {
    throw std::invalid_argument("perfect_partners: runs auto or ps, not " +
                                std::string(to_string(options.algorithm)));
  }
  PartnerResult result{.partner = std::pmr::vector<NodeId>(options.memory)};
  NeighbourTable table(rows, options.memory);
  Stopwatch initial;
  // In PS's place as in perfect_matching (pair_in_ps_place says what and why).
  const PsPlace made =
      pair_in_ps_place(table, nullptr, ps_place_options(options.algorithm, options.seed));
  result.stats.schrijver = made.schrijver;
  result.stats.ordered_sweep = made.ordered_sweep;
  result.stats.unpaired_after_initial = made.unpaired;
  result.stats.initial_seconds = initial.seconds();
  Stopwatch augment;
  const AugmentStats augmented = augment_on_rows(table, options.augment);
  // The partners out of the search state, which is then freed with the table.
  const NodeId n = table.node_count();
  result.partner.resize(n);
  for (NodeId v = 0; v < n; ++v) result.partner[v] = table.slot(v).mate;
  result.stats.augment_seconds = augment.seconds();
  result.stats.augmenting_paths = augmented.augmenting_paths;
  result.stats.blossoms = augmented.blossoms;
  result.stats.nodes_labelled = augmented.nodes_labelled;
  return result;
}

AugmentStats augment_partners(std::span<const NodeId> rows, std::span<NodeId> partner,
                              Augment variant) {
  NeighbourTable table(rows);
  const NodeId n = table.node_count();
  if (partner.size() != n) {
    throw std::invalid_argument("augment_partners: " + std::to_string(partner.size()) +
                                " partners for " + std::to_string(n) + " nodes");
  }
  for (NodeId v = 0; v < n; ++v) {
    const NodeId p = partner[v];
    int i = -1;
    if (p != kNoNode) {
      const auto row = table.neighbours(v);
      i = row[0] == p ? 0 : row[1] == p ? 1 : row[2] == p ? 2 : -1;
      if (i < 0 || p >= n || partner[p] != v) {
        throw std::invalid_argument("augment_partners: node " + std::to_string(v) + "'s partner " +
                                    std::to_string(p) + " is not a neighbour that names it back");
      }
    }
    table.start_search(v, i);
  }
  const AugmentStats stats = augment_on_rows(table, variant);
  for (NodeId v = 0; v < n; ++v) partner[v] = table.slot(v).mate;
  return stats;
}

}  // namespace petersen
