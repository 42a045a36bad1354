#include "run_report.hpp"

#include <cinttypes>
#include <string>

#include "json_text.hpp"

namespace petersen::cli {

namespace {

double initial_paired_percent(const QuadStats& s) {
  return s.triangles == 0 ? 100.0
                          : 100.0 * double(s.triangles - s.matching.unpaired_after_initial) /
                                double(s.triangles);
}

}  // namespace

void print_summary(std::FILE* out, const RunReport& r) {
  const QuadStats& s = r.quad;
  std::fprintf(out, "input       %s\n", r.input.c_str());
  std::fprintf(out,
               "faces       %" PRIu64 ": %" PRIu64 " triangles, %" PRIu64
               " other polygons kept (vertices %" PRIu64 ")\n",
               s.faces_in, s.triangles, s.polygons_kept, s.vertices);
  std::fprintf(out, "components  %" PRIu64 " (%" PRIu64 " closed)\n", s.components,
               s.closed_components);
  std::fprintf(out, "cut edges   %" PRIu64 " of %" PRIu64 ":", s.cuts.total(), s.mesh_edges);
  for (int c = 0; c < kCutCauses; ++c) {
    if (s.cuts.by_cause[c] > 0) {
      std::fprintf(out, " %s %" PRIu64, std::string(to_string(CutCause(c))).c_str(),
                   s.cuts.by_cause[c]);
    }
  }
  std::fprintf(out, "\nalgorithm   %s%s%s\n", r.algorithm.c_str(),
               r.augment.empty() ? "" : ", augment ", r.augment.c_str());
  if (s.lrs_fallback_components > 0) {
    std::fprintf(out, "            %" PRIu64 " closed components by ps: lrs needs %s\n",
                 s.lrs_fallback_components, s.lrs_fallback_reason.c_str());
  }
  std::fprintf(out, "load        %.4f s\n", r.load_seconds);
  std::fprintf(out, "check       %.4f s\n", s.check_seconds);
  std::fprintf(out, "dual        %.4f s\n", s.dual_seconds);
  std::fprintf(out, "initial     %.4f s  paired %.4f %%  unpaired %" PRIu64 "\n",
               s.matching.initial_seconds, initial_paired_percent(s),
               std::uint64_t{s.matching.unpaired_after_initial});
  std::fprintf(
      out, "augment     %.4f s  paths %" PRIu64 "  blossoms %" PRIu64 "  labelled %" PRIu64 "\n",
      s.matching.augment_seconds, s.matching.augmenting_paths, s.matching.blossoms,
      s.matching.nodes_labelled);
  if (s.matching.reductions > 0)
    std::fprintf(out, "reductions  %" PRIu64 "\n", s.matching.reductions);
  if (r.algorithm == "lrs") {
    std::fprintf(out,
                 "flipped     %" PRIu64 " edges, irreducible triangulations %" PRIu64 " vertices\n",
                 s.flipped_edges, s.irreducible_vertices);
  }
  std::fprintf(out, "verify      %.4f s  maximum %s\n", s.verify_seconds,
               s.maximum_certified ? "certified" : "NOT certified");
  std::fprintf(out, "pairs       %" PRIu64 "  triangles left %" PRIu64 " (%.4f s)\n", s.pairs,
               s.triangles_left, s.quads_seconds);
  std::fprintf(out,
               "quality     median %.2f, 95th percentile %.2f degrees, %" PRIu64
               " non-convex, total %.4f%s\n",
               s.quality_median, s.quality_p95, s.nonconvex_quads, s.objective_total,
               s.optimality_certified ? " (minimum certified)" : "");
  if (s.added_vertices > 0 || s.all_quad_seconds > 0) {
    std::fprintf(out, "all-quad    %" PRIu64 " vertices added, %" PRIu64 " faces split (%.4f s)\n",
                 s.added_vertices, s.split_quads, s.all_quad_seconds);
  }
  std::fprintf(out, "write       %s (%.4f s)\n", r.output.c_str(), r.write_seconds);
  std::fprintf(out, "total       %.4f s\n", r.total_seconds);
}

void write_json(std::FILE* out, const RunReport& r) {
  const QuadStats& s = r.quad;
  auto u = [&](const char* key, std::uint64_t value) {
    std::fprintf(out, "  \"%s\": %" PRIu64 ",\n", key, value);
  };
  auto d = [&](const char* key, double value) {
    std::fprintf(out, "  \"%s\": %.9f,\n", key, value);
  };
  std::fprintf(out, "{\n  \"input\": %s,\n  \"output\": %s,\n  \"algorithm\": %s,\n",
               json_string(r.input).c_str(), json_string(r.output).c_str(),
               json_string(r.algorithm).c_str());
  if (!r.augment.empty()) std::fprintf(out, "  \"augment\": %s,\n", json_string(r.augment).c_str());
  u("vertices", s.vertices);
  u("faces_in", s.faces_in);
  u("triangles", s.triangles);
  u("polygons_kept", s.polygons_kept);
  if (s.genus) std::fprintf(out, "  \"genus\": %" PRId64 ",\n", *s.genus);
  std::fprintf(out, "  \"euler_characteristic\": %" PRId64 ",\n", s.euler_characteristic);
  u("components", s.components);
  u("closed_components", s.closed_components);
  u("mesh_edges", s.mesh_edges);
  u("cut_edges", s.cuts.total());
  std::fprintf(out, "  \"cut_edges_by_cause\": {");
  for (int c = 0; c < kCutCauses; ++c) {
    std::fprintf(out, "%s\"%s\": %" PRIu64, c ? ", " : "",
                 std::string(to_string(CutCause(c))).c_str(), s.cuts.by_cause[c]);
  }
  std::fprintf(out, "},\n");
  u("inconsistent_edges", s.inconsistent_edges);
  d("load_seconds", r.load_seconds);
  d("check_seconds", s.check_seconds);
  d("dual_seconds", s.dual_seconds);
  d("initial_seconds", s.matching.initial_seconds);
  d("initial_paired_percent", initial_paired_percent(s));
  u("unpaired_after_initial", s.matching.unpaired_after_initial);
  d("augment_seconds", s.matching.augment_seconds);
  d("matching_seconds", s.matching.matching_seconds());
  u("augmenting_paths", s.matching.augmenting_paths);
  u("blossoms", s.matching.blossoms);
  u("nodes_labelled", s.matching.nodes_labelled);
  u("reductions", s.matching.reductions);
  if (r.algorithm == "lrs") {
    u("flipped_edges", s.flipped_edges);
    u("irreducible_vertices", s.irreducible_vertices);
    u("lrs_fallback_components", s.lrs_fallback_components);
  }
  d("verify_seconds", s.verify_seconds);
  std::fprintf(out, "  \"maximum_certified\": %s,\n", s.maximum_certified ? "true" : "false");
  u("pairs", s.pairs);
  d("quality_median", s.quality_median);
  d("quality_p95", s.quality_p95);
  u("nonconvex_quads", s.nonconvex_quads);
  d("objective_total", s.objective_total);
  std::fprintf(out, "  \"optimality_certified\": %s,\n", s.optimality_certified ? "true" : "false");
  u("triangles_left", s.triangles_left);
  d("quads_seconds", s.quads_seconds);
  u("added_vertices", s.added_vertices);
  d("all_quad_seconds", s.all_quad_seconds);
  d("write_seconds", r.write_seconds);
  std::fprintf(out, "  \"total_seconds\": %.9f\n}\n", r.total_seconds);
}

}  // namespace petersen::cli
