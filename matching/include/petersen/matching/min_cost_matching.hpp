#pragma once
// Exact minimum-cost perfect matching with a certificate of optimality, and the
// minimum-cost matching among the maximum ones for graphs without a perfect matching.
//
// The certificate is a dual solution of Edmonds' perfect-matching polytope in its odd-cut form:
// a value per node and per odd set S of 3+ nodes (the blossoms), such that for every edge e
//   sum over the sets S (nodes included) with exactly one end of e in S of y_S  <=  2·cost(e),
// every set value is >= 0, equality holds on matched edges, and every set with a positive value
// holds (|S| - 1)/2 matched edges. Then 2·total = sum of all values proves the matching optimal.
// The values are in half cost units (2·cost), so they are integers: integer costs have a
// half-integral optimal dual. verify_min_cost_matching (petersen/matching/verify_min_cost.hpp)
// checks all of it, sharing no code with the solver.

#include <cstdint>
#include <span>
#include <vector>

#include "petersen/graph/csr_graph.hpp"
#include "petersen/graph/cubic_graph.hpp"
#include "petersen/graph/memory.hpp"
#include "petersen/matching/matching.hpp"

namespace petersen {

using Cost = std::int64_t;

/// The largest |cost| accepted: the solver's duals and sums stay far inside 64 bits.
inline constexpr Cost kMaxCost = Cost{1} << 40;

/// Degrees (or any real cost) to integers: round(cost · scale). The default scale 2^16 keeps
/// the quad measure (0..270°) exact to 1.5e-5°, and the front door and the LEMON peer get the
/// same integers from the same doubles. Throws std::invalid_argument naming the first index
/// whose cost is not finite or whose scaled value exceeds kMaxCost. O(m).
inline constexpr double kDefaultCostScale = 65536.0;
std::pmr::vector<Cost> scale_costs(
    std::span<const double> costs, double scale = kDefaultCostScale,
    std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// Marks "no set" in MatchingCertificate.
inline constexpr std::uint32_t kNoSet = 0xFFFFFFFFu;

/// The dual solution (see the top of this file): node_dual[v] per node, and the odd sets with a
/// positive value as a laminar forest: set s has value set_dual[s] and lies directly inside set
/// set_parent[s] (kNoSet: none); node v lies directly inside set node_set[v] (kNoSet: none), so
/// the members of s are the nodes whose chain of sets passes s. A forest, not member lists:
/// blossoms nest deeply on meshes (on armadillo's dual, 13.7k sets listed 455M members).
struct MatchingCertificate {
  std::vector<std::int64_t> node_dual;
  std::vector<std::uint32_t> node_set;
  std::vector<std::uint32_t> set_parent;
  std::vector<std::int64_t> set_dual;

  std::size_t set_count() const { return set_dual.size(); }
};

struct MinCostOptions {
  /// Potentials start at y_v = the cheapest edge's cost at v. On: each is raised greedily and
  /// tight edges are matched greedily (Blossom V's greedy start), then, without short searches,
  /// the matching is grown to a maximum one of the tight edges (augment_matching; the short
  /// searches find those paths too). Off: nothing is matched at the start.
  bool greedy_start = true;
  /// Before the forest grows: short primal-dual searches of one tree each, from every free
  /// node in turn, with growing label budgets, augmenting where a free node is near (in reduced
  /// cost), closing a half-integral odd cycle where they meet a blossom, or stopping at the
  /// budget (Blossom V's fractional start). The forest then grows from one node of each odd
  /// cycle left: far fewer trees, whose labels cost several times more each.
  bool short_searches = true;
  /// Threads for the short searches, which run in two parts of the graph at once; 0: every
  /// core. Threads are started for the call and joined before it returns. The result does not
  /// depend on it.
  std::uint32_t threads = 1;
  /// Where the matching and the solver's large arrays are allocated.
  std::pmr::memory_resource* memory = std::pmr::get_default_resource();
};

struct MinCostStats {
  double init_seconds = 0;         ///< potentials and the greedy matching of tight edges
  double search_seconds = 0;       ///< the alternating-tree searches (one per augmentation)
  double certificate_seconds = 0;  ///< collecting the odd sets
  std::uint32_t free_after_init = 0;
  std::uint64_t searches = 0;         ///< alternating trees grown, one augmentation each
  std::uint64_t nodes_labelled = 0;   ///< even/odd labels given to top-level blossoms
  std::uint64_t dual_updates = 0;     ///< times a tree's potentials moved
  std::uint64_t blossoms_shrunk = 0;  ///< odd cycles shrunk
  std::uint64_t blossoms_expanded = 0;
  std::uint64_t queue_pushes = 0;    ///< entries of the slack-keyed priority queue
  std::uint64_t even_scans = 0;      ///< nodes scanned on becoming even
  std::uint64_t released_scans = 0;  ///< nodes scanned on leaving an expanded odd blossom
  std::uint64_t short_labels = 0;    ///< labels given by the short single-tree searches
  std::uint64_t short_augmentations = 0;
  std::uint64_t short_half_cycles = 0;  ///< half-integral odd cycles the short searches closed
};

struct MinCostResult {
  Matching matching;
  Cost total_cost = 0;  ///< sum of the matched edges' costs
  MatchingCertificate certificate = {};
  MinCostStats stats = {};
};

/// A minimum-cost perfect matching of `graph` under `costs` (one per edge id, |cost| <=
/// kMaxCost), with its certificate. Edmonds' primal-dual blossom algorithm: from the greedy
/// start and short single-tree searches (which leave 0.02-0.8 % of the nodes free on the shared
/// meshes' duals), the alternating trees of all free nodes grow at once under one lazy dual clock;
/// the next event (an edge turning tight, an odd blossom's dual reaching zero) comes from a radix
/// priority queue keyed by slack; two trees meeting augment and are released. It runs on a
/// breadth-first renumbering of the graph (meshes' own orders scatter neighbours; the answer is
/// in the input's ids). In the worst case O(n) augmentations, each after O(n) shrinks and
/// expansions that rescan up to m edges: O(n² m); in practice the work follows the regions the
/// trees cover (armadillo's dual, 86k nodes: 0.04 s of CPU time).
/// Iterative throughout. Throws GraphError when the graph has no perfect matching,
/// std::invalid_argument when costs has the wrong size or a cost out of range, and
/// std::overflow_error when the total cost passes 2^63 (possible from 2^24 nodes on, with
/// costs near kMaxCost).
MinCostResult min_cost_perfect_matching(const CubicGraph& graph, std::span<const Cost> costs,
                                        const MinCostOptions& options = {});
MinCostResult min_cost_perfect_matching(const CsrGraph& graph, std::span<const Cost> costs,
                                        const MinCostOptions& options = {});

/// The result of min_cost_matching. The certificate is of the doubled graph described there,
/// whose nodes are v and n + v and whose edges are e, m + e and 2m + v.
struct MinCostMatchingResult {
  Matching matching;                ///< of the input graph; any size
  std::uint32_t size = 0;           ///< matched edges
  Cost matched_cost = 0;            ///< sum of the matched edges' costs
  Cost total = 0;                   ///< matched_cost + the prices of the unmatched nodes
  MatchingCertificate certificate;  ///< of the doubled graph's perfect matching
  MinCostStats stats = {};
};

/// A matching of `graph` of any size minimizing cost(M) + Σ price(v) over the nodes v that M
/// leaves unmatched, with its certificate. `unmatched_cost` holds one price per node, or a
/// single price for every node (|price| <= kMaxCost, any sign); costs one per edge id (|cost| <=
/// kMaxCost). Price 0 and costs = −weight give a maximum-weight matching of any size; a price
/// above every matching's cost difference gives min_cost_maximum_matching.
/// By reduction: the doubled graph H has G, a copy G' (node n + v, edge m + e, same costs) and
/// an edge v–v' (edge 2m + v) of cost 2·price(v). A perfect matching of H is M1 ∪ M2' plus v–v'
/// for the nodes F both leave free, costing cost(M1) + cost(M2) + 2·Σ_F price; M ∪ M' for any M
/// costs twice M's objective, so H's optimum is twice G's and each copy of an optimal H is
/// optimal: the first is returned. The certificate proves the perfect matching M ∪ M' ∪ {v–v'}
/// of H optimal with total 2·total; verify_min_cost_matching rebuilds H and checks it.
/// Twice the work of min_cost_perfect_matching on a graph of n nodes: worst case O(n² m), in
/// practice near the trees' regions (see min_cost_perfect_matching). Throws
/// std::invalid_argument when costs or unmatched_cost has the wrong size or a value out of range
/// (or the doubled graph would pass 32-bit ids), std::overflow_error when a total passes 2^63.
MinCostMatchingResult min_cost_matching(const CsrGraph& graph, std::span<const Cost> costs,
                                        std::span<const Cost> unmatched_cost,
                                        const MinCostOptions& options = {});

/// The result of min_cost_maximum_matching. The certificate is of the doubled graph described
/// there, whose nodes are v and n + v and whose edges are e, m + e and 2m + v.
struct MinCostMaximumResult {
  Matching matching;                ///< of the input graph
  std::uint32_t size = 0;           ///< matched edges: the maximum
  Cost total_cost = 0;              ///< the minimum among matchings of that size
  Cost unmatched_cost = 0;          ///< K, the cost of an edge v–v' of the doubled graph
  MatchingCertificate certificate;  ///< of the doubled graph's perfect matching
  MinCostStats stats = {};
};

/// A minimum-cost matching among the maximum-cardinality matchings of `graph`, by reduction:
/// the doubled graph H has G, a copy G' (node n + v, edge m + e, same costs) and an edge v–v' of
/// cost K = 1 + ν̄·(max(0, max cost) − min(0, min cost)) per node, where ν̄ = min(half the nodes
/// with an edge, the edges) bounds a matching's size. A perfect matching of H is M ∪ M' plus
/// v–v' for the u nodes M leaves free, costing 2·cost(M) + K·u; K exceeds the cost difference
/// of any two matchings of G, so the cheapest perfect matching of H leaves the fewest nodes
/// free, and among those costs the least: min_cost_matching's reduction with K for 2·price.
/// The certificate proves that perfect matching of H optimal; verify_min_cost_maximum_matching
/// rebuilds H and checks it. Throws std::invalid_argument when costs has the wrong size, a cost is
/// out of range or K would pass 2^52, and std::overflow_error when the total cost passes 2^63.
/// Twice the work of min_cost_perfect_matching on a graph of n nodes.
MinCostMaximumResult min_cost_maximum_matching(const CsrGraph& graph, std::span<const Cost> costs,
                                               const MinCostOptions& options = {});

/// The result of cheapest_maximum_matching.
struct CheapestMaximumResult {
  Matching matching;
  std::uint32_t size = 0;  ///< matched edges: the maximum
  bool perfect = false;    ///< every node matched
  Cost total_cost = 0;     ///< the least among matchings of that size
  MinCostStats stats = {};
};

/// The cheapest maximum matching of any graph, for callers that do not know whether it has a
/// perfect one: a cubic bridgeless graph has one (Petersen's theorem); otherwise a maximum
/// matching (maximum_matching, its Tutte–Berge witness checked) tells. Then
/// min_cost_perfect_matching runs when there is a perfect one and min_cost_maximum_matching
/// (twice the work) when not. The answer's certificate is checked by
/// verify_min_cost_perfect_matching or verify_min_cost_maximum_matching, and its size against
/// the maximum's, before it returns (std::logic_error if not: a bug). Throws
/// std::invalid_argument and std::overflow_error as those two do.
CheapestMaximumResult cheapest_maximum_matching(const CsrGraph& graph, std::span<const Cost> costs,
                                                const MinCostOptions& options = {});

}  // namespace petersen
