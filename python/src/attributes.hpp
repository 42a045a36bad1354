#pragma once
// A mesh's attributes (petersen/mesh/mesh_attributes.hpp) as a Python dict and back: index
// arrays as int64 with -1 for "none", property columns as numpy arrays of the dtype their PLY
// type names (so a uint8 colour is read and written back as uint8).

#include <pybind11/pybind11.h>

#include <span>

#include "petersen/mesh/mesh.hpp"

namespace petersen::python {

namespace py = pybind11;

/// The attributes the mesh has, one key per non-empty array (see petersen.read_mesh's docstring
/// for the keys); an empty dict for a mesh with none.
py::dict attributes_dict(const MeshAttributes& attributes);

/// Fills mesh.attributes from a dict of attributes_dict's keys (None: none). Throws ValueError
/// for an unknown key, a bad shape or an index below -1, TypeError for a non-integer index array;
/// sizes and ranges against the mesh are check_attributes' (a MeshError, then a ValueError).
void attributes_from(const py::handle& obj, PolygonMesh& mesh);

/// The mesh's attributes with its faces taken in `order` (a permutation of its face ids).
MeshAttributes attributes_in_order(const PolygonMesh& mesh, std::span<const FaceId> order);

}  // namespace petersen::python
