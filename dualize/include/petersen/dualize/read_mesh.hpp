#pragma once
// Reading triangle meshes from OFF, OBJ and PLY files, plain or gzip-compressed.

#include <string>
#include <string_view>

#include "petersen/dualize/mesh.hpp"

namespace petersen {

enum class MeshFormat { off, obj, ply };

/// The format named by the path's extension (.off, .obj, .ply, case-insensitive), looking past a
/// trailing .gz. Throws MeshError naming the path for any other extension.
MeshFormat mesh_format_of(const std::string& path);

/// Reads a triangle mesh, choosing the format by extension; `name.ext.gz` is decompressed on the
/// fly through zlib. OFF: faces must be triangles. OBJ: faces may be written v, v/vt, v//vn or
/// v/vt/vn, indices may be negative (relative to the vertices read so far); only `v` and `f` lines
/// matter. PLY: ascii, binary_little_endian or binary_big_endian; x, y, z of any numeric type;
/// faces as a list named vertex_indices or vertex_index; other properties and elements are
/// skipped. Every vertex is kept, referenced or not.
/// Throws MeshError with the file name and the line (text) or element index (binary) on: an
/// empty file, an unknown format, truncation, wrong counts, NaN or infinite coordinates, negative
/// or out-of-range indices, faces that are not triangles, counts the file cannot hold (checked
/// before anything is allocated). O(file size).
TriangleMesh read_triangle_mesh(const std::string& path);

/// Parses a mesh already in memory (as read_triangle_mesh does after decompression); `source`
/// names it in error messages.
TriangleMesh parse_triangle_mesh(std::string_view bytes, MeshFormat format,
                                 const std::string& source);

}  // namespace petersen
