#include "parity_system.hpp"

#include <algorithm>
#include <iterator>
#include <unordered_map>

namespace petersen::quad_detail {

namespace {

using Rows = std::vector<std::uint32_t>;

// a := a + b over GF(2), both sorted.
void add_into(Rows& a, const Rows& b) {
  Rows sum;
  sum.reserve(a.size() + b.size());
  std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(sum));
  a = std::move(sum);
}

struct BasisVector {
  Rows rows;     // its rows; the smallest is its key
  Rows columns;  // the input columns it is the sum of
};

// Reduces `rows` (and the columns it sums) by the basis until its smallest row keys no vector.
void reduce(const std::unordered_map<std::uint32_t, BasisVector>& basis, Rows& rows,
            Rows& columns) {
  while (!rows.empty()) {
    const auto it = basis.find(rows.front());
    if (it == basis.end()) return;
    add_into(rows, it->second.rows);
    add_into(columns, it->second.columns);
  }
}

}  // namespace

ParitySolution solve_parity_system(std::span<const std::vector<std::uint32_t>> columns,
                                   std::vector<std::uint32_t> target) {
  std::unordered_map<std::uint32_t, BasisVector> basis;
  for (std::uint32_t c = 0; c < columns.size(); ++c) {
    BasisVector v{columns[c], {c}};
    reduce(basis, v.rows, v.columns);
    if (!v.rows.empty()) {
      const std::uint32_t key = v.rows.front();
      basis.emplace(key, std::move(v));
    }
  }
  ParitySolution solution;
  reduce(basis, target, solution.chosen);
  if (!target.empty()) {
    solution.stuck = target.front();
    solution.chosen.clear();
  }
  return solution;
}

}  // namespace petersen::quad_detail
