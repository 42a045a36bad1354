#pragma once
// Reading polygon meshes from OFF, OBJ and PLY files, plain or gzip-compressed.

#include <string>
#include <string_view>
#include <vector>

#include "petersen/io/file_error.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

enum class MeshFormat { off, obj, ply };

/// How read_mesh treats what a file names but does not have.
struct ReadMeshOptions {
  /// A texture coordinate or normal index past those the file has (an OBJ `f 1//1` with no `vn`
  /// line before it) is refused, a FileError naming the file and line, instead of that attribute
  /// being dropped for that face with one line in `dropped` per attribute (how many faces, the
  /// first line). Indices of vertices are always checked: a face without its corners is no face.
  bool strict = false;
  /// Where the mesh's arrays, and a compressed file's decompressed bytes, are allocated.
  std::pmr::memory_resource* memory = std::pmr::get_default_resource();
};

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
///   written v, v/vt, v//vn or v/vt/vn (indices into the values read so far; negative ones count
///   back from the last), `usemtl`, `g`, `o`, `s`, `mtllib`. A dangling texture coordinate or
///   normal index: see ReadMeshOptions::strict. Messages number OBJ elements from 1, as OBJ does;
///   OFF and PLY ones from 0.
/// - PLY: ascii, binary_little_endian or binary_big_endian; x, y, z of any numeric type; faces as
///   a list named vertex_indices or vertex_index; every other scalar vertex or face property with
///   its type; MeshLab's per-corner `texcoord` face list as corner texture coordinates. Or, for
///   the faces, a `tristrips` element (one record or more of a vertex_indices list, -1 ending a
///   strip, or in an unsigned index type its largest value): each strip a b c d ... read as the
///   triangles (a, b, c), (c, b, d), (c, d, e), ..., every other one reversed so that all keep
///   the first's orientation; a triangle repeating a vertex (what strip writers use to turn a
///   corner) is left out and counted in `dropped`; an error names the strip and list position.
/// Everything else (OBJ `l`, `p`, `curv` lines; other PLY elements and lists; values an OFF
/// keyword does not declare) is read past, and when `dropped` is given, one line per kind of thing
/// is appended to it ("3 'l' lines, the first at line 12").
/// Throws FileError with the file name and the line (text) or element index (binary) on: an
/// empty file, no faces, an unknown format, truncation, wrong counts, NaN or infinite
/// coordinates, negative or out-of-range vertex indices (attribute ones only when strict), faces
/// of fewer than 3 corners, counts the file cannot hold (checked before anything is allocated), a
/// corrupt or absurdly large gzip stream.
/// O(file size).
PolygonMesh read_mesh(const std::string& path, std::vector<std::string>* dropped = nullptr,
                      const ReadMeshOptions& options = {});

/// Parses a mesh already in memory (as read_mesh does after decompression); `source` names it in
/// error messages and is the FileError's file().
PolygonMesh parse_mesh(std::string_view bytes, MeshFormat format, const std::string& source,
                       std::vector<std::string>* dropped = nullptr,
                       const ReadMeshOptions& options = {});

}  // namespace petersen
