#pragma once
// What one contestant run reports: the paper's columns (a)–(e) and the counters beside them. A
// plain struct, so a forked child can hand it to the parent through a pipe.

#include <cstdint>

namespace petersen::bench {

struct Measures {
  double initial_seconds = 0;  ///< (a): initial pairing, or the whole of a one-step algorithm
  double augment_seconds = 0;  ///< (d): time to make the initial pairing perfect
  std::uint32_t unpaired = 0;  ///< (c): nodes left unpaired by the initial pairing
  bool two_phase = false;      ///< an initial pairing then augmentation (columns (b)–(d) apply)
  std::uint64_t augmenting_paths = 0;
  std::uint64_t reductions = 0;  ///< Frink reductions (ds, gw, frink)
  std::uint64_t flips = 0;       ///< edges flipped (lrs)
  std::uint64_t labels = 0;      ///< even/odd labels the augmentation gave (its work)
  std::uint32_t repeats = 1;     ///< calls in one process whose median this is (Runner says why)
  double total_seconds() const { return initial_seconds + augment_seconds; }  ///< (e)
};

/// The outcome of one run in its own process.
struct RunRecord {
  enum class Status : std::int32_t { ok, error, invalid_matching, timeout, crashed };
  Status status = Status::ok;
  Measures measures;
  std::int64_t peak_extra_bytes = 0;  ///< VmHWM after the run minus VmRSS before it
  char message[240] = {};
};

}  // namespace petersen::bench
