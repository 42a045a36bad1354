// Micro-benchmarks of LRS's topological operators (paper §3.3): the contraction step down to an
// irreducible triangulation, and undoing it with vertex splits; per operation.

#include <benchmark/benchmark.h>

#include "contraction_step.hpp"
#include "micro_inputs.hpp"

namespace petersen::micro {

namespace {

void BM_LrsContraction(benchmark::State& state) {
  const PolygonMesh mesh = plate_input(static_cast<std::uint64_t>(state.range(0))).mesh;
  double contractions = 0;
  for (auto _ : state) {
    state.PauseTiming();
    lrs::Triangulation tri = lrs::Triangulation::from_mesh(mesh);
    state.ResumeTiming();
    contractions += double(lrs::contract_to_irreducible(tri).stack.size());
  }
  state.counters["per_contraction"] =
      benchmark::Counter(contractions, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_LrsContraction)
    ->RangeMultiplier(4)
    ->Range(1 << 14, 1 << 20)
    ->Unit(benchmark::kMillisecond);

void BM_LrsSplit(benchmark::State& state) {
  const PolygonMesh mesh = plate_input(static_cast<std::uint64_t>(state.range(0))).mesh;
  double splits = 0;
  for (auto _ : state) {
    state.PauseTiming();
    lrs::Triangulation tri = lrs::Triangulation::from_mesh(mesh);
    const lrs::ContractionResult contracted = lrs::contract_to_irreducible(tri);
    state.ResumeTiming();
    for (auto it = contracted.stack.rbegin(); it != contracted.stack.rend(); ++it)
      lrs::split(tri, *it);
    splits += double(contracted.stack.size());
  }
  state.counters["per_split"] =
      benchmark::Counter(splits, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_LrsSplit)->RangeMultiplier(4)->Range(1 << 14, 1 << 20)->Unit(benchmark::kMillisecond);

}  // namespace

}  // namespace petersen::micro
