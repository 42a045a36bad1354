#pragma once
// A perfect matching as partner nodes, computed on neighbour rows alone: the lean form of
// perfect_matching for a caller that needs only who is paired with whom (quadrangulate).

#include <span>

#include "petersen/graph/cubic_graph.hpp"
#include "petersen/matching/augment.hpp"
#include "petersen/matching/options.hpp"

namespace petersen {

struct PartnerOptions {
  /// Algorithm::automatic or Algorithm::ps (what perfect_matching runs for them); any other
  /// throws std::invalid_argument.
  Algorithm algorithm = Algorithm::automatic;
  Augment augment = Augment::local;
  std::uint64_t seed = 1;
  /// Where the partners and the search state are allocated.
  std::pmr::memory_resource* memory = std::pmr::get_default_resource();
};

struct PartnerResult {
  /// partner[v]: the node matched to v; kNoNode for a node left free (only when the graph is not
  /// bridgeless: Petersen's theorem matches every node of a cubic bridgeless graph).
  std::pmr::vector<NodeId> partner;
  PerfectMatchingStats stats = {};
};

/// PS and Tarjan's augmenting paths (Algorithm::automatic or ps of perfect_matching, the same
/// pairs for the same seed) on a cubic multigraph given by its neighbour rows, `rows[3v..3v+2]`
/// being v's neighbours (CubicGraph::into_neighbour_rows); the rows are read, never copied. It
/// holds the rows (12 bytes per node, the caller's) and the search state (16) where
/// perfect_matching holds the graph (24), its table (28) and the mate edges (4): what lets
/// quadrangulate stay within 64 bytes per triangle. The rows are trusted to be a loop-free cubic
/// graph (each node in the row of each neighbour as often as that neighbour is in its own); no
/// bridge test is made. Check the answer with verify_perfect_partners. Θ(n) for PS; the
/// augmentation's cost follows the regions its searches explore. As in perfect_matching,
/// Algorithm::automatic pairs by the ordered sweep in PS's place where the numbering is local
/// (stats.ordered_sweep), and where it leaves nodes a bipartite graph is matched by Schrijver's
/// algorithm instead (Θ(n), stats.schrijver; its walk's path takes 8 bytes per node on it, about
/// 10^4 nodes on the 4M-node plates).
PartnerResult perfect_partners(std::span<const NodeId> rows, const PartnerOptions& options = {});

/// Tarjan's augmenting paths (augment_matching's, the same searches) from a pairing the caller
/// already has, on neighbour rows: grows `partner` (partner[v] one of v's neighbours that names v
/// back, or kNoNode) to a maximum matching, perfect on a cubic bridgeless graph. Holds the search
/// state only (16 bytes per node) beside the caller's rows and partners, where augment_matching
/// holds a CubicGraph (24), its table (28) and mate edges (4): what lets quadrangulate's lrs
/// augment K's pairing within its budget. Throws std::invalid_argument naming the node when a
/// partner is not a neighbour or does not name it back. Check the answer with
/// verify_perfect_partners.
AugmentStats augment_partners(std::span<const NodeId> rows, std::span<NodeId> partner,
                              Augment variant = Augment::local);

}  // namespace petersen
