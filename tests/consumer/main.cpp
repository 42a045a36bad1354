// A user's property over petersen's public generators, then the BGL and LEMON adaptors.

#include <cstdio>
#include <petersen/matching/perfect_matching.hpp>
#include <petersen/testing/arbitrary.hpp>
#include <petersen/version.hpp>

#include "checks.hpp"

int check_rapidcheck_property() {
  const bool ok =
      rc::check("every arbitrary cubic bridgeless graph has a verified perfect matching",
                [](const petersen::CubicGraph& g) {
                  const petersen::PerfectMatchingResult r = petersen::perfect_matching(g);
                  RC_ASSERT(petersen::verify_perfect_matching(g, r.matching).ok());
                });
  return ok ? 0 : 1;
}

int main() {
  std::printf("consumer of petersen %s\n", petersen::kVersion);
  const int failures = check_rapidcheck_property() + check_boost_graph() + check_lemon_graph();
  std::printf("consumer: %s\n", failures == 0 ? "all checks passed" : "FAILED");
  return failures == 0 ? 0 : 1;
}
