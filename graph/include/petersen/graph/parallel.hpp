#pragma once
// Independent tasks on a few threads, started for the call and joined before it returns: no pool
// and no state outlive it.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace petersen {

/// The threads a `threads` option asks for: itself, or every core the machine reports for 0.
inline std::uint32_t resolve_threads(std::uint32_t threads) {
  if (threads > 0) return threads;
  return std::max(1u, std::thread::hardware_concurrency());
}

/// Runs task(i) for every i in [0, count), each exactly once, on min(threads, count) threads (the
/// calling thread is one of them; threads = 0 means resolve_threads(0)). The threads take the next
/// index as they finish one, so uneven tasks balance. The first exception a task throws is
/// rethrown here once every thread has stopped; the tasks not yet started are skipped.
template <class Task>
void run_parallel(std::uint32_t threads, std::uint32_t count, Task task) {
  const std::uint32_t workers = std::min(resolve_threads(threads), count);
  std::atomic<std::uint32_t> next{0};
  std::atomic<bool> failed{false};
  std::exception_ptr first_error;
  std::mutex error_mutex;
  auto work = [&] {
    for (std::uint32_t i; !failed.load(std::memory_order_relaxed) &&
                          (i = next.fetch_add(1, std::memory_order_relaxed)) < count;) {
      try {
        task(i);
      } catch (...) {
        const std::lock_guard lock(error_mutex);
        if (!first_error) first_error = std::current_exception();
        failed = true;
      }
    }
  };
  {
    std::vector<std::jthread> helpers;
    for (std::uint32_t t = 1; t < workers; ++t) helpers.emplace_back(work);
    work();
  }  // the helpers join here
  if (first_error) std::rethrow_exception(first_error);
}

}  // namespace petersen
