#include "runner.hpp"

#include <algorithm>
#include <chrono>
#include <iostream>

#include "isolated_run.hpp"
#include "petersen/graph/connectivity.hpp"

namespace petersen::bench {

namespace {

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : (values[n / 2 - 1] + values[n / 2]) / 2;
}

Measures median_measures(const std::vector<Measures>& runs) {
  auto column = [&](auto get) {
    std::vector<double> values;
    for (const Measures& m : runs) values.push_back(static_cast<double>(get(m)));
    return median(values);
  };
  Measures m;
  m.initial_seconds = column([](const Measures& r) { return r.initial_seconds; });
  m.augment_seconds = column([](const Measures& r) { return r.augment_seconds; });
  m.unpaired = static_cast<std::uint32_t>(column([](const Measures& r) { return r.unpaired; }));
  m.two_phase = runs.front().two_phase;
  m.augmenting_paths =
      static_cast<std::uint64_t>(column([](const Measures& r) { return r.augmenting_paths; }));
  m.reductions = static_cast<std::uint64_t>(column([](const Measures& r) { return r.reductions; }));
  m.flips = static_cast<std::uint64_t>(column([](const Measures& r) { return r.flips; }));
  m.labels = static_cast<std::uint64_t>(column([](const Measures& r) { return r.labels; }));
  m.repeats = static_cast<std::uint32_t>(column([](const Measures& r) { return r.repeats; }));
  return m;
}

// One run: the contestant's first call, then, when that was quicker than `min_seconds`, further
// calls (same seed) until they add up to it, at most 1000; the median of all of them. Each call
// after the first meets memory the first gave back, as a long run meets its own after its
// first arrays; both sides of a ratio are repeated alike.
Measures repeated(const Contestant& contestant, const BenchInput& input, std::uint64_t seed,
                  double min_seconds) {
  std::vector<Measures> calls{contestant.run(input, seed)};
  double spent = calls.front().total_seconds();
  while (spent < min_seconds && calls.size() < 1000) {
    calls.push_back(contestant.run(input, seed));
    spent += calls.back().total_seconds();
  }
  Measures m = median_measures(calls);
  m.repeats = static_cast<std::uint32_t>(calls.size());
  return m;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Runner::Runner(std::vector<Contestant> contestants, RunnerOptions options)
    : contestants_(std::move(contestants)), options_(options) {}

InputResult Runner::run(const InputSpec& spec, const PolygonMesh& mesh, double load_seconds) {
  InputResult result{spec, {}, 0, load_seconds, 0, {}};
  const auto start = std::chrono::steady_clock::now();
  const Dual dual = build_dual(mesh);
  result.dual_seconds = seconds_since(start);
  validate_bridgeless(dual.graph);
  result.components = count_components(dual.graph);
  result.facts = mesh_facts(mesh, result.components);
  const BenchInput input{mesh, dual};

  double floor_seconds = 0;
  for (const Contestant& contestant : contestants_) {
    Cell cell = run_contestant(contestant, input, result, floor_seconds);
    if (contestant.floor && cell.status == Cell::Status::ok) {
      floor_seconds = cell.median.total_seconds();
      cell.ratio_to_floor = 1;
    }
    std::cerr << "  " << spec.name << " " << contestant.name << ": "
              << (cell.status == Cell::Status::ok
                      ? std::to_string(cell.median.total_seconds()) + " s"
                      : cell.message)
              << "\n";
    result.cells.push_back(std::move(cell));
  }
  return result;
}

Cell Runner::run_contestant(const Contestant& contestant, const BenchInput& input,
                            const InputResult& result, double floor_seconds) {
  Cell cell{contestant.name, contestant.paper_name, Cell::Status::ok, "", 0, {}, 0, 0, 0};
  const std::uint32_t nodes = input.dual.graph.node_count();
  const auto cap_key = std::make_pair(result.spec.group, contestant.name);
  if (nodes > contestant.max_nodes) {
    cell.status = Cell::Status::skipped;
    cell.message = "skipped (n > " + std::to_string(contestant.max_nodes) + ")";
    return cell;
  }
  if (auto it = capped_at_.find(cap_key); it != capped_at_.end() && it->second <= nodes) {
    cell.status = Cell::Status::capped_before;
    cell.message = "> cap (not run: hit the cap at " + std::to_string(it->second) + " triangles)";
    return cell;
  }

  std::vector<Measures> runs;
  std::vector<double> peaks;
  double spent = 0;
  for (int r = 0; r < options_.runs && (r == 0 || spent < options_.budget_seconds); ++r) {
    const std::uint64_t seed = contestant.seeded ? options_.seed + r : options_.seed;
    const RunRecord record =
        run_isolated([&] { return repeated(contestant, input, seed, options_.min_run_seconds); },
                     options_.cap_seconds);
    switch (record.status) {
      case RunRecord::Status::ok:
        runs.push_back(record.measures);
        peaks.push_back(double(record.peak_extra_bytes) / (1024.0 * 1024.0));
        spent += record.measures.total_seconds();
        continue;
      case RunRecord::Status::timeout:
        cell.status = Cell::Status::capped;
        cell.message = "> cap";
        capped_at_[cap_key] = nodes;
        break;
      case RunRecord::Status::invalid_matching:
        cell.status = Cell::Status::failed;
        cell.message = std::string("INVALID MATCHING: ") + record.message;
        any_failure_ = true;
        break;
      default:
        cell.status = Cell::Status::failed;
        cell.message = std::string("FAILED: ") + record.message;
        any_failure_ = true;
        break;
    }
    return cell;
  }
  cell.runs = static_cast<int>(runs.size());
  cell.median = median_measures(runs);
  cell.paired_percent =
      nodes == 0 ? 100.0 : 100.0 * double(nodes - cell.median.unpaired) / double(nodes);
  cell.peak_mib = median(peaks);
  if (floor_seconds > 0) cell.ratio_to_floor = cell.median.total_seconds() / floor_seconds;
  return cell;
}

}  // namespace petersen::bench
