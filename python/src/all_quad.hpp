#pragma once
// petersen._petersen's all-quad steps part by part (petersen/partition/all_quad.hpp), which
// petersen.distributed runs as Dask tasks after the pairing.

#include <pybind11/pybind11.h>

namespace petersen::python {

void add_all_quad(pybind11::module_& m);

}  // namespace petersen::python
