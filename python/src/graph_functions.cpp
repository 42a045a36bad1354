#include "graph_functions.hpp"

#include <pybind11/numpy.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "petersen/matching/any_graph.hpp"
#include "petersen/matching/real_costs.hpp"

namespace petersen::python {
namespace {

CostObjective objective_of(const std::string& name) {
  if (name == "maximum") return CostObjective::maximum;
  if (name == "any_size") return CostObjective::any_size;
  if (name == "perfect") return CostObjective::perfect;
  throw py::value_error("unknown objective '" + name + "': maximum, any_size or perfect");
}

// The costs (int64 or float64) as the solver's integers: integers as they are when every one is
// within `limit` (kMaxCost, or the less the maximum objective's unmatched cost needs), else as
// doubles rounded at a power of two (integer_costs), the rounding kept.
IntegerCosts solver_costs(const py::array& costs, std::size_t m, Cost limit) {
  if (costs.ndim() != 1 || static_cast<std::size_t>(costs.shape(0)) != m) {
    throw py::value_error("costs: one per edge, " + std::to_string(m) + ", in a flat array");
  }
  const char kind = costs.dtype().kind();
  if (kind != 'f' && !(kind == 'i' && costs.dtype().itemsize() == 8)) {
    throw py::type_error("costs must be an int64 or float array");
  }
  if (kind == 'i') {
    const auto ints = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>(costs);
    const std::int64_t* data = ints.data();
    if (std::all_of(data, data + m, [&](std::int64_t c) { return c <= limit && c >= -limit; })) {
      IntegerCosts exact;
      exact.costs.assign(data, data + m);
      return exact;
    }
  }
  const auto reals = py::array_t<double, py::array::c_style | py::array::forcecast>(costs);
  return integer_costs(std::span<const double>(reals.data(), m), limit);
}

// The cheapest matching among those `objective` allows (cheapest_matching_any_graph, its
// certificate checked): the sorted indices of its edges, whether the costs were exact, the
// power of two they were scaled by, the largest rounding, whether it is perfect, and for
// "perfect" without a perfect matching the Tutte–Berge set proving there is none.
py::tuple weighted_matching_py(std::uint32_t n, const py::handle& edges, const py::array& costs,
                               const std::string& objective, std::uint32_t threads) {
  const CostObjective chosen = objective_of(objective);
  const std::vector<std::array<NodeId, 2>> list = node_pairs(n, edges);
  std::uint64_t loop_free = 0;
  for (auto [a, b] : list) loop_free += a != b;
  const std::uint64_t largest = std::min<std::uint64_t>(n / 2, loop_free);
  const Cost limit =
      chosen == CostObjective::maximum ? maximum_matching_cost_limit(largest) : kMaxCost;
  const IntegerCosts integers = solver_costs(costs, list.size(), limit);
  const std::vector<std::int64_t> cost_list(integers.costs.begin(), integers.costs.end());
  AnyGraphCheapestMatching result;
  std::vector<std::int64_t> matched;
  {
    py::gil_scoped_release release;
    result = cheapest_matching_any_graph(n, list, cost_list, threads, chosen);
    matched = matched_edges(list, result.mate_edge);
  }
  py::array_t<std::int64_t> matched_array(matched.size());
  std::copy(matched.begin(), matched.end(), matched_array.mutable_data());
  py::array_t<std::int64_t> tutte(result.tutte_set.size());
  std::copy(result.tutte_set.begin(), result.tutte_set.end(), tutte.mutable_data());
  return py::make_tuple(matched_array, integers.exact, integers.exponent, integers.rounding,
                        result.perfect, tutte);
}

}  // namespace

void add_graph_functions(py::module_& m) {
  m.def("weighted_matching", &weighted_matching_py, py::arg("n"), py::arg("edges"),
        py::arg("costs"), py::arg("objective"), py::arg("threads"));
}

}  // namespace petersen::python
