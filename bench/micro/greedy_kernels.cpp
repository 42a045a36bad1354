// Micro-benchmarks of the greedy initial pairings SG and PS (paper §3.1), and of auto's pairing in
// PS's place (on these plates, in their generator's local order, the ordered sweep). They run
// through the front door; only the initial pairing's own time
// (PerfectMatchingStats::initial_seconds) is reported.

#include <benchmark/benchmark.h>

#include "micro_inputs.hpp"
#include "petersen/matching/perfect_matching.hpp"

namespace petersen::micro {

namespace {

void greedy(benchmark::State& state, Algorithm algorithm) {
  const CubicGraph& graph = plate_input(static_cast<std::uint64_t>(state.range(0))).dual.graph;
  std::uint64_t seed = 1;
  double unpaired = 0;
  for (auto _ : state) {
    const PerfectMatchingResult result =
        perfect_matching(graph, {.algorithm = algorithm, .seed = seed++, .validate = false});
    state.SetIterationTime(result.stats.initial_seconds);
    unpaired += result.stats.unpaired_after_initial;
  }
  state.counters["unpaired"] = benchmark::Counter(unpaired, benchmark::Counter::kAvgIterations);
  state.SetItemsProcessed(state.iterations() * std::int64_t(graph.node_count()));
}

void BM_GreedySG(benchmark::State& state) {
  greedy(state, Algorithm::sg);
}
void BM_GreedyPS(benchmark::State& state) {
  greedy(state, Algorithm::ps);
}
void BM_GreedyAuto(benchmark::State& state) {
  greedy(state, Algorithm::automatic);
}
BENCHMARK(BM_GreedySG)
    ->RangeMultiplier(4)
    ->Range(1 << 14, 1 << 20)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GreedyPS)
    ->RangeMultiplier(4)
    ->Range(1 << 14, 1 << 20)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_GreedyAuto)
    ->RangeMultiplier(4)
    ->Range(1 << 14, 1 << 20)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

}  // namespace petersen::micro
