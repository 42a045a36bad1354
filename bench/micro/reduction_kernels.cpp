// Micro-benchmarks of Frink's reductions (paper §3.2, Appendix A) with the ds and gw choosers:
// a whole run, reported per reduction. A chooser this build lacks is skipped with its message.

#include <benchmark/benchmark.h>

#include <stdexcept>

#include "micro_inputs.hpp"
#include "petersen/matching/perfect_matching.hpp"

namespace petersen::micro {

namespace {

void reductions(benchmark::State& state, Algorithm chooser) {
  const CubicGraph& graph = plate_input(static_cast<std::uint64_t>(state.range(0))).dual.graph;
  double count = 0;
  for (auto _ : state) {
    try {
      const PerfectMatchingResult result =
          perfect_matching(graph, {.algorithm = chooser, .validate = false});
      state.SetIterationTime(result.stats.initial_seconds);
      count += double(result.stats.reductions);
    } catch (const std::invalid_argument& e) {
      state.SkipWithError(e.what());
      return;
    }
  }
  // Seconds per reduction, averaged over the run (inverted rate).
  state.counters["per_reduction"] =
      benchmark::Counter(count, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

void BM_ReductionsDS(benchmark::State& state) {
  reductions(state, Algorithm::ds);
}
void BM_ReductionsGW(benchmark::State& state) {
  reductions(state, Algorithm::gw);
}
BENCHMARK(BM_ReductionsDS)
    ->RangeMultiplier(4)
    ->Range(1 << 12, 1 << 16)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReductionsGW)
    ->RangeMultiplier(4)
    ->Range(1 << 12, 1 << 16)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace

}  // namespace petersen::micro
