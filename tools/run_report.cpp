#include "run_report.hpp"

#include <cinttypes>
#include <string>

#include "json_text.hpp"

namespace petersen::cli {

void print_summary(std::FILE* out, const RunReport& r) {
  std::fprintf(out, "input       %s\n", r.input.c_str());
  std::fprintf(out,
               "triangles   %" PRIu64 " (vertices %" PRIu64 ", genus %" PRId64
               ", components %" PRIu64 ")\n",
               r.triangles, r.vertices, r.genus, r.components);
  std::fprintf(out, "algorithm   %s%s%s\n", r.algorithm.c_str(),
               r.augment.empty() ? "" : ", augment ", r.augment.c_str());
  std::fprintf(out, "load        %.4f s\n", r.load_seconds);
  std::fprintf(out, "dual        %.4f s\n", r.dual_seconds);
  std::fprintf(out, "initial     %.4f s  paired %.4f %%  unpaired %" PRIu64 "\n", r.initial_seconds,
               r.initial_paired_percent(), r.unpaired_after_initial);
  std::fprintf(
      out, "augment     %.4f s  paths %" PRIu64 "  blossoms %" PRIu64 "  labelled %" PRIu64 "\n",
      r.augment_seconds, r.augmenting_paths, r.blossoms, r.nodes_labelled);
  if (r.reductions > 0) std::fprintf(out, "reductions  %" PRIu64 "\n", r.reductions);
  if (r.flipped_edges >= 0) {
    const std::uint64_t edges = r.triangles * 3 / 2;
    std::fprintf(out,
                 "flipped     %" PRId64 " of %" PRIu64
                 " edges (%.2f %%), irreducible triangulation %" PRId64 " vertices\n",
                 r.flipped_edges, edges, 100.0 * double(r.flipped_edges) / double(edges),
                 r.irreducible_vertices);
  }
  std::fprintf(out, "matching    %.4f s\n", r.matching_seconds());
  std::fprintf(out, "quads       %" PRIu64 " written to %s (%.4f s)\n", r.quads, r.output.c_str(),
               r.write_seconds);
  std::fprintf(out, "total       %.4f s\n", r.total_seconds);
}

void write_json(std::FILE* out, const RunReport& r) {
  std::fprintf(out, "{\n  \"input\": %s,\n  \"output\": %s,\n  \"algorithm\": %s,\n",
               json_string(r.input).c_str(), json_string(r.output).c_str(),
               json_string(r.algorithm).c_str());
  if (!r.augment.empty()) std::fprintf(out, "  \"augment\": %s,\n", json_string(r.augment).c_str());
  std::fprintf(out,
               "  \"vertices\": %" PRIu64 ",\n  \"triangles\": %" PRIu64 ",\n  \"genus\": %" PRId64
               ",\n  \"components\": %" PRIu64 ",\n",
               r.vertices, r.triangles, r.genus, r.components);
  std::fprintf(out, "  \"load_seconds\": %.9f,\n  \"dual_seconds\": %.9f,\n", r.load_seconds,
               r.dual_seconds);
  std::fprintf(out, "  \"initial_seconds\": %.9f,\n  \"initial_paired_percent\": %.6f,\n",
               r.initial_seconds, r.initial_paired_percent());
  std::fprintf(out, "  \"unpaired_after_initial\": %" PRIu64 ",\n  \"augment_seconds\": %.9f,\n",
               r.unpaired_after_initial, r.augment_seconds);
  std::fprintf(out, "  \"matching_seconds\": %.9f,\n", r.matching_seconds());
  std::fprintf(out,
               "  \"augmenting_paths\": %" PRIu64 ",\n  \"blossoms\": %" PRIu64
               ",\n  \"nodes_labelled\": %" PRIu64 ",\n",
               r.augmenting_paths, r.blossoms, r.nodes_labelled);
  std::fprintf(out, "  \"reductions\": %" PRIu64 ",\n", r.reductions);
  if (r.flipped_edges >= 0) {
    std::fprintf(out,
                 "  \"flipped_edges\": %" PRId64 ",\n  \"irreducible_vertices\": %" PRId64 ",\n",
                 r.flipped_edges, r.irreducible_vertices);
  }
  std::fprintf(
      out, "  \"quads\": %" PRIu64 ",\n  \"write_seconds\": %.9f,\n  \"total_seconds\": %.9f\n}\n",
      r.quads, r.write_seconds, r.total_seconds);
}

}  // namespace petersen::cli
