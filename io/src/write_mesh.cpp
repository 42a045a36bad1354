#include "petersen/io/write_mesh.hpp"

#include <bit>
#include <charconv>
#include <cstring>
#include <span>

#include "petersen/graph/memory.hpp"
#include "petersen/io/file_bytes.hpp"
#include "petersen/io/read_mesh.hpp"
#include "write_buffer.hpp"

namespace petersen {

namespace {

// Any mesh as the writers see it: positions, and face f's corners as face(f).
template <class FaceAt>
struct MeshView {
  std::span<const std::array<double, 3>> positions;
  std::size_t face_count = 0;
  std::size_t corner_count = 0;
  std::uint32_t max_arity = 0;
  FaceAt face;
};

/// "x y z\n", the coordinates of a vertex line in both text formats.
void put_position(Buffer& out, const std::array<double, 3>& p) {
  out.number(p[0]);
  out.put(' ');
  out.number(p[1]);
  out.put(' ');
  out.number(p[2]);
  out.put('\n');
}

template <class FaceAt>
Buffer off_text(const MeshView<FaceAt>& mesh) {
  constexpr std::size_t n = Buffer::kLongestNumber;
  Buffer out(64 + mesh.positions.size() * 3 * (n + 1) + mesh.face_count * (n + 1) +
             mesh.corner_count * (n + 1));
  out.word("OFF\n");
  out.number(mesh.positions.size());
  out.put(' ');
  out.number(mesh.face_count);
  out.word(" 0\n");
  for (const auto& p : mesh.positions) {
    put_position(out, p);
  }
  for (std::size_t f = 0; f < mesh.face_count; ++f) {
    const std::span<const VertexId> face = mesh.face(f);
    out.number(face.size());
    for (VertexId v : face) {
      out.put(' ');
      out.number(v);
    }
    out.put('\n');
  }
  return out;
}

template <class FaceAt>
Buffer obj_text(const MeshView<FaceAt>& mesh) {
  constexpr std::size_t n = Buffer::kLongestNumber;
  Buffer out(mesh.positions.size() * (2 + 3 * (n + 1)) + mesh.face_count * 2 +
             mesh.corner_count * (n + 1));
  for (const auto& p : mesh.positions) {
    out.word("v ");
    put_position(out, p);
  }
  for (std::size_t f = 0; f < mesh.face_count; ++f) {
    out.put('f');
    for (VertexId v : mesh.face(f)) {
      out.put(' ');
      out.number(std::uint64_t{v} + 1);  // OBJ counts from 1
    }
    out.put('\n');
  }
  return out;
}

// Binary little endian: x, y, z as doubles (every position exact), each face as a list of uint
// indices counted by a uchar, or by a uint when some face has more than 255 corners.
template <class FaceAt>
Buffer ply_bytes(const MeshView<FaceAt>& mesh) {
  const bool wide = mesh.max_arity > 255;
  const std::string header =
      "ply\nformat binary_little_endian 1.0\ncomment written by petersen\nelement vertex " +
      std::to_string(mesh.positions.size()) +
      "\nproperty double x\nproperty double y\nproperty double z\nelement face " +
      std::to_string(mesh.face_count) + "\nproperty list " + (wide ? "uint" : "uchar") +
      " uint vertex_indices\nend_header\n";
  Buffer out(header.size() + mesh.positions.size_bytes() + mesh.face_count * (wide ? 4 : 1) +
             mesh.corner_count * 4);
  out.word(header);
  out.binary(mesh.positions.data(), mesh.positions.size());
  for (std::size_t f = 0; f < mesh.face_count; ++f) {
    const std::span<const VertexId> face = mesh.face(f);
    if (wide) {
      const std::uint32_t count = static_cast<std::uint32_t>(face.size());
      out.binary(&count, 1);
    } else {
      out.put(static_cast<char>(face.size()));
    }
    out.binary(face.data(), face.size());
  }
  return out;
}

template <class FaceAt>
void write_view(const std::string& path, const MeshView<FaceAt>& mesh) {
  switch (mesh_format_of(path)) {
    case MeshFormat::off:
      write_file_bytes(path, off_text(mesh).view());
      break;
    case MeshFormat::obj:
      write_file_bytes(path, obj_text(mesh).view());
      break;
    case MeshFormat::ply:
      write_file_bytes(path, ply_bytes(mesh).view());
      break;
  }
}

}  // namespace

std::vector<std::string> write_mesh(const std::string& path, const PolygonMesh& mesh) {
  check_attributes(mesh);
  const MeshFormat format = mesh_format_of(path);
  std::vector<std::string> dropped;
  const bool float_positions =
      format == MeshFormat::ply && mesh.attributes.position_type == ScalarType::float32;
  if (!mesh.attributes.empty() || float_positions) {
    const Buffer bytes = format == MeshFormat::off   ? off_with_attributes(mesh, path, dropped)
                         : format == MeshFormat::obj ? obj_with_attributes(mesh, path, dropped)
                                                     : ply_with_attributes(mesh, path, dropped);
    write_file_bytes(path, bytes.view());
    return dropped;
  }
  std::uint32_t max_arity = mesh.face_count() > 0 ? 3 : 0;
  if (!mesh.all_triangles()) {
    for (std::size_t f = 0; f < mesh.face_count(); ++f) {
      max_arity = std::max(max_arity, mesh.arity(static_cast<FaceId>(f)));
    }
  }
  auto face = [&mesh](std::size_t f) { return mesh.face(static_cast<FaceId>(f)); };
  write_view(path, MeshView<decltype(face)>{mesh.positions, mesh.face_count(), mesh.corners.size(),
                                            max_arity, face});
  return dropped;
}

}  // namespace petersen
