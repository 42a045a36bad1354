#pragma once
// Runs every contestant on one input, repeatedly and in isolation, and condenses the runs into
// medians: one Cell per contestant.

#include <map>
#include <string>
#include <vector>

#include "contestants.hpp"
#include "inputs.hpp"

namespace petersen::bench {

struct RunnerOptions {
  int runs = 5;                ///< runs per contestant and input (medians are reported)
  double cap_seconds = 10;     ///< per run; a slower run is killed and reported as "> cap"
  double budget_seconds = 10;  ///< no further repeats once a contestant's runs add up to this
  std::uint64_t seed = 1;      ///< run r of a seeded contestant uses seed + r
  /// A run whose first call takes less is repeated in its process until its calls add up to this,
  /// and reports their median. Off (0) by default, so every row is one cold call per process as
  /// in the paper's tables; on, a sub-millisecond row measures the algorithm on warm memory
  /// instead of its first page touches (bench/RESULTS.md, "The small meshes, warm").
  double min_run_seconds = 0;
};

/// One contestant on one input.
struct Cell {
  enum class Status { ok, capped, capped_before, skipped, failed };
  std::string contestant, paper_name;
  Status status = Status::ok;
  std::string message;  ///< why it failed or was skipped
  int runs = 0;
  Measures median;  ///< each column's median over the runs
  double paired_percent = 0;
  double peak_mib = 0;        ///< median peak extra memory
  double ratio_to_floor = 0;  ///< median total over the BFS floor's median total
};

struct InputResult {
  InputSpec spec;
  MeshFacts facts;
  std::uint32_t components = 0;
  double load_seconds = 0, dual_seconds = 0;
  std::vector<Cell> cells;
};

/// Runs contestants over inputs in the given order, remembering across inputs which contestants
/// are absent from this build and which hit the cap (a contestant that hit the cap on an input
/// of a group is not run again on larger inputs of that group: Status::capped_before).
class Runner {
 public:
  Runner(std::vector<Contestant> contestants, RunnerOptions options);

  /// Builds and validates the dual graph of the input's mesh (loaded by the caller in
  /// `load_seconds`), then runs every contestant on it. Throws MeshError or GraphError for a
  /// broken input.
  InputResult run(const InputSpec& spec, const PolygonMesh& mesh, double load_seconds);

  /// Whether any run returned a matching that failed verification, or crashed or threw.
  bool any_failure() const { return any_failure_; }

 private:
  Cell run_contestant(const Contestant& contestant, const BenchInput& input,
                      const InputResult& result, double floor_seconds);

  std::vector<Contestant> contestants_;
  RunnerOptions options_;
  std::map<std::pair<std::string, std::string>, std::uint64_t> capped_at_;  // (group, name) -> F
  bool any_failure_ = false;
};

}  // namespace petersen::bench
