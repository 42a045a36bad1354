#include "petersen/dualize/read_mesh.hpp"

#include "file_bytes.hpp"
#include "parsers.hpp"

namespace petersen {

MeshFormat mesh_format_of(const std::string& path) {
  std::string_view name = path;
  if (ends_with_nocase(name, ".gz")) name.remove_suffix(3);
  if (ends_with_nocase(name, ".off")) return MeshFormat::off;
  if (ends_with_nocase(name, ".obj")) return MeshFormat::obj;
  if (ends_with_nocase(name, ".ply")) return MeshFormat::ply;
  throw MeshError(path + ": unknown mesh format (expected .off, .obj or .ply, optionally .gz)");
}

TriangleMesh parse_triangle_mesh(std::string_view bytes, MeshFormat format,
                                 const std::string& source) {
  if (bytes.empty()) throw MeshError(source + ": empty file");
  TriangleMesh mesh;
  switch (format) {
    case MeshFormat::off:
      mesh = parse_off(bytes, source);
      break;
    case MeshFormat::obj:
      mesh = parse_obj(bytes, source);
      break;
    case MeshFormat::ply:
      mesh = parse_ply(bytes, source);
      break;
  }
  // A file with no faces is not a mesh the library can do anything with; say so here rather
  // than let an empty surface pass as closed.
  if (mesh.triangles.empty()) throw MeshError(source + ": no faces");
  return mesh;
}

TriangleMesh read_triangle_mesh(const std::string& path) {
  const MeshFormat format = mesh_format_of(path);
  return parse_triangle_mesh(read_file_bytes(path), format, path);
}

}  // namespace petersen
