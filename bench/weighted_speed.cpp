// Exact minimum-cost perfect matching under the quad measure: petersen's certified solver
// against LEMON's MaxWeightedPerfectMatching on the same integer costs, beside PS with local
// augmentation (shape-blind, the cardinality floor), on the dual of each mesh.
// Usage: petersen_weighted_speed [--no-lemon] [--rounds N] [--threads N] [mesh files...]; without
// files it measures every shared mesh of at least 80k triangles from ../shared/meshes (when
// present). --rounds 1 runs the solver once per mesh (for a profiler; the default is 3);
// --threads is MinCostOptions::threads (default 0: every core, as the CLI).
// Columns: ours_s and ps_s are wall-time medians of the rounds, cpu_s that of the process's CPU
// time (cpu_min the least; every thread's, the short searches' helper included); xfaster =
// LEMON's wall time / ours, xcpu = LEMON's CPU time / ours, x_ps and xcpu_ps = ours / PS in wall
// and CPU time. LEMON and PS run on one thread. On a loaded machine the CPU ratios are the
// steadier ones: wall time adds whatever else ran.
// free0 is the number of nodes left free for the forest (after the greedy start and the short
// searches), labels the forest's labels, short_lab and short_aug the short searches' labels and
// augmentations, half_cyc the half-integral cycles they closed.

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "dual_costs.hpp"
#include "memory_pool.hpp"
#include "petersen/dualize/dual.hpp"
#include "petersen/dualize/quad_quality.hpp"
#include "petersen/graph/memory.hpp"
#include "petersen/io/read_mesh.hpp"
#include "petersen/lemon_peer/lemon_peer.hpp"
#include "petersen/matching/min_cost_matching.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "petersen/matching/verify_min_cost.hpp"

