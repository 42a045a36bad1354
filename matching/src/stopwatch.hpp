#pragma once
// Wall-clock seconds since construction, for the per-phase statistics.

#include <chrono>

namespace petersen {

class Stopwatch {
 public:
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace petersen
