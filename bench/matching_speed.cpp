// Matching speed of SG and PS (paper §3.1) with both augmentation variants, beside one plain BFS
// over the same graph (the floor) and LEMON's MaxMatching (the peer).
// Usage: petersen_matching_speed [mesh files...]; without files it measures the dual of
// armadillo-sub2 from ../shared/meshes (when present), of a voxel plate with 30×30 holes, and a
// random cubic bridgeless graph of 1.4M nodes.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "bfs_floor.hpp"
#include "memory_pool.hpp"
#include "petersen/dualize/dual.hpp"
#include "petersen/generators/graph_generators.hpp"
#include "petersen/generators/surface_generators.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/lemon_peer/lemon_peer.hpp"
#include "petersen/matching/perfect_matching.hpp"

namespace {

using namespace petersen;

// Faithful SG resets all n nodes for each of its ~6 % n searches: estimate it past this many
// node-resets (about a minute).
constexpr double kFaithfulBudget = 2e10;

double seconds_of(const std::function<void()>& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

PerfectMatchingResult run_checked(const CubicGraph& g, Algorithm algorithm, Augment augment) {
  PerfectMatchingResult r = perfect_matching(
      g, {.algorithm = algorithm, .augment = augment, .seed = 1, .validate = false});
  if (!verify_perfect_matching(g, r.matching).ok()) {
    std::printf("%s+%s: NOT PERFECT\n", std::string(to_string(algorithm)).c_str(),
                std::string(to_string(augment)).c_str());
    std::exit(1);
  }
  return r;
}

void print_row(const std::string& label, const PerfectMatchingStats& s, double seconds,
               double x_bfs, std::uint32_t n) {
  std::printf("%-14s %9.4f %9.4f %9.4f %9.2f %8u %9.4f %9llu %8llu\n", label.c_str(),
              s.initial_seconds, s.augment_seconds, seconds, x_bfs, s.unpaired_after_initial,
              s.paired_percent(n), (unsigned long long)s.nodes_labelled,
              (unsigned long long)s.blossoms);
}

// The machine is shared, so timings drift: every round runs the BFS and then each local variant,
// each variant's time is taken relative to the BFS of its own round, and the medians over the
// rounds are reported. Faithful runs once (it takes far longer than the drift), or, past the
// budget, is estimated from its measured cost per search on the same graph from the PS start.
void measure(const std::string& name, const CubicGraph& g) {
  constexpr int kRounds = 5;
  const std::uint32_t n = g.node_count();
  std::printf("\n== %s: %u nodes\n", name.c_str(), n);
  constexpr Algorithm kGreedy[] = {Algorithm::automatic, Algorithm::sg};
  std::vector<double> bfs;
  std::vector<double> seconds[2], ratio[2], initial[2], augment[2];
  PerfectMatchingResult local[2];
  for (int round = 0; round < kRounds; ++round) {
    bfs.push_back(seconds_of([&] { petersen::bench::bfs_floor(g); }));
    for (int a = 0; a < 2; ++a) {
      local[a] = run_checked(g, kGreedy[a], Augment::local);
      seconds[a].push_back(local[a].stats.matching_seconds());
      initial[a].push_back(local[a].stats.initial_seconds);
      augment[a].push_back(local[a].stats.augment_seconds);
      ratio[a].push_back(seconds[a].back() / bfs.back());
    }
  }
  const double bfs_median = median(bfs);
  std::printf("%-14s %9.4f s (median of %d, each round beside the variants)\n", "BFS", bfs_median,
              kRounds);
  std::printf("%-14s %9s %9s %9s %9s %8s %9s %9s %8s\n", "algorithm", "initial", "augment", "total",
              "xBFS", "unpaired", "paired%", "labelled", "blossoms");
  double faithful_per_search = 0;
  for (int a = 0; a < 2; ++a) {
    const std::string algorithm(to_string(kGreedy[a]));
    PerfectMatchingStats medians = local[a].stats;
    medians.initial_seconds = median(initial[a]);
    medians.augment_seconds = median(augment[a]);
    print_row(algorithm + "+local", medians, median(seconds[a]), median(ratio[a]), n);
    const std::uint32_t unpaired = local[a].stats.unpaired_after_initial;
    double faithful_seconds = 0;
    if (0.5 * unpaired * double(n) <= kFaithfulBudget) {
      const PerfectMatchingResult r = run_checked(g, kGreedy[a], Augment::faithful);
      faithful_seconds = r.stats.matching_seconds();
      if (r.stats.augmenting_paths > 0)
        faithful_per_search = r.stats.augment_seconds / double(r.stats.augmenting_paths);
      print_row(algorithm + "+faithful", r.stats, faithful_seconds, faithful_seconds / bfs_median,
                n);
    } else if (faithful_per_search == 0) {
      // PS left nothing to search (Schrijver matched a bipartite graph): no cost to scale from.
      std::printf("%-14s not run and not estimated: no PS search was timed on this graph\n",
                  (algorithm + "+faithful").c_str());
      continue;
    } else {
      faithful_seconds = local[a].stats.initial_seconds +
                         faithful_per_search * double(local[a].stats.augmenting_paths);
      std::printf("%-14s %9s %9s %9.1f %9.0f  estimated: %llu searches x %.4f s per search\n",
                  (algorithm + "+faithful").c_str(), "", "", faithful_seconds,
                  faithful_seconds / bfs_median,
                  (unsigned long long)local[a].stats.augmenting_paths, faithful_per_search);
    }
    std::printf("%-14s local is %.0fx faster than faithful\n", "",
                faithful_seconds / median(seconds[a]));
  }
  Matching lemon(g.node_count());
  const double lemon_seconds = seconds_of([&] {
    lemon_peer::maximum_matching(g.node_count(), g.edge_ends().data(), g.edge_count(),
                                 lemon.mate_edge.data());
  });
  std::printf("%-14s %9.4f %9s %9.4f %9.2f   (PS+local %.1fx faster, SG+local %.1fx faster)\n",
              "lemon", lemon_seconds, "", lemon_seconds, lemon_seconds / bfs_median,
              lemon_seconds / median(seconds[0]), lemon_seconds / median(seconds[1]));
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  petersen::bench::install_memory_pool();
  std::vector<std::string> files(argv + 1, argv + argc);
  const bool defaults = files.empty();
  if (defaults) {
    const std::string armadillo = PETERSEN_SHARED_MESHES "/armadillo-sub2.ply.gz";
    if (std::filesystem::exists(armadillo)) files.push_back(armadillo);
  }
  for (const std::string& file : files) {
    measure(std::filesystem::path(file).filename().string(), dual_graph(read_mesh(file)));
  }
  if (defaults) {
    measure("voxel_plate 30x30 holes, subdivision 13",
            dual_graph(voxel_plate({.holes_x = 30, .holes_y = 30, .subdivision = 13})));
    measure("random_cubic_bridgeless(1.4M)", random_cubic_bridgeless(1'400'000, 1));
  }
}