namespace {

using namespace petersen;

double seconds_of(const std::function<void()>& run) {
  const auto start = std::chrono::steady_clock::now();
  run();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// The process's CPU time (nothing else runs in it meanwhile): on the loaded machine, wall times
// of one program swing 2x between runs; CPU times swing less, so A/B comparisons of the solver
// read this column.
double cpu_seconds_of(const std::function<void()>& run) {
  timespec start, end;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &start);
  run();
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &end);
  return double(end.tv_sec - start.tv_sec) + 1e-9 * double(end.tv_nsec - start.tv_nsec);
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// The machine is shared: ours and PS run `rounds` times alternately and report medians; LEMON,
// far slower, runs once.
void measure(const std::string& name, const PolygonMesh& mesh, bool with_lemon, int rounds,
             std::uint32_t threads) {
  const Dual dual = build_dual(mesh);
  const CubicGraph& g = dual.graph;
  const std::pmr::vector<double> degrees = bench::dual_edge_costs(mesh, dual);
  const std::pmr::vector<Cost> costs = scale_costs(degrees);
  std::vector<double> ours, ours_cpu, ps, ps_cpu;
  MinCostResult result;
  for (int round = 0; round < rounds; ++round) {
    ours.push_back(seconds_of([&] {
      ours_cpu.push_back(cpu_seconds_of(
          [&] { result = min_cost_perfect_matching(g, costs, {.threads = threads}); }));
    }));
    ps.push_back(seconds_of([&] {
      ps_cpu.push_back(cpu_seconds_of([&] {
        perfect_matching(
            g, {.algorithm = Algorithm::automatic, .augment = Augment::local, .validate = false});
      }));
    }));
  }
  CertificateCheck check;
  const double verify_seconds = seconds_of([&] {
    check = verify_min_cost_perfect_matching(g.node_count(), g.edge_ends(), costs, result.matching,
                                             result.total_cost, result.certificate);
  });
  if (!check.ok()) {
    std::printf("%s: CERTIFICATE REJECTED: %s\n", name.c_str(), check.problem.c_str());
    std::exit(1);
  }
  double lemon_seconds = 0, lemon_cpu = 0;
  std::int64_t lemon_total = 0;
  if (with_lemon) {
    std::vector<std::uint32_t> mate(g.node_count());
    lemon_seconds = seconds_of([&] {
      lemon_cpu = cpu_seconds_of([&] {
        if (!lemon_peer::min_cost_perfect_matching(g.node_count(), g.edge_ends().data(),
                                                   g.edge_count(), costs.data(), mate.data(),
                                                   lemon_total)) {
          std::printf("%s: LEMON found no perfect matching\n", name.c_str());
          std::exit(1);
        }
      });
    });
    if (lemon_total != result.total_cost) {
      std::printf("%s: OPTIMA DIFFER: ours %lld, LEMON %lld\n", name.c_str(),
                  (long long)result.total_cost, (long long)lemon_total);
      std::exit(1);
    }
  }
  const MinCostStats& s = result.stats;
  const double t = median(ours), t_ps = median(ps), cpu = median(ours_cpu);
  std::printf(
      "%-24s %9u %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %8.3f %7.1f %7.1f %7.3f %7.1f %7.1f %8.2f "
      "%7u %8llu %8llu %9llu %9llu %9llu %9llu %8llu %8llu\n",
      name.c_str(), g.node_count(), t, cpu, *std::min_element(ours_cpu.begin(), ours_cpu.end()),
      s.init_seconds, s.search_seconds, verify_seconds, lemon_seconds, lemon_seconds / t,
      lemon_cpu / cpu, t_ps, t / t_ps, cpu / median(ps_cpu),
      double(result.total_cost) / kDefaultCostScale / (g.node_count() / 2), s.free_after_init,
      (unsigned long long)s.blossoms_shrunk, (unsigned long long)s.queue_pushes,
      (unsigned long long)s.nodes_labelled, (unsigned long long)s.even_scans,
      (unsigned long long)s.released_scans, (unsigned long long)s.short_labels,
      (unsigned long long)s.short_augmentations, (unsigned long long)s.short_half_cycles);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  // As the CLI does: the rounds after the first reuse the memory the first one released.
  petersen::bench::install_memory_pool();
  std::vector<std::string> files;
  bool with_lemon = true;
  int rounds = 3;
  std::uint32_t threads = 0;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (arg == "--no-lemon") {
      with_lemon = false;
    } else if (arg == "--rounds" && i + 1 < argc) {
      rounds = std::atoi(argv[++i]);
      if (rounds < 1) {
        std::fprintf(stderr, "--rounds needs a positive count\n");
        return 2;
      }
    } else if (arg == "--threads" && i + 1 < argc) {
      threads = static_cast<std::uint32_t>(std::atoi(argv[++i]));
    } else if (arg.starts_with("--")) {
      std::fprintf(stderr,
                   "usage: petersen_weighted_speed [--no-lemon] [--rounds N] [--threads N] "
                   "[mesh files...]\n");
      return 2;
    } else {
      files.push_back(arg);
    }
  }
  if (files.empty()) {
    for (const char* mesh : {"armadillo.obj.gz", "nefertiti.obj.gz", "fertility-sub3.ply.gz",
                             "rocker-arm-sub3.ply.gz", "armadillo-sub2.ply.gz"}) {
      const std::string path = std::string(PETERSEN_SHARED_MESHES) + "/" + mesh;
      if (std::filesystem::exists(path)) files.push_back(path);
    }
  }
  std::printf(
      "%-24s %9s %8s %8s %8s %8s %8s %8s %8s %7s %7s %7s %7s %7s %8s %7s %8s %8s %9s %9s %9s %9s "
      "%8s %8s\n",
      "mesh", "nodes", "ours_s", "cpu_s", "cpu_min", "init_s", "search_s", "verify_s", "lemon_s",
      "xfaster", "xcpu", "ps_s", "x_ps", "xcpu_ps", "mean_deg", "free0", "blossoms", "pushes",
      "labels", "even_scan", "rel_scan", "short_lab", "short_aug", "half_cyc");
  for (const std::string& file : files) {
    measure(std::filesystem::path(file).filename().string(), read_mesh(file), with_lemon, rounds,
            threads);
  }
}
