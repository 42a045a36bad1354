// Matching speed of SG and PS (paper §3.1) with both augmentation variants, beside one plain BFS
// over the same graph (the floor) and LEMON's MaxMatching (the peer), for issue 3.
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

#include "petersen/dualize/dual.hpp"
#include "petersen/dualize/read_mesh.hpp"
#include "petersen/dualize/surface_generators.hpp"
#include "petersen/graph/generators.hpp"
#include "petersen/matching/perfect_matching.hpp"

namespace {

using namespace petersen;

// Faithful SG resets all n nodes for each of its ~6 % n searches: skip it past this many
// node-resets (about a minute).
constexpr double kFaithfulBudget = 2e10;

double seconds_of(const std::function<void()>& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Breadth-first search from every unvisited node: visits all nodes and edges once.
std::uint32_t plain_bfs(const CubicGraph& g, std::vector<NodeId>& queue,
                        std::vector<std::uint8_t>& seen) {
  std::fill(seen.begin(), seen.end(), 0);
  queue.clear();
  std::uint32_t components = 0;
  for (NodeId s = 0; s < g.node_count(); ++s) {
    if (seen[s]) continue;
    ++components;
    seen[s] = 1;
    queue.push_back(s);
    for (std::size_t head = queue.size() - 1; head < queue.size(); ++head) {
      const NodeId v = queue[head];
      for (EdgeId e : g.incident_edges(v)) {
        const NodeId u = g.other_end(e, v);
        if (!seen[u]) {
          seen[u] = 1;
          queue.push_back(u);
        }
      }
    }
  }
  return components;
}

void measure(const std::string& name, const CubicGraph& g) {
  std::printf("\n== %s: %u nodes\n", name.c_str(), g.node_count());
  std::vector<NodeId> queue;
  queue.reserve(g.node_count());
  std::vector<std::uint8_t> seen(g.node_count());
  double bfs = 1e30;
  for (int i = 0; i < 5; ++i) bfs = std::min(bfs, seconds_of([&] { plain_bfs(g, queue, seen); }));
  std::printf("%-14s %9.4f s\n", "BFS", bfs);
  std::printf("%-14s %9s %9s %9s %9s %8s %9s %9s %8s\n", "algorithm", "initial", "augment", "total",
              "xBFS", "unpaired", "paired%", "labelled", "blossoms");
  for (Algorithm algorithm : {Algorithm::ps, Algorithm::sg}) {
    std::uint32_t unpaired = 0;
    for (Augment augment : {Augment::local, Augment::faithful}) {
      const std::string label =
          std::string(to_string(algorithm)) + "+" + std::string(to_string(augment));
      if (augment == Augment::faithful &&
          0.5 * unpaired * double(g.node_count()) > kFaithfulBudget) {
        std::printf("%-14s skipped: %u searches × %u-node resets exceed the budget\n",
                    label.c_str(), unpaired / 2, g.node_count());
        continue;
      }
      Result best;
      best.stats.initial_seconds = 1e30;
      for (int i = 0; i < (augment == Augment::local ? 3 : 1); ++i) {
        Result r = perfect_matching(
            g, {.algorithm = algorithm, .augment = augment, .seed = 1, .validate = false});
        if (!verify_perfect_matching(g, r.matching).ok()) {
          std::printf("%s: NOT PERFECT\n", label.c_str());
          std::exit(1);
        }
        if (r.stats.matching_seconds() < best.stats.matching_seconds()) best = std::move(r);
      }
      const Stats& s = best.stats;
      unpaired = s.unpaired_after_initial;
      std::printf("%-14s %9.4f %9.4f %9.4f %9.2f %8u %9.4f %9llu %8llu\n", label.c_str(),
                  s.initial_seconds, s.augment_seconds, s.matching_seconds(),
                  s.matching_seconds() / bfs, s.unpaired_after_initial,
                  s.paired_percent(g.node_count()), (unsigned long long)s.nodes_labelled,
                  (unsigned long long)s.blossoms);
    }
  }
  Result lemon = perfect_matching(g, {.algorithm = Algorithm::lemon, .validate = false});
  std::printf("%-14s %9.4f %9s %9.4f %9.2f\n", "lemon", lemon.stats.initial_seconds, "",
              lemon.stats.matching_seconds(), lemon.stats.matching_seconds() / bfs);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> files(argv + 1, argv + argc);
  const bool defaults = files.empty();
  if (defaults) {
    const std::string armadillo = PETERSEN_SHARED_MESHES "/armadillo-sub2.ply.gz";
    if (std::filesystem::exists(armadillo)) files.push_back(armadillo);
  }
  for (const std::string& file : files) {
    measure(std::filesystem::path(file).filename().string(), dual_graph(read_triangle_mesh(file)));
  }
  if (defaults) {
    measure("voxel_plate 30x30 holes, subdivision 13",
            dual_graph(voxel_plate({.holes_x = 30, .holes_y = 30, .subdivision = 13})));
    measure("random_cubic_bridgeless(1.4M)", random_cubic_bridgeless(1'400'000, 1));
  }
}
