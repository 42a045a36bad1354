#include "petersen/quadrangulate/stats_fields.hpp"

namespace petersen {

std::vector<std::pair<CutCause, std::uint64_t>> crossable_cuts_behind_left(const QuadStats& stats) {
  std::vector<std::pair<CutCause, std::uint64_t>> causes;
  if (double(stats.triangles_left) <= kLeftShareToExplain * double(stats.triangles)) return causes;
  for (int c = 0; c < kCutCauses; ++c) {
    const CutCause cause = CutCause(c);
    if (is_attribute_cause(cause) && stats.cuts.by_cause[c] > 0) {
      causes.emplace_back(cause, stats.cuts.by_cause[c]);
    }
  }
  return causes;
}

std::vector<StatField> stats_fields(const QuadStats& s, const QuadOptions& options,
                                    const RunFigures& run) {
  std::vector<StatField> f;
  auto add = [&](const char* key, StatValue value) { f.push_back({key, std::move(value)}); };
  auto u = [&](const char* key, std::uint64_t value) { add(key, value); };
  auto d = [&](const char* key, double value) { add(key, value); };
  if (!run.input.empty()) add("input", run.input);
  if (!run.output.empty()) add("output", run.output);
  // Both cost objectives run the minimum-cost matching, not the algorithm.
  const bool quality = options.objective != Objective::pairs;
  // What the algorithm ran: lrs, or a graph algorithm; auto, sg, ps and lrs augment, auto and ps
  // pair in PS's place.
  const bool lrs = !quality && std::holds_alternative<Lrs>(options.algorithm);
  const Algorithm* graph = quality ? nullptr : std::get_if<Algorithm>(&options.algorithm);
  const bool in_ps_place = graph && (*graph == Algorithm::automatic || *graph == Algorithm::ps);
  const bool augments = lrs || in_ps_place || (graph && *graph == Algorithm::sg);
  add("objective", std::string(to_string(options.objective)));
  add("algorithm", quality ? std::string("min-cost") : std::string(to_string(options.algorithm)));
  if (options.objective == Objective::quads) {
    d("triangle_cost", options.triangle_cost);
    d("flow_weight", options.flow_weight);
  }
  if (augments) {
    add("augment", std::string(to_string(options.augment)));
  }
  if (options.max_corner_deviation) d("max_corner_deviation", *options.max_corner_deviation);
  u("vertices", s.vertices);
  u("faces_in", s.faces_in);
  u("triangles", s.triangles);
  u("polygons_kept", s.polygons_kept);
  u("duplicate_faces", s.duplicate_faces);
  if (s.genus) add("genus", *s.genus);
  add("euler_characteristic", s.euler_characteristic);
  u("components", s.components);
  u("closed_components", s.closed_components);
  u("mesh_edges", s.mesh_edges);
  u("cut_edges", s.cuts.total());
  std::vector<std::pair<std::string, std::uint64_t>> by_cause;
  for (int c = 0; c < kCutCauses; ++c) {
    by_cause.emplace_back(std::string(to_string(CutCause(c))), s.cuts.by_cause[c]);
  }
  add("cut_edges_by_cause", std::move(by_cause));
  u("inconsistent_edges", s.inconsistent_edges);
  if (run.load_seconds) d("load_seconds", *run.load_seconds);
  d("check_seconds", s.check_seconds);
  if (options.objective == Objective::quads && options.flow_weight > 0) {
    d("field_seconds", s.field_seconds);
    u("field_iterations", s.field_iterations);
  }
  d("dual_seconds", s.dual_seconds);
  d("initial_seconds", s.matching.initial_seconds);
  d("initial_paired_percent",
    s.triangles == 0
        ? 100.0
        : 100.0 * double(s.triangles - s.matching.unpaired_after_initial) / double(s.triangles));
  u("unpaired_after_initial", s.matching.unpaired_after_initial);
  if (in_ps_place) add("schrijver", s.matching.schrijver);
  if (in_ps_place) add("ordered_sweep", s.matching.ordered_sweep);
  d("augment_seconds", s.matching.augment_seconds);
  d("matching_seconds", s.matching.matching_seconds());
  u("augmenting_paths", s.matching.augmenting_paths);
  u("blossoms", s.matching.blossoms);
  u("nodes_labelled", s.matching.nodes_labelled);
  u("reductions", s.matching.reductions);
  if (lrs) {
    u("flipped_edges", s.flipped_edges);
    u("irreducible_vertices", s.irreducible_vertices);
    u("lrs_fallback_components", s.lrs_fallback_components);
  }
  d("verify_seconds", s.verify_seconds);
  add("maximum_certified", s.maximum_certified);
  u("pairs", s.pairs);
  u("triangles_left", s.triangles_left);
  if (const auto behind = crossable_cuts_behind_left(s); !behind.empty()) {
    std::vector<std::pair<std::string, std::uint64_t>> by_name;
    for (const auto& [cause, count] : behind) by_name.emplace_back(to_string(cause), count);
    add("cross_to_pair", std::move(by_name));
  }
  d("quality_median", s.quality_median);
  d("quality_p95", s.quality_p95);
  u("nonconvex_quads", s.nonconvex_quads);
  d("objective_total", s.objective_total);
  add("optimality_certified", s.optimality_certified);
  d("quads_seconds", s.quads_seconds);
  u("added_vertices", s.added_vertices);
  if (options.all_quad) {
    u("split_edges", s.split_edges);
    u("degenerate_faces", s.degenerate_faces);
    u("centre_vertices", s.centre_vertices);
    u("added_vertices_minimum", s.added_vertices_minimum);
    add("all_quad_certified", s.all_quad_certified);
    u("split_quads", s.split_quads);
    d("split_quality_median", s.split_quality_median);
    d("split_quality_p95", s.split_quality_p95);
  }
  d("all_quad_seconds", s.all_quad_seconds);
  if (run.write_seconds) d("write_seconds", *run.write_seconds);
  d("total_seconds", run.total_seconds.value_or(s.total_seconds));
  return f;
}

}  // namespace petersen
