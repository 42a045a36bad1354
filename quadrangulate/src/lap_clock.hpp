#pragma once
// Wall-clock seconds between laps, for the front door's per-phase statistics.

#include <chrono>

namespace petersen::quad_detail {

class LapClock {
 public:
  /// Seconds since the previous lap (or construction); starts the next lap.
  double lap() {
    const auto now = std::chrono::steady_clock::now();
    const double seconds = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return seconds;
  }

 private:
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

}  // namespace petersen::quad_detail
