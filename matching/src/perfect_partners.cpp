#include "petersen/matching/perfect_partners.hpp"

#include "augment/augment_cubic.hpp"
#include "greedy/greedy.hpp"
#include "stopwatch.hpp"

namespace petersen {

PartnerResult perfect_partners(std::span<const NodeId> rows, const PartnerOptions& options) {
  PartnerResult result;
  NeighbourTable table(rows);
  Stopwatch initial;
  result.stats.unpaired_after_initial = puli_segal_on_rows(table, options.seed);
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

}  // namespace petersen
