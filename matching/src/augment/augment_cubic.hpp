#pragma once
// Tarjan's augmentation of a cubic graph's matching over a NeighbourTable the caller already
// built (PS builds one for its own pass, paper §3.1), so the table is paid for once.

#include "neighbour_table.hpp"
#include "petersen/matching/augment.hpp"

namespace petersen {

/// augment_matching(graph, ...) on the table's graph. The table's search state must be fresh for
/// `matching`: the table built with it, or written by puli_segal.
AugmentStats augment_matching(const NeighbourTable& graph, Matching& matching,
                              Augment variant = Augment::local);

/// The same over a table on neighbour rows, whose search state is the matching: fresh for it on
/// entry (written by puli_segal_on_rows), each slot's mate updated by every augmenting path.
AugmentStats augment_on_rows(const NeighbourTable& table, Augment variant = Augment::local);

}  // namespace petersen
