// Linking petersen::matching alone: no process-wide hook is installed and no memory is kept by
// using the library; a huge-page pool is an object the program makes and hands in, and what it
// keeps it gives back when destroyed. (The LEMON half
// of the check, no LEMON symbol in this binary, is the CTest beside it in CMakeLists.txt.)
// A plain main, so that nothing but petersen::matching and the C++ runtime is linked.

#include <cstdio>
#include <cstdlib>
#include <memory_resource>
#include <thread>

#include "counting_resource.hpp"
#include "petersen/generators/graph_generators.hpp"
#include "petersen/matching/perfect_matching.hpp"
#include "petersen/memory_pool/huge_page_pool.hpp"

// glibc's registration behind pthread_atfork; this definition takes the place of the one in
// libc_nonshared.a for every object linked here, so each registration is counted, then made.
extern "C" int __register_atfork(void (*prepare)(), void (*parent)(), void (*child)(),
                                 void* dso_handle);
extern "C" void* __dso_handle;
namespace {
int atfork_calls = 0;
}  // namespace
extern "C" int pthread_atfork(void (*prepare)(), void (*parent)(), void (*child)()) {
  ++atfork_calls;
  return __register_atfork(prepare, parent, child, &__dso_handle);
}

namespace {

int failures = 0;
void expect(bool ok, const char* what) {
  std::printf("%s: %s\n", ok ? "ok" : "FAILED", what);
  failures += !ok;
}

// A perfect matching of a graph whose arrays are several huge pages each, checked.
bool match_a_large_graph(std::pmr::memory_resource* memory = std::pmr::get_default_resource()) {
  const petersen::CubicGraph graph = petersen::random_cubic_bridgeless(1u << 18, 7);
  const petersen::PerfectMatchingResult result =
      petersen::perfect_matching(graph, {.memory = memory});
  return result.matching.mate_edge.get_allocator().resource() == memory &&
         petersen::verify_perfect_matching(graph, result.matching).ok();
}

}  // namespace

int main() {
  const int before_calls = atfork_calls;  // a sanitizer runtime may register its own before main
  expect(match_a_large_graph(), "a perfect matching of 2^18 nodes by the default options");
  expect(atfork_calls == before_calls, "no fork handler installed by using the library");
  {
    petersen::HugePagePool pool;
    std::pmr::memory_resource* const before = std::pmr::set_default_resource(&pool);
    expect(match_a_large_graph(), "the same on a huge-page pool");
    std::pmr::set_default_resource(before);
    expect(pool.retained_bytes() > 0, "the pool keeps the freed arrays");
    expect(atfork_calls == before_calls, "no fork handler installed by a pool");
  }
  {
    // Two threads, each matching on its own resource: each resource serves its own call's
    // matching and gets every byte back; nothing is shared.
    petersen::testing::CountingResource first, second;
    bool ok_first = false, ok_second = false;
    std::thread a([&] { ok_first = match_a_large_graph(&first); });
    std::thread b([&] { ok_second = match_a_large_graph(&second); });
    a.join();
    b.join();
    expect(ok_first && ok_second, "two threads match, each on its own resource");
    expect(first.allocated_bytes() >= (1u << 18) * sizeof(petersen::EdgeId) &&
               second.allocated_bytes() >= (1u << 18) * sizeof(petersen::EdgeId),
           "each resource served its call's matching");
    expect(first.live_bytes() == 0 && second.live_bytes() == 0,
           "each resource got every byte back");
  }
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
