#include "match_command.hpp"

#include <algorithm>
#include <cinttypes>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "json_text.hpp"
#include "match_costs.hpp"
#include "option_checks.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/io/file_bytes.hpp"
#include "petersen/io/read_graph.hpp"
#include "petersen/matching/any_graph.hpp"

namespace petersen::cli {

namespace {

// The matched edges as "u v" lines in the input's ids, at their first ends in node order.
std::string matched_edge_lines(const GraphFile& graph, std::span<const EdgeId> mate_edge) {
  std::string text;
  text.reserve(std::size_t{graph.node_count} * 8);
  char line[32];
  for (NodeId v = 0; v < graph.node_count; ++v) {
    const EdgeId e = mate_edge[v];
    if (e == kNoEdge || graph.edges[e][0] != v) continue;  // once per edge, at its first end
    const int n = std::snprintf(line, sizeof line, "%" PRIu64 " %" PRIu64 "\n",
                                std::uint64_t{graph.edges[e][0]} + graph.first_id,
                                std::uint64_t{graph.edges[e][1]} + graph.first_id);
    text.append(line, static_cast<std::size_t>(n));
  }
  return text;
}

struct Objective {
  std::string_view name;
  std::optional<CostObjective> solver;  // none: size
  bool weights;                         // the file's numbers are weights: costs negated
};
constexpr Objective kObjectives[] = {
    {"size", std::nullopt, false},
    {"cost", CostObjective::maximum, false},
    {"weight", CostObjective::any_size, true},
    {"weight-maximum", CostObjective::maximum, true},
    {"perfect-cost", CostObjective::perfect, false},
};

// match_any_graph's note with the node or edge named in the file's terms: its ids, an edge by
// its line.
std::string file_note(const GraphFile& graph, const AnyGraphMatching& matched) {
  if (matched.note_edge != kNoEdge) {
    const auto [a, b] = graph.edges[matched.note_edge];
    return "the edge on line " + std::to_string(graph.edge_lines[matched.note_edge]) + " (" +
           std::to_string(graph.file_id(a)) + ", " + std::to_string(graph.file_id(b)) + ") " +
           matched.note_predicate;
  }
  if (matched.note_node != kNoNode) {
    return "node " + std::to_string(graph.file_id(matched.note_node)) + " " +
           matched.note_predicate;
  }
  return matched.note;
}

// The Tutte–Berge proof that no perfect matching exists, in the file's ids: G − A has |A| + u
// odd components, each leaving a node unmatched or matched into A, so every matching leaves u.
std::string tutte_text(const GraphFile& graph, const std::vector<std::uint32_t>& set,
                       std::uint64_t unmatched) {
  std::string ids;
  for (std::size_t i = 0; i < set.size() && i < 20; ++i) {
    if (i > 0) ids += ' ';
    ids += std::to_string(graph.file_id(set[i]));
  }
  if (set.size() > 20) ids += " ...";
  return "Tutte-Berge witness A = {" + ids + "}: G - A has " +
         std::to_string(set.size() + unmatched) +
         " odd components, more than |A| = " + std::to_string(set.size()) +
         ", so every matching leaves " + std::to_string(unmatched) + " nodes unmatched";
}

struct MatchReport {
  const MatchArgs& args;
  GraphFormat format;
  const GraphFile& graph;
  const std::optional<AnyGraphMatching>& matched;           // by --algorithm (see run_match)
  const std::optional<AnyGraphCheapestMatching>& cheapest;  // a cost objective
  const std::optional<SolverCosts>& costs;
  std::uint32_t size;
  bool perfect;
  bool refused;  // perfect-cost without a perfect matching
  double gap;
  double read_seconds, cost_seconds, match_seconds, write_seconds, total_seconds;
  bool written;
};

void print_stats_json(std::FILE* out, const MatchReport& r) {
  std::fprintf(out, "{\n  \"input\": %s,\n  \"output\": %s,\n  \"format\": %s,\n",
               json_string(r.args.input).c_str(), json_string(r.args.output).c_str(),
               json_string(std::string(to_string(r.format))).c_str());
  std::fprintf(out, "  \"algorithm\": %s,\n  \"augment\": %s,\n  \"objective\": %s,\n",
               json_string(!r.matched                    ? "min-cost"
                           : r.matched->cubic_bridgeless ? r.args.algorithm
                                                         : "augment")
                   .c_str(),
               json_string(r.args.augment).c_str(), json_string(r.args.objective).c_str());
  if (r.cheapest && !r.refused) {
    std::fprintf(out,
                 "  \"%s\": %s,\n  \"optimality_certified\": true,\n  \"exact\": %s,\n  "
                 "\"gap_bound\": %.17g,\n  \"min_cost_seconds\": %.6f,\n",
                 r.costs->negated ? "total_weight" : "total_cost",
                 r.costs->text(r.cheapest->total_cost, r.cheapest->mate_edge, r.graph).c_str(),
                 r.costs->rounded ? "false" : "true", r.gap, r.cost_seconds);
  } else if (r.cheapest) {  // perfect-cost without a perfect matching: the proof
    std::string set;
    for (std::uint32_t v : r.cheapest->tutte_set)
      set += (set.empty() ? "" : ", ") + std::to_string(r.graph.file_id(v));
    std::fprintf(out, "  \"tutte_set\": [%s],\n", set.c_str());
  }
  std::fprintf(out,
               "  \"nodes\": %" PRIu32
               ",\n  \"edges\": %zu,\n  \"perfect\": %s,\n  \"matched_edges\": %" PRIu32
               ",\n  \"unmatched_nodes\": %" PRIu64 ",\n  \"written\": %s,\n",
               r.graph.node_count, r.graph.edges.size(), r.perfect ? "true" : "false", r.size,
               std::uint64_t{r.graph.node_count} - 2 * std::uint64_t{r.size},
               r.written ? "true" : "false");
  if (r.matched) {  // the run by --algorithm, when there was one
    const PerfectMatchingStats& s = r.matched->stats;
    std::fprintf(out, "  \"cubic_bridgeless\": %s,\n  \"note\": %s,\n",
                 r.matched->cubic_bridgeless ? "true" : "false",
                 json_string(file_note(r.graph, *r.matched)).c_str());
    std::fprintf(out,
                 "  \"augmenting_paths\": %" PRIu64 ",\n  \"blossoms\": %" PRIu64
                 ",\n  \"reductions\": %" PRIu64
                 ",\n  \"schrijver\": %s,\n  \"ordered_sweep\": %s,\n",
                 s.augmenting_paths, s.blossoms, s.reductions, s.schrijver ? "true" : "false",
                 s.ordered_sweep ? "true" : "false");
    std::fprintf(out,
                 "  \"validate_seconds\": %.6f,\n  \"initial_seconds\": %.6f,\n  "
                 "\"augment_seconds\": %.6f,\n",
                 s.validate_seconds, s.initial_seconds, s.augment_seconds);
  }
  std::fprintf(out,
               "  \"read_seconds\": %.6f,\n  \"match_seconds\": %.6f,\n  "
               "\"write_seconds\": %.6f,\n  \"total_seconds\": %.6f\n}\n",
               r.read_seconds, r.match_seconds, r.write_seconds, r.total_seconds);
}

// Whole or not at all (write_printed).
void write_stats_json(const MatchReport& r) {
  write_printed(r.args.stats_json, [&](std::FILE* out) { print_stats_json(out, r); });
}

}  // namespace

CLI::App* add_match_command(CLI::App& app, MatchArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "match",
      "A perfect matching of a cubic bridgeless graph file (a maximum matching of any other)");
  cmd->add_option("IN", args.input,
                  "graph: DIMACS (.dimacs, .col: 'p edge N M', 'e U V', 1-based) or an edge "
                  "list (.txt, .edges: 'U V' per line, 0-based, an optional '# nodes N' "
                  "comment), optionally .gz; a third number C (integer or decimal) on every "
                  "edge line is its cost or weight")
      ->required();
  cmd->add_option("OUT", args.output,
                  "matched edges to write, one 'U V' line each, in the input's ids")
      ->required()
      ->check(in_existing_folder());
  cmd->add_option("--format", args.format, "dimacs or edges (default: from IN's extension)")
      ->transform(one_of(names_of<GraphFormat>()));
  cmd->add_option("--algorithm", args.algorithm,
                  "for a cubic bridgeless graph: auto (the fastest pairing, then augmenting "
                  "paths), sg, ps (Puli-Segal as the paper has it), ds, gw or frink")
      ->transform(one_of(names_of<Algorithm>(), " (lrs works on meshes: petersen quad)"))
      ->capture_default_str();
  cmd->add_option("--objective", args.objective,
                  "size: a maximum matching (perfect when there is one); from the numbers the "
                  "file gives ('e U V C', 'U V C'), each answer certified optimal: cost: the "
                  "cheapest maximum matching; weight: the heaviest matching of any size; "
                  "weight-maximum: the heaviest maximum matching; perfect-cost: the cheapest "
                  "perfect matching (exit 3 with a Tutte-Berge proof when there is none)")
      ->transform(one_of({"size", "cost", "weight", "weight-maximum", "perfect-cost"}))
      ->capture_default_str();
  cmd->add_option("--augment", args.augment, "augmenting-path variant: local or faithful")
      ->transform(one_of(names_of<Augment>()))
      ->capture_default_str();
  cmd->add_option("--seed", args.seed, "seed of the random orders (auto, sg, ps)")
      ->capture_default_str();
  cmd->add_option("--stats-json", args.stats_json,
                  "also write the summary as one JSON object to this file (whole, then renamed "
                  "into place)")
      ->check(in_existing_folder());
  cmd->add_flag("--require-perfect", args.require_perfect,
                "exit with code 3, writing nothing, when the graph has no perfect matching");
  return cmd;
}

