#pragma once
// petersen._petersen.render and quad_quality.

#include <pybind11/pybind11.h>

namespace petersen::python {

void add_render(pybind11::module_& m);

}  // namespace petersen::python
