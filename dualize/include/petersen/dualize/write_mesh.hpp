#pragma once
// Writing polygon, triangle and quad meshes as OFF, OBJ or PLY (binary little endian), by
// extension, atomically.

#include <string>

#include "petersen/dualize/mesh.hpp"

namespace petersen {

/// Writes the mesh in the format its extension names (see mesh_format_of); a trailing .gz
/// compresses it (gzip, libdeflate level 6). Faces of any arity are written as they are.
/// Coordinates are written in their shortest exact form (text) or as doubles (PLY), so reading
/// the file back gives the same numbers and the same faces. The write is atomic: the bytes go to
/// a new temporary file in the target's folder, flushed to disk, then renamed over the target, so
/// a failed or killed run never leaves a partial file at `path` and never damages a file already
/// there (which may be the very file the mesh was read from). Throws MeshError naming the path if
/// it cannot be written; the temporary file is removed then. O(V + corners).
void write_mesh(const std::string& path, const PolygonMesh& mesh);

/// Writes the quad mesh like write_mesh.
void write_quad_mesh(const std::string& path, const QuadMesh& mesh);

/// Writes the triangle mesh like write_mesh.
void write_triangle_mesh(const std::string& path, const TriangleMesh& mesh);

}  // namespace petersen
