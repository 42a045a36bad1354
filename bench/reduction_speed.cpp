// Frink's reductions (paper §3.2) with the ds and gw choosers on a doubling series of voxel-plate
// duals (and random cubic graphs with --random), printing time / (n log² n) and time / (n log n)
// so the growth can be read off; mesh files given on the command line are timed too.
//
// Usage: petersen_reduction_speed [--choosers ds,gw] [--ds-max N] [--random]
//                                 [min_nodes=65536] [max_nodes=4194304] [mesh files...]
// --ds-max caps the series for ds (default 2^21: larger ds runs take minutes).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "memory_pool.hpp"
#include "petersen/dualize/dual.hpp"
#include "petersen/generators/graph_generators.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/matching/avoiding.hpp"

namespace {

using namespace petersen;

void measure(const std::string& family, const CubicGraph& g, ReductionChooser chooser) {
  const ReductionResult r = perfect_matching_avoiding(g, kNoEdge, {.chooser = chooser});
  if (!verify_perfect_matching(g, r.matching).ok()) {
    std::fprintf(stderr, "%s %s: not a perfect matching\n", family.c_str(),
                 std::string(to_string(chooser)).c_str());
    std::exit(1);
  }
  const double n = g.node_count(), lg = std::log2(n);
  const double t = r.stats.setup_seconds + r.stats.reduce_seconds + r.stats.lift_seconds;
  std::printf(
      "%-8s %-3s %9.0f %8.3f s (setup %.3f, reduce %.3f, lift %.3f)  %7.2f ns/(n lg2 n)"
      "  %7.2f ns/(n lg n)  searches/swaps %llu\n",
      family.c_str(), std::string(to_string(chooser)).c_str(), n, t, r.stats.setup_seconds,
      r.stats.reduce_seconds, r.stats.lift_seconds, 1e9 * t / (n * lg * lg), 1e9 * t / (n * lg),
      static_cast<unsigned long long>(r.stats.replacement_searches + r.stats.cover_swaps));
  std::fflush(stdout);
}

// The dual of a square voxel plate with about n triangles (genus = holes², the paper's family B).
CubicGraph plate_dual_near(std::uint32_t n) {
  const double per_hole =
      voxel_plate({.holes_x = 8, .holes_y = 8}).face_count() / 64.0;  // triangles per hole
  const auto holes = static_cast<std::uint32_t>(std::max(1.0, std::sqrt(n / per_hole)));
  return dual_graph(voxel_plate({.holes_x = holes, .holes_y = holes}));
}

}  // namespace

int main(int argc, char** argv) {
  petersen::bench::install_memory_pool();
  std::vector<ReductionChooser> choosers = {ReductionChooser::ds, ReductionChooser::gw};
  std::uint32_t ds_max = 1u << 21;
  bool random = false;
  std::vector<std::string> positional;
  for (int i = 1; i < argc; ++i) {
    const std::string_view arg = argv[i];
    if (arg == "--choosers" && i + 1 < argc) {
      choosers.clear();
      for (std::string_view list = argv[++i]; !list.empty();) {
        const std::size_t comma = std::min(list.find(','), list.size());
        const auto a = parse_reduction_chooser(list.substr(0, comma));
        if (!a) {
          std::fprintf(stderr, "unknown chooser in %s\n", argv[i]);
          return 2;
        }
        choosers.push_back(*a);
        list.remove_prefix(std::min(comma + 1, list.size()));
      }
    } else if (arg == "--ds-max" && i + 1 < argc) {
      ds_max = static_cast<std::uint32_t>(std::stoul(argv[++i]));
    } else if (arg == "--random") {
      random = true;
    } else {
      positional.emplace_back(arg);
    }
  }
  const std::uint32_t lo = positional.size() > 0 ? std::stoul(positional[0]) : 65536;
  const std::uint32_t hi = positional.size() > 1 ? std::stoul(positional[1]) : 4194304;
  for (std::uint64_t n = lo; n <= hi; n *= 2) {
    const CubicGraph plate = plate_dual_near(static_cast<std::uint32_t>(n));
    for (ReductionChooser chooser : choosers)
      if (chooser != ReductionChooser::ds || plate.node_count() <= ds_max)
        measure("plate", plate, chooser);
    if (!random) continue;
    const CubicGraph graph = random_cubic_bridgeless(static_cast<std::uint32_t>(n), n);
    for (ReductionChooser chooser : choosers)
      if (chooser != ReductionChooser::ds || n <= ds_max) measure("random", graph, chooser);
  }
  for (std::size_t i = 2; i < positional.size(); ++i) {
    const CubicGraph g = dual_graph(read_mesh(positional[i]));
    for (ReductionChooser chooser : choosers) measure(positional[i], g, chooser);
  }
}
