#pragma once
// Binary PLY triangle meshes larger than memory: read by ranges of faces and vertices from a
// mapped file, written as a stream. The header is read by the one PLY header reader.

#include <array>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "petersen/graph/memory.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

/// A binary little-endian PLY whose elements are a vertex element of scalar properties and then
/// a face element of one list, the corners, with an integer count and 32-bit indices. Mapped, not
/// read: a range is read where it is asked for, and released() gives its pages back, so that
/// the process holds only what it is working on. Not copyable. Its const members may run on
/// several threads at once: they only read the mapping (a range one thread releases, another
/// faults in again from the page cache).
class PlyTriangleStream {
 public:
  /// Maps the file and reads its header. Throws FileError naming the file (and the header line)
  /// when it cannot be opened, is compressed, is not such a PLY, or is shorter than its header
  /// says.
  explicit PlyTriangleStream(const std::string& path);
  ~PlyTriangleStream();
  PlyTriangleStream(const PlyTriangleStream&) = delete;
  PlyTriangleStream& operator=(const PlyTriangleStream&) = delete;

  std::uint64_t vertex_count() const { return vertex_count_; }
  std::uint64_t face_count() const { return face_count_; }
  std::size_t vertex_record_bytes() const { return vertex_bytes_; }
  /// The header lines declaring the vertex element ("element vertex N" and its properties), each
  /// ending in '\n': a writer copies them with the records.
  const std::string& vertex_declaration() const { return vertex_declaration_; }
  /// Where the vertex records start in the file, and where the face records start (right after
  /// the last vertex record): a reader or a writer that copies the vertex block as it is.
  std::size_t vertex_offset() const { return vertex_start_; }
  std::size_t face_offset() const { return face_start_; }
  /// The same with `count` vertices ("element vertex count"): a writer that adds vertices.
  std::string vertex_declaration(std::uint64_t count) const;
  /// Appends to `out` one vertex record that blends the vertices `ids` (one to four): each
  /// property the average of theirs, a float one rounded to its type, an integer one rounded to
  /// the nearest (halves away from zero). The record of a midpoint or a centre that --all-quad
  /// adds. O(ids · properties), random reads.
  void append_blended_record(std::span<const VertexId> ids, std::string& out) const;

  /// The corners of faces first..first+count-1 into `corners` (3 per face). Throws FileError
  /// naming the file, the face and its byte for a face that is not a triangle or names a vertex
  /// out of range. O(count).
  void read_faces(std::uint64_t first, std::uint64_t count, std::span<VertexId> corners) const;
  /// The positions (properties x, y and z, of any scalar type, as doubles: the values the
  /// in-memory reader gives) of the vertices `ids`, into `positions` (one per id). Throws
  /// FileError naming the file when the vertex element has no x, y or z. O(ids), random reads.
  void read_positions(std::span<const VertexId> ids,
                      std::span<std::array<double, 3>> positions) const;
  /// The records of vertices first..first+count-1, as they are in the file.
  std::string_view vertex_records(std::uint64_t first, std::uint64_t count) const;
  /// Gives the pages of those faces' or vertices' records back (they stay in the page cache).
  void release_faces(std::uint64_t first, std::uint64_t count) const;
  void release_vertices(std::uint64_t first, std::uint64_t count) const;

 private:
  void release(std::size_t begin, std::size_t end) const;

  std::string path_;
  const char* bytes_ = nullptr;
  std::size_t size_ = 0;
  std::uint64_t vertex_count_ = 0, face_count_ = 0;
  std::size_t vertex_bytes_ = 0, vertex_start_ = 0, face_start_ = 0;
  std::size_t count_bytes_ = 1, face_bytes_ = 13;
  // Where x, y and z lie in a vertex record and their types; offset SIZE_MAX when absent.
  std::array<std::size_t, 3> xyz_offset_{};
  std::array<std::uint8_t, 3> xyz_type_{};
  std::vector<std::uint8_t> property_types_;  // the vertex properties' ScalarTypes, in order
  std::string vertex_declaration_;
};

/// A binary little-endian PLY written as a stream: the header, the vertex records as given, then
/// quads and triangles (a uchar count and int indices), into a temporary file beside `path`
/// renamed over it by commit() (removed if the writer is destroyed first). Throws FileError naming
/// the path when writing fails, and when commit() finds other than face_count faces.
class PlyStreamWriter {
 public:
  PlyStreamWriter(const std::string& path, const std::string& vertex_declaration,
                  std::uint64_t face_count);
  ~PlyStreamWriter();
  PlyStreamWriter(const PlyStreamWriter&) = delete;
  PlyStreamWriter& operator=(const PlyStreamWriter&) = delete;

  void write_vertex_records(std::string_view records) { put(records); }
  void write_triangle(VertexId a, VertexId b, VertexId c);
  void write_quad(VertexId a, VertexId b, VertexId c, VertexId d);
  void commit();
  std::uint64_t bytes_written() const { return bytes_; }

 private:
  void put(std::string_view bytes);
  void flush();
  template <std::size_t N>
  void write_face(const VertexId (&corners)[N]);

  struct File;
  std::unique_ptr<File> file_;
  std::string path_;
  RawArray<char> buffer_;
  std::size_t used_ = 0;
  std::uint64_t faces_expected_ = 0, faces_ = 0, bytes_ = 0;
};

}  // namespace petersen
