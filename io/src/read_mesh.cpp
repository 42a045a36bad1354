#include "petersen/io/read_mesh.hpp"

#include "parsers.hpp"
#include "petersen/io/file_bytes.hpp"

namespace petersen {

namespace {

PolygonMesh parse(std::string_view bytes, MeshFormat format, const std::string& source,
                  std::vector<std::string>* dropped, const ReadMeshOptions& options) {
  if (bytes.empty()) throw FileError(source, 0, "empty file");
  std::vector<std::string> ignored;
  std::vector<std::string>& out = dropped ? *dropped : ignored;
  // Made on options.memory and moved, never assigned: an assignment across resources copies.
  PolygonMesh mesh = format == MeshFormat::off   ? parse_off(bytes, source, out, options.memory)
                     : format == MeshFormat::obj ? parse_obj(bytes, source, options, out)
                                                 : parse_ply(bytes, source, out, options.memory);
  // A file with no faces is not a mesh the library can do anything with; say so here rather
  // than let an empty surface pass as closed.
  if (mesh.face_count() == 0) throw FileError(source, 0, "no faces");
  return mesh;
}

}  // namespace

MeshFormat mesh_format_of(const std::string& path) {
  std::string_view name = path;
  if (ends_with_nocase(name, ".gz")) name.remove_suffix(3);
  if (ends_with_nocase(name, ".off")) return MeshFormat::off;
  if (ends_with_nocase(name, ".obj")) return MeshFormat::obj;
  if (ends_with_nocase(name, ".ply")) return MeshFormat::ply;
  throw FileError(path, 0, "unknown mesh format (expected .off, .obj or .ply, optionally .gz)");
}

PolygonMesh parse_mesh(std::string_view bytes, MeshFormat format, const std::string& source,
                       std::vector<std::string>* dropped, const ReadMeshOptions& options) {
  return parse(bytes, format, source, dropped, options);
}

PolygonMesh read_mesh(const std::string& path, std::vector<std::string>* dropped,
                      const ReadMeshOptions& options) {
  const MeshFormat format = mesh_format_of(path);
  return parse(read_file_bytes(path, options.memory).view(), format, path, dropped, options);
}

}  // namespace petersen
