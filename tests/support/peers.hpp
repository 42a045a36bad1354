#pragma once
// Maximum matchings by the peers petersen is tested against, on plain edge lists.

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace petersen::testing {

using EdgeList = std::vector<std::array<std::uint32_t, 2>>;

/// Size of a maximum matching by Boost's edmonds_maximum_cardinality_matching.
std::uint32_t boost_matching_size(std::uint32_t node_count,
                                  std::span<const std::array<std::uint32_t, 2>> edges);
/// Size of a maximum matching by LEMON's MaxMatching.
std::uint32_t lemon_matching_size(std::uint32_t node_count,
                                  std::span<const std::array<std::uint32_t, 2>> edges);

}  // namespace petersen::testing
