#include "run_report.hpp"

#include <cinttypes>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "json_text.hpp"
#include "petersen/quadrangulate/stats_fields.hpp"

namespace petersen::cli {

namespace {

double initial_paired_percent(const QuadStats& s) {
  return s.triangles == 0 ? 100.0
                          : 100.0 * double(s.triangles - s.matching.unpaired_after_initial) /
                                double(s.triangles);
}

// When many triangles are left beside cuts of the mesh's attributes: which causes, and the
// --cross that lets pairs cross them (crossable_cuts_behind_left).
void print_left_causes(std::FILE* out, const QuadStats& s) {
  const auto behind = crossable_cuts_behind_left(s);
  if (behind.empty()) return;
  std::string causes, flag;
  for (const auto& [cause, count] : behind) {
    const std::string name(to_string(cause));
    causes += (causes.empty() ? "" : ", ") + name + " " + std::to_string(count);
    flag += (flag.empty() ? "" : ",") + name;
  }
  std::fprintf(out,
               "left by     %.1f %% of the triangles left, beside cut edges of the mesh's "
               "attributes (%s); --cross %s lets pairs cross them\n",
               100.0 * double(s.triangles_left) / double(s.triangles), causes.c_str(),
               flag.c_str());
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
  std::fprintf(out, "cut edges   %" PRIu64 " of %" PRIu64, s.cuts.total(), s.mesh_edges);
  for (int c = 0, listed = 0; c < kCutCauses; ++c) {
    if (s.cuts.by_cause[c] > 0) {
      std::fprintf(out, "%s %s %" PRIu64, listed++ == 0 ? ":" : ",",
                   std::string(to_string(CutCause(c))).c_str(), s.cuts.by_cause[c]);
    }
  }
  const PairingAlgorithm& a = r.options.algorithm;
  const bool quality = r.options.objective != Objective::pairs;
  const bool lrs = std::holds_alternative<Lrs>(a);
  const Algorithm* graph = std::get_if<Algorithm>(&a);
  const bool augments = !quality && (lrs || *graph == Algorithm::automatic ||
                                     *graph == Algorithm::sg || *graph == Algorithm::ps);
  const std::string by_cost =
      "min-cost (objective " + std::string(to_string(r.options.objective)) + ")";
  std::fprintf(out, "\nalgorithm   %s%s%s\n",
               quality ? by_cost.c_str() : std::string(to_string(a)).c_str(),
               augments ? ", augment " : "",
               augments ? std::string(to_string(r.options.augment)).c_str() : "");
  if (s.lrs_fallback_components > 0) {
    // The default algorithm takes what lrs refuses (quadrangulate.hpp); the reason is the first
    // component's.
    std::fprintf(out,
                 "            lrs refused %" PRIu64
                 " closed component%s (paired by auto instead): %s\n",
                 s.lrs_fallback_components, s.lrs_fallback_components == 1 ? "" : "s",
                 s.lrs_fallback_reason.c_str());
  }
  std::fprintf(out, "load        %.4f s\n", r.load_seconds);
  std::fprintf(out, "check       %.4f s\n", s.check_seconds);
  if (r.options.objective == Objective::quads && r.options.flow_weight > 0) {
    std::fprintf(out, "field       %.4f s  cross field in %u iterations (part of check)\n",
                 s.field_seconds, s.field_iterations);
  }
  std::fprintf(out, "dual        %.4f s\n", s.dual_seconds);
  std::fprintf(out, "initial     %.4f s  paired %.4f %%  unpaired %" PRIu64 "%s\n",
               s.matching.initial_seconds, initial_paired_percent(s),
               std::uint64_t{s.matching.unpaired_after_initial},
               s.matching.schrijver       ? "  (Schrijver's exact matching: a bipartite dual)"
               : s.matching.ordered_sweep ? "  (ordered sweep: a local numbering)"
                                          : "");
  std::fprintf(
      out, "augment     %.4f s  paths %" PRIu64 "  blossoms %" PRIu64 "  labelled %" PRIu64 "\n",
      s.matching.augment_seconds, s.matching.augmenting_paths, s.matching.blossoms,
      s.matching.nodes_labelled);
  if (s.matching.reductions > 0)
    std::fprintf(out, "reductions  %" PRIu64 "\n", s.matching.reductions);
  if (lrs) {
    std::fprintf(out,
                 "flipped     %" PRIu64 " edges, irreducible triangulations %" PRIu64 " vertices\n",
                 s.flipped_edges, s.irreducible_vertices);
  }
  if (r.options.objective == Objective::quads) {
    // Not a maximum pairing by design: a triangle stays where leaving it costs less.
    std::fprintf(out, "verify      %.4f s  optimum %s%s\n", s.verify_seconds,
                 s.optimality_certified ? "certified" : "NOT certified",
                 s.maximum_certified ? ", every triangle paired" : "");
  } else {
    std::fprintf(out, "verify      %.4f s  maximum %s\n", s.verify_seconds,
                 s.maximum_certified ? "certified" : "NOT certified");
  }
  std::fprintf(out, "pairs       %" PRIu64 "  triangles left %" PRIu64 " (%.4f s)\n", s.pairs,
               s.triangles_left, s.quads_seconds);
  print_left_causes(out, s);
  if (s.duplicate_faces > 0) {
    std::fprintf(out,
                 "duplicates  %" PRIu64
                 " faces repeat an earlier face's vertices: no pair crosses "
                 "their edges; --drop-duplicate-faces drops the copies\n",
                 s.duplicate_faces);
  }
  std::fprintf(out,
               "quality     median %.2f, 95th percentile %.2f degrees, %" PRIu64
               " non-convex, total %.4f%s\n",
               s.quality_median, s.quality_p95, s.nonconvex_quads, s.objective_total,
               s.optimality_certified ? " (minimum certified)" : "");
  if (r.options.max_corner_deviation) {
    std::fprintf(out, "threshold   quads of at most %g degrees; %" PRIu64 " pairs over it cut%s\n",
                 *r.options.max_corner_deviation,
                 s.cuts.by_cause[static_cast<int>(CutCause::shape)],
                 quality ? "" : "; any pairs within it, --objective quality picks the cheapest");
  }
  if (s.added_vertices > 0 || s.all_quad_seconds > 0) {
    std::fprintf(out,
                 "all-quad    %" PRIu64 " vertices added (%" PRIu64 " midpoints, fewest %" PRIu64
                 "%s), %" PRIu64 " faces made, worst corner median %.2f, p95 %.2f (%.4f s)\n",
                 s.added_vertices, s.split_edges, s.added_vertices_minimum,
                 s.all_quad_certified ? ", certified" : ", not proved", s.split_quads,
                 s.split_quality_median, s.split_quality_p95, s.all_quad_seconds);
  }
  if (s.degenerate_faces > 0) {
    std::fprintf(out, "degenerate  %" PRIu64 " faces repeat a vertex: kept as they are\n",
                 s.degenerate_faces);
  }
  std::fprintf(out, "written     %s (%.4f s)\n", r.output.c_str(), r.write_seconds);
  std::fprintf(out, "total       %.4f s\n", r.total_seconds);
}

void write_json(std::FILE* out, const RunReport& r) {
  const std::vector<StatField> fields = stats_fields(r.quad, r.options,
                                                     {.input = r.input,
                                                      .output = r.output,
                                                      .load_seconds = r.load_seconds,
                                                      .write_seconds = r.write_seconds,
                                                      .total_seconds = r.total_seconds});
  std::fprintf(out, "{\n");
  for (std::size_t i = 0; i < fields.size(); ++i) {
    std::fprintf(out, "  \"%s\": ", fields[i].key.c_str());
    std::visit(
        [&](const auto& v) {
          using T = std::decay_t<decltype(v)>;
          if constexpr (std::is_same_v<T, bool>) {
            std::fputs(v ? "true" : "false", out);
          } else if constexpr (std::is_same_v<T, std::int64_t>) {
            std::fprintf(out, "%" PRId64, v);
          } else if constexpr (std::is_same_v<T, std::uint64_t>) {
            std::fprintf(out, "%" PRIu64, v);
          } else if constexpr (std::is_same_v<T, double>) {
            std::fprintf(out, "%.9f", v);
          } else if constexpr (std::is_same_v<T, std::string>) {
            std::fputs(json_string(v).c_str(), out);
          } else {
            std::fputs("{", out);
            for (std::size_t k = 0; k < v.size(); ++k) {
              std::fprintf(out, "%s\"%s\": %" PRIu64, k ? ", " : "", v[k].first.c_str(),
                           v[k].second);
            }
            std::fputs("}", out);
          }
        },
        fields[i].value);
    std::fputs(i + 1 < fields.size() ? ",\n" : "\n}\n", out);
  }
}

}  // namespace petersen::cli
