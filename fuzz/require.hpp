#pragma once
// The fuzz targets' check: a broken promise names itself (file, line, condition) in the log
// before the abort that libFuzzer reports, so a finding says what broke, not only where.

#include <cstdio>
#include <cstdlib>

namespace petersen::fuzz {

[[noreturn]] inline void broken(const char* what, const char* file, int line) {
  std::fprintf(stderr, "%s:%d: broken: %s\n", file, line, what);
  std::abort();
}

}  // namespace petersen::fuzz

#define REQUIRE(condition) \
  ((condition) ? void() : ::petersen::fuzz::broken(#condition, __FILE__, __LINE__))
