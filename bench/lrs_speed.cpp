// LRS speed (paper §3.3–3.4): contraction and expansion are linear at genus 0.
// Usage: petersen_lrs_speed [mesh files...]. Without files it runs a doubling series of genus-0
// voxel plates with dents (the paper's family A) up to past 4M triangles, then the shared
// armadillo-sub2 (1.38M triangles, genus 0) beside PS on the same dual when ../shared/meshes is
// present.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "memory_pool.hpp"
#include "petersen/dualize/dual.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/lrs/lrs.hpp"
#include "petersen/matching/perfect_matching.hpp"

namespace {

using namespace petersen;

// The run with the smallest pairing time of `runs` (the least disturbed by other processes).
LrsStats best_of(const PolygonMesh& mesh, int runs) {
  LrsStats best;
  for (int r = 0; r < runs; ++r) {
    const LrsStats s = pair_closed_component_by_lrs(mesh).stats;
    if (r == 0 || s.matching_seconds() < best.matching_seconds()) best = s;
  }
  return best;
}

void print_header() {
  std::printf("%-26s %9s %5s %6s %4s %8s %8s %8s %8s %8s %7s %7s %6s\n", "mesh", "F", "genus",
              "|T'|", "l", "contr s", "expand s", "augm s", "pair s", "total s", "ns/F c", "ns/F e",
              "flip%");
}

void print_row(const std::string& name, const LrsStats& s) {
  std::printf("%-26s %9u %5u %6u %4u %8.3f %8.3f %8.3f %8.3f %8.3f %7.1f %7.1f %6.2f\n",
              name.c_str(), s.faces, s.genus, s.irreducible_vertices, s.unpaired_after_expansion,
              s.contraction_seconds, s.expansion_seconds, s.augment_seconds, s.matching_seconds(),
              s.total_seconds, 1e9 * s.contraction_seconds / s.faces,
              1e9 * s.expansion_seconds / s.faces, s.flipped_percent());
}

void compare_with_ps(const std::string& name, const PolygonMesh& mesh) {
  const LrsStats lrs = best_of(mesh, 3);
  print_row(name, lrs);
  const CubicGraph dual = dual_graph(mesh);
  double ps_best = 0;
  for (int r = 0; r < 3; ++r) {
    const PerfectMatchingStats ps =
        perfect_matching(dual, {.algorithm = Algorithm::automatic}).stats;
    if (r == 0 || ps.matching_seconds() < ps_best) ps_best = ps.matching_seconds();
  }
  std::printf(
      "  LRS pairing %.3f s (contraction %.3f + expansion %.3f + augmentation %.3f); "
      "PS + local augmentation %.3f s on the prebuilt dual: LRS/PS = %.2f\n",
      lrs.matching_seconds(), lrs.contraction_seconds, lrs.expansion_seconds, lrs.augment_seconds,
      ps_best, lrs.matching_seconds() / ps_best);
  std::printf("  setup (surface check + halfedges) %.3f s, quads %.3f s\n", lrs.setup_seconds,
              lrs.quads_seconds);
}

}  // namespace

int main(int argc, char** argv) {
  petersen::bench::install_memory_pool();
  print_header();
  if (argc > 1) {
    for (int i = 1; i < argc; ++i) compare_with_ps(argv[i], read_mesh(argv[i]));
    return 0;
  }
  // Doubling series: the plate grows by doubling holes_x and holes_y in turn.
  PlateSpec spec{.holes_x = 8, .holes_y = 8, .subdivision = 4, .dents = true};
  for (int step = 0;; ++step) {
    const PolygonMesh mesh = voxel_plate(spec);
    const LrsStats s = best_of(mesh, mesh.face_count() > 2000000 ? 1 : 3);
    print_row("plate " + std::to_string(spec.holes_x) + "x" + std::to_string(spec.holes_y) +
                  " sub" + std::to_string(spec.subdivision),
              s);
    if (s.faces > 4000000) break;
    (step % 2 == 0 ? spec.holes_x : spec.holes_y) *= 2;
  }
  const std::string armadillo = std::string(PETERSEN_SHARED_MESHES) + "/armadillo-sub2.ply.gz";
  if (std::filesystem::exists(armadillo)) {
    compare_with_ps("armadillo-sub2", read_mesh(armadillo));
  }
  return 0;
}
