#pragma once
// Writing triangle and quad meshes as OFF, OBJ or PLY (binary little endian), by extension.

#include <string>

#include "petersen/dualize/mesh.hpp"

namespace petersen {

/// Writes the quad mesh in the format its extension names (see mesh_format_of); a trailing .gz
/// compresses it. Coordinates are written in their shortest exact form (text) or as doubles
/// (PLY), so reading the file back gives the same numbers. Throws MeshError naming the path if it
/// cannot be written. O(V + F).
void write_quad_mesh(const std::string& path, const QuadMesh& mesh);

/// Writes the triangle mesh like write_quad_mesh.
void write_triangle_mesh(const std::string& path, const TriangleMesh& mesh);

}  // namespace petersen