int run_match(const MatchArgs& args) {
  const auto start = Stopwatch();
  std::optional<GraphFormat> format;
  if (!args.format.empty()) {
    format = parse_graph_format(args.format);
    if (!format) throw CLI::ValidationError("--format", "unknown graph format " + args.format);
  }
  const std::optional<Algorithm> algorithm = parse_algorithm(args.algorithm);
  if (!algorithm) {
    throw CLI::ValidationError("--algorithm", "unknown graph algorithm " + args.algorithm);
  }
  const std::optional<Augment> augment = parse_augment(args.augment);
  if (!augment) throw CLI::ValidationError("--augment", "unknown augmentation " + args.augment);
  const Objective* objective = nullptr;
  for (const Objective& o : kObjectives)
    if (o.name == args.objective) objective = &o;
  if (!objective) {
    throw CLI::ValidationError("--objective",
                               "unknown objective " + args.objective +
                                   " (size, cost, weight, weight-maximum or perfect-cost)");
  }
  const bool by_cost = objective->solver.has_value();

  const GraphFile graph = read_graph(args.input, format);
  if (by_cost && !graph.has_costs() && !graph.edges.empty()) {
    throw GraphError(args.input + ": --objective " + args.objective +
                     " needs a number on every edge line ('e U V C' or 'U V C')");
  }
  const double read_seconds = start.seconds();
  auto clock = Stopwatch();
  // The matching by --algorithm, unless only the cheapest is wanted (it finds the maximum size
  // itself): with a cost objective, only to tell first whether a perfect one exists. Both
  // verify what they return (a perfect matching; a maximum one by its Tutte-Berge witness; the
  // cheapest by its dual solution).
  std::optional<AnyGraphMatching> matched;
  if (!by_cost || (args.require_perfect && *objective->solver != CostObjective::perfect)) {
    matched = match_any_graph(graph.node_count, graph.edges,
                              {.algorithm = *algorithm, .augment = *augment, .seed = args.seed});
  }
  std::optional<AnyGraphCheapestMatching> cheapest;
  std::optional<SolverCosts> costs;
  const auto cost_clock = Stopwatch();
  if (by_cost && (!matched || matched->perfect)) {
    std::uint64_t loop_free = 0;
    for (auto [a, b] : graph.edges) loop_free += a != b;
    const std::uint64_t largest = std::min<std::uint64_t>(graph.node_count / 2, loop_free);
    costs = solver_costs(graph, objective->weights,
                         *objective->solver == CostObjective::maximum ? largest : 0);
    cheapest = cheapest_matching_any_graph(graph.node_count, graph.edges, costs->costs, 0,
                                           *objective->solver);
  }
  const double cost_seconds = cost_clock.seconds();
  const double match_seconds = clock.seconds();
  const std::uint32_t size = cheapest ? cheapest->size : matched->size;
  const bool perfect = cheapest ? cheapest->perfect : matched->perfect;
  const std::uint64_t unmatched = std::uint64_t{graph.node_count} - 2 * std::uint64_t{size};
  const bool refused = cheapest && *objective->solver == CostObjective::perfect && !perfect;

  if (!by_cost && !matched->cubic_bridgeless) {
    std::fprintf(stderr,
                 "petersen: note: %s is not cubic and bridgeless (%s): a maximum matching "
                 "instead, %" PRIu32 " edges, %" PRIu64 " nodes unmatched\n",
                 args.input.c_str(), file_note(graph, *matched).c_str(), size, unmatched);
  }
  const bool write = !refused && (perfect || !args.require_perfect);
  clock = Stopwatch();
  if (write) {
    write_file_bytes(args.output, cheapest ? matched_edge_lines(graph, cheapest->mate_edge)
                                           : matched_edge_lines(graph, matched->mate_edge));
  }
  const double write_seconds = clock.seconds();
  const double total_seconds = start.seconds();

  std::printf("input       %s (%s, %" PRIu32 " nodes, %zu edges)\n", args.input.c_str(),
              std::string(to_string(format ? *format : graph_format_of(args.input))).c_str(),
              graph.node_count, graph.edges.size());
  std::printf("matching    %s: %s, %" PRIu32 " edges, %" PRIu64 " nodes unmatched (%.4f s)\n",
              cheapest                    ? args.objective.c_str()
              : matched->cubic_bridgeless ? args.algorithm.c_str()
                                          : "augmenting paths",
              perfect ? "perfect" : "maximum", size, unmatched, match_seconds);
  const double gap = costs ? costs->gap_bound(size + std::uint64_t{graph.node_count} / 2) : 0;
  if (cheapest && !refused) {
    std::printf("%s      %s (%s certified, %.4f s)\n", objective->weights ? "weight" : "cost  ",
                costs->text(cheapest->total_cost, cheapest->mate_edge, graph).c_str(),
                objective->weights ? "maximum" : "minimum", cost_seconds);
    if (costs->rounded) {
      std::printf(
          "tolerance   %.3g: the numbers rounded to multiples of 2^%d, the optimum of "
          "those certified, within %.3g of the exact optimum\n",
          gap, -costs->rounded->exponent, gap);
    }
  }
  if (write) {
    std::printf("written     %s (%.4f s)\n", args.output.c_str(), write_seconds);
  }
  std::printf("total       %.4f s\n", total_seconds);
  if (!args.stats_json.empty()) {
    write_stats_json({args, format ? *format : graph_format_of(args.input), graph, matched,
                      cheapest, costs, size, perfect, refused, gap, read_seconds, cost_seconds,
                      match_seconds, write_seconds, total_seconds, write});
    std::printf("written     %s\n", args.stats_json.c_str());
  }
  if (refused) {
    std::fprintf(stderr, "petersen: %s has no perfect matching (%s); nothing written to %s\n",
                 args.input.c_str(), tutte_text(graph, cheapest->tutte_set, unmatched).c_str(),
                 args.output.c_str());
    return kNoPerfectMatching;
  }
  if (!write) {
    std::fprintf(stderr, "petersen: %s has no perfect matching; nothing written to %s\n",
                 args.input.c_str(), args.output.c_str());
    return kNoPerfectMatching;
  }
  return 0;
}

}  // namespace petersen::cli
