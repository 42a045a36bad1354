// Frink's reductions (paper §3.2) with the ds and gw choosers on doubling series of random cubic
// graphs and voxel-plate duals, printing time / (n log² n) and time / (n log n) so the growth
// can be read off; an optional mesh file is timed too.
//
// Usage: petersen_reduction_speed [min_nodes=65536] [max_nodes=4194304] [mesh files...]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "petersen/dualize/dual.hpp"
#include "petersen/dualize/read_mesh.hpp"
#include "petersen/dualize/surface_generators.hpp"
#include "petersen/graph/generators.hpp"
#include "petersen/matching/avoiding.hpp"

namespace {

using namespace petersen;

void measure(const char* family, const CubicGraph& g, Algorithm chooser) {
  const ReductionResult r = perfect_matching_avoiding(g, kNoEdge, {.chooser = chooser});
  if (!verify_perfect_matching(g, r.matching).ok()) {
    std::fprintf(stderr, "%s %s: not a perfect matching\n", family,
                 std::string(to_string(chooser)).c_str());
    std::exit(1);
  }
  const double n = g.node_count(), lg = std::log2(n);
  const double t = r.stats.setup_seconds + r.stats.reduce_seconds + r.stats.lift_seconds;
  std::printf(
      "%-8s %-3s %9.0f %8.3f s (setup %.3f, reduce %.3f, lift %.3f)  %7.2f ns/(n lg2 n)"
      "  %7.2f ns/(n lg n)  searches %llu\n",
      family, std::string(to_string(chooser)).c_str(), n, t, r.stats.setup_seconds,
      r.stats.reduce_seconds, r.stats.lift_seconds, 1e9 * t / (n * lg * lg), 1e9 * t / (n * lg),
      static_cast<unsigned long long>(r.stats.replacement_searches));
  std::fflush(stdout);
}

// The dual of a square voxel plate with about n triangles (genus = holes², the paper's family B).
CubicGraph plate_dual_near(std::uint32_t n) {
  const double per_hole =
      voxel_plate({.holes_x = 8, .holes_y = 8}).triangles.size() / 64.0;  // triangles per hole
  const auto holes = static_cast<std::uint32_t>(std::max(1.0, std::sqrt(n / per_hole)));
  return dual_graph(voxel_plate({.holes_x = holes, .holes_y = holes}));
}

}  // namespace

int main(int argc, char** argv) {
  const std::uint32_t lo = argc > 1 ? std::stoul(argv[1]) : 65536;
  const std::uint32_t hi = argc > 2 ? std::stoul(argv[2]) : 4194304;
  const Algorithm choosers[] = {Algorithm::ds, Algorithm::gw};
  for (std::uint32_t n = lo; n <= hi; n *= 2) {
    const CubicGraph random = random_cubic_bridgeless(n, n);
    const CubicGraph plate = plate_dual_near(n);
    for (Algorithm chooser : choosers) {
      try {
        measure("random", random, chooser);
        measure("plate", plate, chooser);
      } catch (const std::invalid_argument& e) {
        std::printf("%s\n", e.what());
      }
    }
  }
  for (int i = 3; i < argc; ++i) {
    const CubicGraph g = dual_graph(read_triangle_mesh(argv[i]));
    for (Algorithm chooser : choosers) {
      try {
        measure(argv[i], g, chooser);
      } catch (const std::invalid_argument& e) {
        std::printf("%s\n", e.what());
      }
    }
  }
}
