#pragma once
// The one seeded generator behind petersen's random choices (the greedy pairings' orders, the
// random cubic graphs): SplitMix64 with its own bounded draws, so a seed gives the same result on
// every platform and standard library (std::shuffle and std::uniform_int_distribution do not).

#include <cstdint>

namespace petersen {

class SeededRandom {
 public:
  explicit SeededRandom(std::uint64_t seed) : state_(seed) {}

  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
  }
  /// A value in [0, bound), by Lemire's multiply-shift (bias below bound / 2^32).
  std::uint32_t below(std::uint32_t bound) {
    return static_cast<std::uint32_t>(((next() >> 32) * bound) >> 32);
  }
  /// A value in [0, bound) for bounds past 2^32 (bias below bound / 2^64).
  std::uint64_t below64(std::uint64_t bound) {
    __extension__ using Wide = unsigned __int128;
    return static_cast<std::uint64_t>((Wide{next()} * bound) >> 64);
  }

 private:
  std::uint64_t state_;
};

}  // namespace petersen
