#pragma once
// petersen._petersen's part, cut and repair steps (petersen/partition/partition.hpp), which
// petersen.distributed runs as Dask tasks.

#include <pybind11/pybind11.h>

namespace petersen::python {

void add_partition(pybind11::module_& m);

}  // namespace petersen::python
