#pragma once
// Raised inside a contestant run when its matching fails verify_perfect_matching.

#include <stdexcept>

namespace petersen::bench {

struct VerificationError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace petersen::bench
