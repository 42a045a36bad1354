// Linking petersen::matching alone: no process-wide hook is installed and no memory is kept by
// merely using the library, until the program turns the huge-page pool on itself. (The LEMON half
// of the check, no LEMON symbol in this binary, is the CTest beside it in CMakeLists.txt.)
// A plain main, so that nothing but petersen::matching and the C++ runtime is linked.

#include <cstdio>
#include <cstdlib>

#include "petersen/generators/graph_generators.hpp"
#include "petersen/graph/huge_pages.hpp"
#include "petersen/matching/perfect_matching.hpp"

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
bool match_a_large_graph() {
  const petersen::CubicGraph graph = petersen::random_cubic_bridgeless(1u << 18, 7);
  const petersen::PerfectMatchingResult result = petersen::perfect_matching(graph);
  return petersen::verify_perfect_matching(graph, result.matching).ok();
}

}  // namespace

int main() {
  const int before = atfork_calls;  // a sanitizer runtime may register its own before main
  expect(match_a_large_graph(), "a perfect matching of 2^18 nodes by the default options");
  expect(atfork_calls == before, "no fork handler installed by using the library");
  expect(petersen::huge_pages::retained_bytes() == 0, "no memory kept after the arrays are freed");

  petersen::huge_pages::enable_pool();
  expect(atfork_calls == before + 1, "enable_pool() installs its fork handler");
  expect(match_a_large_graph(), "the same with the pool on");
  expect(petersen::huge_pages::retained_bytes() > 0, "the pool keeps the freed arrays");
  petersen::huge_pages::disable_pool();
  expect(petersen::huge_pages::retained_bytes() == 0, "disable_pool() gives them back");
  return failures == 0 ? EXIT_SUCCESS : EXIT_FAILURE;
}
