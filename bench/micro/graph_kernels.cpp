// Micro-benchmarks of the graph kernels every algorithm pays for: the dual build and one BFS.

#include <benchmark/benchmark.h>

#include <vector>

#include "bfs_floor.hpp"
#include "micro_inputs.hpp"

namespace petersen::micro {

namespace {

void BM_DualBuild(benchmark::State& state) {
  const MicroInput& input = plate_input(static_cast<std::uint64_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(build_dual(input.mesh));
  state.SetItemsProcessed(state.iterations() * std::int64_t(input.mesh.face_count()));
}
BENCHMARK(BM_DualBuild)->RangeMultiplier(4)->Range(1 << 14, 1 << 20)->Unit(benchmark::kMillisecond);

// The floor of the bench (bfs_floor.hpp).
void BM_Bfs(benchmark::State& state) {
  const CubicGraph& graph = plate_input(static_cast<std::uint64_t>(state.range(0))).dual.graph;
  for (auto _ : state) benchmark::DoNotOptimize(petersen::bench::bfs_floor(graph));
  state.SetItemsProcessed(state.iterations() * std::int64_t(graph.node_count()));
}
BENCHMARK(BM_Bfs)->RangeMultiplier(4)->Range(1 << 14, 1 << 20)->Unit(benchmark::kMillisecond);

}  // namespace

}  // namespace petersen::micro
