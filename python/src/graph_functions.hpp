#pragma once
// petersen._petersen.weighted_matching: the minimum-cost matchings of any graph for
// petersen.graphs (networkx, scipy and arrays), with integer or real costs.

#include <pybind11/pybind11.h>

namespace petersen::python {

void add_graph_functions(pybind11::module_& m);

}  // namespace petersen::python
