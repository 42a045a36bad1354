// Micro-benchmarks of the graph kernels every algorithm pays for: the dual build and one BFS.

#include <benchmark/benchmark.h>

#include <vector>

#include "micro_inputs.hpp"

namespace petersen::micro {

namespace {

void BM_DualBuild(benchmark::State& state) {
  const MicroInput& input = plate_input(static_cast<std::uint64_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(build_dual(input.mesh));
  state.SetItemsProcessed(state.iterations() * std::int64_t(input.mesh.triangles.size()));
}
BENCHMARK(BM_DualBuild)->RangeMultiplier(4)->Range(1 << 14, 1 << 20)->Unit(benchmark::kMillisecond);

// The floor of the bench: one plain breadth-first search over the dual graph.
void BM_Bfs(benchmark::State& state) {
  const CubicGraph& graph = plate_input(static_cast<std::uint64_t>(state.range(0))).dual.graph;
  std::vector<std::uint8_t> seen(graph.node_count());
  std::vector<NodeId> queue(graph.node_count());
  for (auto _ : state) {
    std::fill(seen.begin(), seen.end(), 0);
    std::size_t head = 0, tail = 0;
    seen[0] = 1;
    queue[tail++] = 0;
    while (head < tail) {
      const NodeId v = queue[head++];
      for (EdgeId e : graph.incident_edges(v)) {
        const NodeId w = graph.other_end(e, v);
        if (!seen[w]) {
          seen[w] = 1;
          queue[tail++] = w;
        }
      }
    }
    benchmark::DoNotOptimize(tail);
  }
  state.SetItemsProcessed(state.iterations() * std::int64_t(graph.node_count()));
}
BENCHMARK(BM_Bfs)->RangeMultiplier(4)->Range(1 << 14, 1 << 20)->Unit(benchmark::kMillisecond);

}  // namespace

}  // namespace petersen::micro
