#include "petersen/matching/perfect_matching.hpp"

#include <optional>

#include "augment/augment_cubic.hpp"
#include "greedy/greedy.hpp"
#include "petersen/graph/connectivity.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "reduction/match_by_reductions.hpp"

namespace petersen {

namespace {

constexpr std::pair<Algorithm, std::string_view> kAlgorithmNames[] = {
    {Algorithm::automatic, "auto"}, {Algorithm::sg, "sg"}, {Algorithm::ps, "ps"},
    {Algorithm::ds, "ds"},          {Algorithm::gw, "gw"}, {Algorithm::frink, "frink"},
};
constexpr std::pair<Augment, std::string_view> kAugmentNames[] = {{Augment::local, "local"},
                                                                  {Augment::faithful, "faithful"}};

// SG or PS (paper §3.1), then Tarjan's augmenting paths until the matching is perfect. PS and
// the augmentation share one NeighbourTable, built in PS's time; SG does not read neighbours,
// so for SG it is built in the augmentation's time. Algorithm::automatic pairs in PS's place by
// pair_in_ps_place (greedy.hpp): the ordered sweep, Schrijver's exact matching where the sweep
// leaves nodes (on a bipartite graph PS leaves patches of one colour that cost the augmentation
// 20 BFS passes: the regular plates), PS where neither stands; Algorithm::ps runs PS alone.
void match_greedily_then_augment(const CubicGraph& graph, const PerfectMatchingOptions& options,
                                 PerfectMatchingResult& result) {
  Stopwatch initial;
  std::optional<NeighbourTable> table;
  if (options.algorithm == Algorithm::sg) {
    simple_greedy(graph, result.matching, options.seed);
    result.stats.initial_seconds = initial.seconds();
    result.stats.unpaired_after_initial = result.matching.unmatched_count();
  } else {
    const PsPlace made = pair_in_ps_place(table.emplace(graph), &result.matching.mate_edge,
                                          ps_place_options(options.algorithm, options.seed));
    result.stats.initial_seconds = initial.seconds();
    result.stats.unpaired_after_initial = made.unpaired;
    result.stats.schrijver = made.schrijver;
    result.stats.ordered_sweep = made.ordered_sweep;
  }
  Stopwatch augment;
  if (!table) table.emplace(graph, &result.matching.mate_edge);
  const AugmentStats augmented = augment_matching(*table, result.matching, options.augment);
  result.stats.augment_seconds = augment.seconds();
  result.stats.augmenting_paths = augmented.augmenting_paths;
  result.stats.blossoms = augmented.blossoms;
  result.stats.nodes_labelled = augmented.nodes_labelled;
}

// Frink's reductions (paper §3.2, Appendix A): a one-step algorithm, all of it "initial".
void match_by_reductions(const CubicGraph& graph, const PerfectMatchingOptions& options,
                         PerfectMatchingResult& result) {
  const ReductionChooser chooser = options.algorithm == Algorithm::frink ? ReductionChooser::frink
                                   : options.algorithm == Algorithm::ds  ? ReductionChooser::ds
                                                                         : ReductionChooser::gw;
  ReductionResult r = reduction::match_by_reductions(graph, kNoEdge, {.chooser = chooser});
  result.matching = std::move(r.matching);
  result.stats.initial_seconds =
      r.stats.setup_seconds + r.stats.reduce_seconds + r.stats.lift_seconds;
  result.stats.reductions = r.stats.reductions + r.stats.digon_reductions;
  for (int k = 0; k < 3; ++k) result.stats.lift_cases[k] = r.stats.lift_cases[k];
  result.stats.replacement_searches = r.stats.replacement_searches;
  result.stats.cover_swaps = r.stats.cover_swaps;
}

}  // namespace

std::string_view to_string(Algorithm algorithm) {
  for (auto [a, name] : kAlgorithmNames)
    if (a == algorithm) return name;
  return "?";
}

std::optional<Algorithm> parse_algorithm(std::string_view name) {
  for (auto [a, n] : kAlgorithmNames)
    if (n == name) return a;
  return std::nullopt;
}

std::string_view to_string(Augment augment) {
  for (auto [a, name] : kAugmentNames)
    if (a == augment) return name;
  return "?";
}

std::optional<Augment> parse_augment(std::string_view name) {
  for (auto [a, n] : kAugmentNames)
    if (n == name) return a;
  return std::nullopt;
}

PerfectMatchingResult perfect_matching(const CubicGraph& graph,
                                       const PerfectMatchingOptions& options) {
  PerfectMatchingResult result{Matching(graph.node_count(), options.memory), {}};
  if (options.validate) {
    Stopwatch clock;
    validate_bridgeless(graph);
    result.stats.validate_seconds = clock.seconds();
  }
  switch (options.algorithm) {
    case Algorithm::automatic:
    case Algorithm::sg:
    case Algorithm::ps:
      match_greedily_then_augment(graph, options, result);
      break;
    case Algorithm::frink:
    case Algorithm::ds:
    case Algorithm::gw:
      match_by_reductions(graph, options, result);
      break;
  }
  return result;
}

}  // namespace petersen
