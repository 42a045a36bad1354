#pragma once
// Runs one contestant in a forked child with a time cap and measures its peak memory.

#include <functional>

#include "measures.hpp"

namespace petersen::bench {

/// Forks; the child returns its free heap pages to the system (malloc_trim), resets its
/// resident-memory high-water mark (/proc/self/clear_refs), runs `body`, adds the growth of VmHWM
/// over the VmRSS it started from, and writes the record to a pipe. The parent waits at most
/// `cap_seconds`, then SIGKILLs the child (Status::timeout). A child that dies without reporting is
/// Status::crashed; an exception from `body` is Status::error.
RunRecord run_isolated(const std::function<Measures()>& body, double cap_seconds);

/// Copies `text` into the record's message, truncated to fit.
void set_message(RunRecord& record, const char* text);

}  // namespace petersen::bench
