#pragma once
// The summary of one `petersen quad` run, printed for people and written as JSON for scripts.

#include <cstdint>
#include <cstdio>
#include <string>

namespace petersen::cli {

struct RunReport {
  std::string input, output, algorithm;
  std::string augment;  ///< augmenting-path variant, for the algorithms that augment
  std::uint64_t vertices = 0, triangles = 0, components = 0;
  std::int64_t genus = 0;
  double load_seconds = 0, dual_seconds = 0, initial_seconds = 0, augment_seconds = 0;
  double write_seconds = 0, total_seconds = 0;
  std::uint64_t unpaired_after_initial = 0, augmenting_paths = 0, blossoms = 0;
  std::uint64_t nodes_labelled = 0, reductions = 0, quads = 0;
  // LRS only: edges flipped in the expansion step and vertices of the irreducible triangulation.
  std::int64_t flipped_edges = -1, irreducible_vertices = -1;

  double matching_seconds() const { return initial_seconds + augment_seconds; }
  double initial_paired_percent() const {
    return triangles == 0 ? 100.0
                          : 100.0 * double(triangles - unpaired_after_initial) / double(triangles);
  }
};

void print_summary(std::FILE* out, const RunReport& report);
void write_json(std::FILE* out, const RunReport& report);

}  // namespace petersen::cli
