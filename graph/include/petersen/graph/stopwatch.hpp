#pragma once
// Wall-clock time for the per-phase statistics that every module's result reports.

#include <chrono>

namespace petersen {

/// Seconds since construction (seconds()), and seconds between laps (lap()), on the steady
/// clock. Reading it costs one clock read; it allocates nothing.
class Stopwatch {
 public:
  /// Seconds since construction.
  double seconds() const { return since(start_); }
  /// Seconds since the previous lap (or construction); starts the next lap.
  double lap() {
    const Clock::time_point now = Clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  using Clock = std::chrono::steady_clock;
  static double since(Clock::time_point t) {
    return std::chrono::duration<double>(Clock::now() - t).count();
  }
  Clock::time_point start_ = Clock::now();
  Clock::time_point last_ = start_;
};

}  // namespace petersen
