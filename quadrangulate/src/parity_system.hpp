#pragma once
// A system of parities over GF(2), for the non-manifold edges of --all-quad: splitting such an edge
// adds a side to every face on it at once, so it flips the parity of several components together.

#include <cstdint>
#include <span>
#include <vector>

namespace petersen::quad_detail {

/// What solve_parity_system found: the columns to take, or, when none will do, a row the target
/// keeps whatever is taken (`stuck`, else kNoRow).
struct ParitySolution {
  static constexpr std::uint32_t kNoRow = 0xFFFFFFFFu;
  std::vector<std::uint32_t> chosen;  ///< ascending column ids
  std::uint32_t stuck = kNoRow;
};

/// A set of columns whose sum over GF(2) is `target`; each column and the target are sets of
/// rows, sorted ascending. Gaussian elimination with sparse rows, each basis vector keyed by its
/// smallest row and carrying the columns it sums: O(c · b · r) for c columns, a basis of b
/// vectors and vectors of up to r rows; on meshes the columns touch a few components each.
ParitySolution solve_parity_system(std::span<const std::vector<std::uint32_t>> columns,
                                   std::vector<std::uint32_t> target);

}  // namespace petersen::quad_detail
