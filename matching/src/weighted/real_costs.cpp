#include "petersen/matching/real_costs.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <stdexcept>
#include <string>

namespace petersen {

namespace {

// The binary digits after the point of a finite double: c = M · 2^(e − 53) with M odd (frexp's
// mantissa as a 53-bit integer, its trailing zero bits dropped); 0 for integers.
int fraction_bits(double c) {
  if (c == 0) return 0;
  int e = 0;
  const double m = std::frexp(std::abs(c), &e);  // c = m · 2^e, m in [0.5, 1)
  const auto mantissa = static_cast<std::uint64_t>(std::ldexp(m, 53));
  return std::max(0, 53 - e - std::countr_zero(mantissa));
}

}  // namespace

IntegerCosts integer_costs(std::span<const double> costs, Cost limit) {
  if (limit < 1 || limit > kMaxCost) {
    throw std::invalid_argument("integer_costs: limit " + std::to_string(limit) +
                                " outside 1..2^40");
  }
  double most = 0;
  int bits = 0;
  for (std::size_t e = 0; e < costs.size(); ++e) {
    if (!std::isfinite(costs[e])) {
      throw std::invalid_argument("integer_costs: cost " + std::to_string(costs[e]) + " at index " +
                                  std::to_string(e) + " is not finite");
    }
    most = std::max(most, std::abs(costs[e]));
    bits = std::max(bits, fraction_bits(costs[e]));
  }
  IntegerCosts result;
  result.costs.resize(costs.size());
  const auto top = static_cast<double>(limit);
  // Exact when 2^bits makes every cost an integer within the limit (the product is exact: a
  // power-of-two scaling of a double below 2^53 in magnitude).
  int k = bits;
  result.exact = most == 0 || (bits <= 1074 && std::ldexp(most, bits) <= top);
  if (!result.exact) {
    // most · 2^k < 2^(ilogb(most) + 1 + k) <= 2^floor(log2 limit) <= limit.
    k = std::ilogb(top) - (std::ilogb(most) + 1);
  }
  result.exponent = k;
  for (std::size_t e = 0; e < costs.size(); ++e) {
    const double scaled = std::round(std::ldexp(costs[e], k));
    result.costs[e] = static_cast<Cost>(scaled);
    result.rounding = std::max(result.rounding, std::abs(std::ldexp(scaled, -k) - costs[e]));
  }
  return result;
}

Cost maximum_matching_cost_limit(std::uint64_t largest_matching) {
  // K <= 1 + ν · 2 · limit < 2^52.
  constexpr std::uint64_t kRoom = (std::uint64_t{1} << 52) - 2;
  if (largest_matching == 0) return kMaxCost;
  return static_cast<Cost>(std::clamp<std::uint64_t>(kRoom / (2 * largest_matching), 1,
                                                     static_cast<std::uint64_t>(kMaxCost)));
}

}  // namespace petersen
