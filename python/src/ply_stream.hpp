#pragma once
// petersen._petersen's reader of binary PLY triangle meshes by ranges (petersen/io/ply_stream.hpp):
// petersen.distributed's tasks read their faces and positions through the one PLY header reader.

#include <pybind11/pybind11.h>

namespace petersen::python {

void add_ply_stream(pybind11::module_& m);

}  // namespace petersen::python
