#pragma once
// The certificate of a maximum matching: a Tutte–Berge witness, checked on its own.

#include <span>

#include "petersen/graph/csr_graph.hpp"
#include "petersen/matching/matching.hpp"

namespace petersen {

/// Checks that `matching` is a maximum matching of `graph`, with `tutte_set` as the proof. By the
/// Tutte–Berge formula every matching leaves at least odd(G − A) − |A| nodes free, where A is any
/// node set and odd(G − A) counts the components of G − A with an odd number of nodes; a valid
/// matching that leaves exactly that many free for A = tutte_set is therefore maximum. The check
/// knows nothing of how the matching or the set were found (the Gallai–Edmonds set of an
/// Edmonds search is one such A). Problems: those of verify_matching, bad_witness (a node out of
/// range or named twice), not_maximum (the counts differ; the message gives both). O(n + m).
MatchingCheck verify_maximum_matching(const CsrGraph& graph, const Matching& matching,
                                      std::span<const NodeId> tutte_set);

}  // namespace petersen
