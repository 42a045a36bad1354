#include "match_command.hpp"

#include <cinttypes>
#include <cstdio>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "json_text.hpp"
#include "option_checks.hpp"
#include "petersen/graph/stopwatch.hpp"
#include "petersen/io/file_bytes.hpp"
#include "petersen/io/read_graph.hpp"
#include "petersen/lemon_peer/lemon_peer.hpp"
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

struct MatchReport {
  const MatchArgs& args;
  GraphFormat format;
  const GraphFile& graph;
  const std::optional<AnyGraphMatching>& matched;           // by --algorithm (see run_match)
  const std::optional<AnyGraphCheapestMatching>& cheapest;  // --objective cost
  std::uint32_t size;
  bool perfect;
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
  if (r.cheapest) {
    std::fprintf(out,
                 "  \"total_cost\": %" PRId64
                 ",\n  \"optimality_certified\": true,\n  \"min_cost_seconds\": %.6f,\n",
                 r.cheapest->total_cost, r.cost_seconds);
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
                 json_string(r.matched->note).c_str());
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

// The algorithms that run on a graph: all but lrs, which needs a mesh.
std::vector<std::string> graph_algorithm_names() {
  std::vector<std::string> names = names_of<Algorithm>();
  std::erase(names, std::string(to_string(Algorithm::lrs)));
  return names;
}

}  // namespace

CLI::App* add_match_command(CLI::App& app, MatchArgs& args) {
  CLI::App* cmd = app.add_subcommand(
      "match",
      "A perfect matching of a cubic bridgeless graph file (a maximum matching of any other)");
  cmd->add_option("IN", args.input,
                  "graph: DIMACS (.dimacs, .col: 'p edge N M', 'e U V', 1-based) or an edge "
                  "list (.txt, .edges: 'U V' per line, 0-based, optional 'N M' first line), "
                  "optionally .gz; a third number C on every edge line is its cost")
      ->required();
  cmd->add_option("OUT", args.output,
                  "matched edges to write, one 'U V' line each, in the input's ids")
      ->required()
      ->check(in_existing_folder());
  cmd->add_option("--format", args.format, "dimacs or edges (default: from IN's extension)")
      ->transform(one_of(names_of<GraphFormat>()));
  cmd->add_option("--algorithm", args.algorithm,
                  "for a cubic bridgeless graph: auto (the fastest pairing, then augmenting "
                  "paths), sg, ps (Puli-Segal as the paper has it), ds, gw, frink or lemon")
      ->transform(one_of(graph_algorithm_names(), " (lrs works on meshes: petersen quad)"))
      ->capture_default_str();
  cmd->add_option("--objective", args.objective,
                  "size: a maximum matching (perfect when there is one); cost: the one of least "
                  "total cost among those, certified optimal, from the costs the file gives "
                  "('e U V C', 'U V C')")
      ->transform(one_of({"size", "cost"}))
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
  if (!algorithm || *algorithm == Algorithm::lrs) {
    throw CLI::ValidationError("--algorithm",
                               "unknown graph algorithm " + args.algorithm +
                                   (algorithm ? " (lrs works on meshes: petersen quad)" : ""));
  }
  const std::optional<Augment> augment = parse_augment(args.augment);
  if (!augment) throw CLI::ValidationError("--augment", "unknown augmentation " + args.augment);
  if (args.objective != "size" && args.objective != "cost") {
    throw CLI::ValidationError("--objective",
                               "unknown objective " + args.objective + " (size or cost)");
  }
  const bool by_cost = args.objective == "cost";

  const GraphFile graph = read_graph(args.input, format);
  if (by_cost && graph.costs.size() != graph.edges.size()) {
    throw GraphError(args.input +
                     ": --objective cost needs a cost on every edge line ('e U V C' or 'U V C')");
  }
  const double read_seconds = start.seconds();
  auto clock = Stopwatch();
  // The matching by --algorithm, unless only the cheapest is wanted (it finds the maximum size
  // itself): with --objective cost, only to tell first whether a perfect one exists. Both
  // verify what they return (a perfect matching; a maximum one by its Tutte-Berge witness; the
  // cheapest by its dual solution).
  std::optional<AnyGraphMatching> matched;
  if (!by_cost || args.require_perfect) {
    matched = match_any_graph(graph.node_count, graph.edges,
                              {.algorithm = *algorithm,
                               .augment = *augment,
                               .seed = args.seed,
                               .peer = &lemon_peer::maximum_matching});
  }
  std::optional<AnyGraphCheapestMatching> cheapest;
  const auto cost_clock = Stopwatch();
  if (by_cost && (!matched || matched->perfect)) {
    cheapest = cheapest_matching_any_graph(graph.node_count, graph.edges, graph.costs, 0);
  }
  const double cost_seconds = cost_clock.seconds();
  const double match_seconds = clock.seconds();
  const std::uint32_t size = cheapest ? cheapest->size : matched->size;
  const bool perfect = cheapest ? cheapest->perfect : matched->perfect;
  const std::uint64_t unmatched = std::uint64_t{graph.node_count} - 2 * std::uint64_t{size};

  if (!by_cost && !matched->cubic_bridgeless) {
    std::fprintf(stderr,
                 "petersen: note: %s is not cubic and bridgeless (%s): a maximum matching "
                 "instead, %" PRIu32 " edges, %" PRIu64 " nodes unmatched\n",
                 args.input.c_str(), matched->note.c_str(), size, unmatched);
  }
  const bool write = perfect || !args.require_perfect;
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
              cheapest                    ? "min-cost"
              : matched->cubic_bridgeless ? args.algorithm.c_str()
                                          : "augmenting paths",
              perfect ? "perfect" : "maximum", size, unmatched, match_seconds);
  if (cheapest) {
    std::printf("cost        %" PRId64 " (minimum certified, %.4f s)\n", cheapest->total_cost,
                cost_seconds);
  }
  if (write) {
    std::printf("written     %s (%.4f s)\n", args.output.c_str(), write_seconds);
  }
  std::printf("total       %.4f s\n", total_seconds);
  if (!args.stats_json.empty()) {
    write_stats_json({args, format ? *format : graph_format_of(args.input), graph, matched,
                      cheapest, size, perfect, read_seconds, cost_seconds, match_seconds,
                      write_seconds, total_seconds, write});
    std::printf("written     %s\n", args.stats_json.c_str());
  }
  if (!write) {
    std::fprintf(stderr, "petersen: %s has no perfect matching; nothing written to %s\n",
                 args.input.c_str(), args.output.c_str());
    return kNoPerfectMatching;
  }
  return 0;
}

}  // namespace petersen::cli
