#pragma once
// Reading polygon meshes from OFF, OBJ and PLY files, plain or gzip-compressed.

#include <string>
#include <string_view>
#include <vector>

#include "petersen/io/file_error.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

enum class MeshFormat { off, obj, ply };

/// The format named by the path's extension (.off, .obj, .ply, case-insensitive), looking past a
/// trailing .gz. Throws FileError naming the path for any other extension.
MeshFormat mesh_format_of(const std::string& path);

/// Reads a polygon mesh, choosing the format by extension; a gzip-compressed file (recognised by
/// its first bytes, whatever its name; several gzip members are read one after the other) is
/// decompressed first. Faces of any arity from 3 are kept exactly as written: same corners, same
/// order, repeated corners included. Every vertex is kept, referenced or not. What else a file
/// carries is kept in mesh.attributes (see MeshAttributes):
/// - OFF: "n i1 ... in" face lines; vertex normals (NOFF), colours (COFF) and texture
///   coordinates (STOFF) as vertex properties nx ny nz, red green blue [alpha], s t; a colour
///   after a face's indices as face properties red green blue [alpha]; whole numbers 0-255 are
///   uint8, other colours float32.
/// - OBJ: `v` (with `r g b` as vertex properties red, green, blue), `vt`, `vn`, `f` with corners
///   written v, v/vt, v//vn or v/vt/vn (negative indices count back from the last read so far),
///   `usemtl`, `g`, `o`, `s`, `mtllib`.
/// - PLY: ascii, binary_little_endian or binary_big_endian; x, y, z of any numeric type; faces as
///   a list named vertex_indices or vertex_index; every other scalar vertex or face property with
///   its type; MeshLab's per-corner `texcoord` face list as corner texture coordinates.
/// Everything else (OBJ `l`, `p`, `curv` lines; other PLY elements and lists; values an OFF
/// keyword does not declare) is read past, and when `dropped` is given, one line per kind of thing
/// is appended to it ("3 'l' lines, the first at line 12").
/// Throws FileError with the file name and the line (text) or element index (binary) on: an
/// empty file, no faces, an unknown format, truncation, wrong counts, NaN or infinite
/// coordinates, negative or out-of-range indices, faces of fewer than 3 corners, counts the file
/// cannot hold (checked before anything is allocated), a corrupt or absurdly large gzip stream.
/// O(file size).
PolygonMesh read_mesh(const std::string& path, std::vector<std::string>* dropped = nullptr);

/// Parses a mesh already in memory (as read_mesh does after decompression); `source` names it in
/// error messages and is the FileError's file().
PolygonMesh parse_mesh(std::string_view bytes, MeshFormat format, const std::string& source,
                       std::vector<std::string>* dropped = nullptr);

}  // namespace petersen
