#pragma once
// Writing polygon meshes as OFF, OBJ or PLY (binary little endian), by extension, atomically.

#include <string>
#include <vector>

#include "petersen/io/file_error.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// Writes the mesh in the format its extension names (see mesh_format_of); a trailing .gz
/// compresses it (gzip, libdeflate level 6). Faces of any arity are written as they are.
/// Coordinates are written in their shortest exact form (text) or as doubles (PLY), so reading
/// the file back gives the same numbers and the same faces. The write is atomic: the bytes go to
/// a new temporary file in the target's folder, flushed to disk, then renamed over the target, so
/// a failed or killed run never leaves a partial file at `path` and never damages a file already
/// there (which may be the very file the mesh was read from). Throws FileError naming the path if
/// it cannot be written; the temporary file is removed then. O(V + corners).
///
/// The mesh's attributes (check_attributes is called first) are written back as the readers read
/// them: OBJ gets mtllib lines, vertex colours (v x y z r g b, a uint8 colour scaled to 0-1),
/// vt, vn, faces as v/vt/vn with o, g, usemtl and s lines where a face's value changes; binary
/// PLY gets every vertex and face property with its type, x y z as float when
/// attributes.position_type says so, and corner texture coordinates as MeshLab's `texcoord` face
/// list; OFF gets vertex normals, colours and s t, and face colours. Returns one line per kind of
/// thing the format has no place for ("corner normals (vn): PLY has no place for them"), empty
/// when everything was written. Throws FileError naming the path for a value its PLY type cannot
/// hold, a value a text format cannot spell (not finite) or a name the format cannot spell;
/// MeshError when check_attributes refuses the mesh.
std::vector<std::string> write_mesh(const std::string& path, const PolygonMesh& mesh);

}  // namespace petersen
