#include "petersen/dualize/write_mesh.hpp"

#include <bit>
#include <charconv>
#include <cstring>
#include <span>

#include "file_bytes.hpp"
#include "petersen/dualize/read_mesh.hpp"
#include "petersen/graph/huge_pages.hpp"

namespace petersen {

namespace {

// The file's bytes, built in memory and written at once: tens of megabytes for a million faces,
// so on huge pages and recycled like the meshes' arrays (huge_pages.hpp), not faulted in afresh.
using Bytes = std::basic_string<char, std::char_traits<char>, HugePageAllocator<char>>;

// Appends numbers with std::to_chars: shortest exact text for doubles, no locale, no iostreams.
struct Text {
  Bytes out;
  void number(double x) { append(x); }
  void number(std::uint64_t x) { append(x); }
  void word(std::string_view s) { out += s; }
  template <typename T>
  void append(T x) {
    char buffer[32];
    const char* end = std::to_chars(buffer, buffer + sizeof buffer, x).ptr;
    out.append(buffer, static_cast<std::size_t>(end - buffer));
  }
};

template <std::size_t N>
Bytes off_text(std::span<const std::array<double, 3>> positions,
               std::span<const std::array<VertexId, N>> faces) {
  Text t;
  t.word("OFF\n");
  t.number(std::uint64_t{positions.size()});
  t.word(" ");
  t.number(std::uint64_t{faces.size()});
  t.word(" 0\n");
  for (const auto& p : positions) {
    for (int d = 0; d < 3; ++d) {
      t.number(p[d]);
      t.word(d < 2 ? " " : "\n");
    }
  }
  for (const auto& f : faces) {
    t.number(std::uint64_t{N});
    for (VertexId v : f) {
      t.word(" ");
      t.number(std::uint64_t{v});
    }
    t.word("\n");
  }
  return std::move(t.out);
}

template <std::size_t N>
Bytes obj_text(std::span<const std::array<double, 3>> positions,
               std::span<const std::array<VertexId, N>> faces) {
  Text t;
  for (const auto& p : positions) {
    t.word("v");
    for (double x : p) {
      t.word(" ");
      t.number(x);
    }
    t.word("\n");
  }
  for (const auto& f : faces) {
    t.word("f");
    for (VertexId v : f) {
      t.word(" ");
      t.number(std::uint64_t{v} + 1);  // OBJ counts from 1
    }
    t.word("\n");
  }
  return std::move(t.out);
}

template <typename T>
void put_le(Bytes& out, T value) {
  static_assert(std::endian::native == std::endian::little || sizeof(T) == 1,
                "binary PLY writing assumes a little-endian host");
  char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  out.append(raw, sizeof(T));
}

template <std::size_t N>
Bytes ply_bytes(std::span<const std::array<double, 3>> positions,
                std::span<const std::array<VertexId, N>> faces) {
  Bytes out = "ply\nformat binary_little_endian 1.0\ncomment written by petersen\n";
  const std::string header = "element vertex " + std::to_string(positions.size()) +
                             "\nproperty double x\nproperty double y\nproperty double z\n" +
                             "element face " + std::to_string(faces.size()) +
                             "\nproperty list uchar uint vertex_indices\nend_header\n";
  out += header;
  out.reserve(out.size() + positions.size() * 24 + faces.size() * (1 + 4 * N));
  for (const auto& p : positions)
    for (double x : p) put_le(out, x);
  for (const auto& f : faces) {
    put_le(out, static_cast<std::uint8_t>(N));
    for (VertexId v : f) put_le(out, v);
  }
  return out;
}

template <std::size_t N>
void write_mesh(const std::string& path, std::span<const std::array<double, 3>> positions,
                std::span<const std::array<VertexId, N>> faces) {
  switch (mesh_format_of(path)) {
    case MeshFormat::off:
      write_file_bytes(path, off_text<N>(positions, faces));
      break;
    case MeshFormat::obj:
      write_file_bytes(path, obj_text<N>(positions, faces));
      break;
    case MeshFormat::ply:
      write_file_bytes(path, ply_bytes<N>(positions, faces));
      break;
  }
}

}  // namespace

void write_quad_mesh(const std::string& path, const QuadMesh& mesh) {
  write_mesh<4>(path, mesh.positions, mesh.quads);
}

void write_triangle_mesh(const std::string& path, const TriangleMesh& mesh) {
  write_mesh<3>(path, mesh.positions, mesh.triangles);
}

}  // namespace petersen
