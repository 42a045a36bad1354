// run_parallel: every task once on any number of threads, and a task's exception reaches the
// caller.

#include "petersen/graph/parallel.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace petersen {
namespace {

TEST(RunParallel, RunsEveryTaskOnce) {
  for (std::uint32_t threads : {0u, 1u, 2u, 3u, 8u}) {
    for (std::uint32_t count : {0u, 1u, 2u, 7u, 1000u}) {
      std::vector<std::atomic<int>> runs(count);
      run_parallel(threads, count, [&](std::uint32_t i) { ++runs[i]; });
      for (std::uint32_t i = 0; i < count; ++i) {
        EXPECT_EQ(runs[i].load(), 1) << threads << " threads, task " << i << " of " << count;
      }
    }
  }
}

TEST(RunParallel, RethrowsATasksException) {
  for (std::uint32_t threads : {1u, 2u, 4u}) {
    std::atomic<int> started{0};
    EXPECT_THROW(run_parallel(threads, 100,
                              [&](std::uint32_t i) {
                                ++started;
                                if (i == 5) throw std::runtime_error("task 5");
                              }),
                 std::runtime_error);
    EXPECT_GE(started.load(), 6);
  }
}

TEST(RunParallel, ZeroThreadsMeansEveryCore) {
  EXPECT_GE(resolve_threads(0), 1u);
  EXPECT_EQ(resolve_threads(3), 3u);
}

}  // namespace
}  // namespace petersen
