// Micro-benchmark of one augmentation: a perfect matching loses the matched edges of an
// alternating walk of up to `length` matched edges and gains its unmatched ones, which leaves its
// two ends free; augment_matching must find one augmenting path between them (local and faithful).

#include <benchmark/benchmark.h>

#include <random>

#include "micro_inputs.hpp"
#include "petersen/matching/augment.hpp"
#include "petersen/matching/perfect_matching.hpp"

namespace petersen::micro {

namespace {

// A perfect matching with two free nodes at the ends of a random alternating walk from `start`
// of up to `length` matched edges (it stops early when stuck): the walk's matched edges are
// unmatched and its other edges matched.
Matching two_free_nodes(const CubicGraph& graph, NodeId start, int length, std::uint64_t seed) {
  Matching matching =
      perfect_matching(graph, {.algorithm = Algorithm::automatic, .validate = false}).matching;
  std::mt19937_64 rng(seed);
  std::vector<std::uint8_t> on_walk(graph.node_count(), 0);
  std::vector<EdgeId> flip_in;   // unmatched edges of the walk, matched afterwards
  std::vector<EdgeId> flip_out;  // matched edges of the walk, unmatched afterwards
  NodeId v = start;
  on_walk[v] = 1;
  for (int step = 0; step < length; ++step) {
    const EdgeId matched = matching.mate_edge[v];
    const NodeId w = graph.other_end(matched, v);
    on_walk[w] = 1;
    flip_out.push_back(matched);
    if (step + 1 == length) break;  // the walk ends with a matched edge: both ends become free
    // Leave w over a random unmatched edge to a node not yet on the walk, if there is one.
    EdgeId next = kNoEdge;
    for (int k = 0, first = int(rng() % 3); k < 3 && next == kNoEdge; ++k) {
      const EdgeId e = graph.incident_edge(w, (first + k) % 3);
      const NodeId x = graph.other_end(e, w);
      if (e != matched && !on_walk[x] && !on_walk[graph.other_end(matching.mate_edge[x], x)])
        next = e;
    }
    if (next == kNoEdge) break;
    flip_in.push_back(next);
    v = graph.other_end(next, w);
    on_walk[v] = 1;
  }
  for (EdgeId e : flip_out) {
    const auto [a, b] = graph.endpoints(e);
    matching.mate_edge[a] = matching.mate_edge[b] = kNoEdge;
  }
  for (EdgeId e : flip_in) matching.match(graph, e);
  return matching;
}

void one_augmentation(benchmark::State& state, Augment variant) {
  const CubicGraph& graph = plate_input(static_cast<std::uint64_t>(state.range(0))).dual.graph;
  const Matching broken = two_free_nodes(graph, graph.node_count() / 2, int(state.range(1)), 7);
  std::uint64_t labelled = 0;
  for (auto _ : state) {
    state.PauseTiming();
    Matching matching = broken;
    state.ResumeTiming();
    labelled += augment_matching(graph, matching, variant).nodes_labelled;
  }
  state.counters["free"] = double(broken.unmatched_count());
  state.counters["labelled"] =
      benchmark::Counter(double(labelled), benchmark::Counter::kAvgIterations);
}

void BM_AugmentLocal(benchmark::State& state) {
  one_augmentation(state, Augment::local);
}
void BM_AugmentFaithful(benchmark::State& state) {
  one_augmentation(state, Augment::faithful);
}
BENCHMARK(BM_AugmentLocal)
    ->ArgsProduct({{1 << 16, 1 << 20}, {8, 64}})
    ->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AugmentFaithful)
    ->ArgsProduct({{1 << 16, 1 << 20}, {8, 64}})
    ->Unit(benchmark::kMicrosecond);

}  // namespace

}  // namespace petersen::micro
