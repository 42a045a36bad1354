// PlyTriangleStream and PlyStreamWriter (ply_stream.hpp).

#include "petersen/io/ply_stream.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <bit>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "petersen/io/file_error.hpp"
#include "ply_header.hpp"
#include "ply_types.hpp"
#include "temporary_file.hpp"

namespace petersen {

namespace {

constexpr std::size_t kPage = 4096;

std::uint64_t read_little(const char* p, std::size_t bytes) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < bytes; ++i) value |= std::uint64_t(std::uint8_t(p[i])) << (8 * i);
  return value;
}

// Checks that the header is one PlyTriangleStream takes; returns the vertex record's bytes.
std::size_t check_layout(const ply::Header& header, const std::string& path) {
  auto refuse = [&](const std::string& what) {
    throw FileError(path, 0,
                    what +
                        ": the out-of-core conversion reads binary little-endian PLY with a "
                        "vertex element of scalars, then a face element of one 32-bit "
                        "vertex_indices list, and nothing else");
  };
  if (header.encoding != ply::Encoding::little) refuse("not binary little-endian");
  if (header.elements.size() != 2 || header.elements[0].role != ply::Role::vertex ||
      header.elements[1].role != ply::Role::face) {
    refuse("other elements than vertex and face, or face first");
  }
  std::size_t bytes = 0;
  for (const ply::Property& p : header.elements[0].properties) {
    if (p.is_list) refuse("vertex property " + p.name + " is a list");
    bytes += ply::size_of(p.type);
  }
  const std::vector<ply::Property>& face = header.elements[1].properties;
  if (face.size() != 1 || !face[0].is_list || ply::size_of(face[0].type) != 4) {
    refuse("face properties besides a 32-bit vertex_indices list");
  }
  return bytes;
}

// A scalar of the file as a double: every PLY type converts exactly.
double scalar_at(const char* p, ScalarType type) {
  switch (type) {
    case ScalarType::int8:
      return double(std::int8_t(p[0]));
    case ScalarType::uint8:
      return double(std::uint8_t(p[0]));
    case ScalarType::int16:
      return double(std::int16_t(read_little(p, 2)));
    case ScalarType::uint16:
      return double(read_little(p, 2));
    case ScalarType::int32:
      return double(std::int32_t(read_little(p, 4)));
    case ScalarType::uint32:
      return double(read_little(p, 4));
    case ScalarType::float32:
      return double(std::bit_cast<float>(std::uint32_t(read_little(p, 4))));
    case ScalarType::float64:
      return std::bit_cast<double>(read_little(p, 8));
  }
  return 0;
}

std::string declaration_of(const ply::Element& vertex) {
  std::string text = "element vertex " + std::to_string(vertex.count) + "\n";
  for (const ply::Property& p : vertex.properties) {
    text.append("property ").append(ply::type_name(p.type)).append(" ").append(p.name) += '\n';
  }
  return text;
}

}  // namespace

std::string PlyTriangleStream::vertex_declaration(std::uint64_t count) const {
  const std::size_t line_end = vertex_declaration_.find('\n');
  return "element vertex " + std::to_string(count) + vertex_declaration_.substr(line_end);
}

void PlyTriangleStream::append_blended_record(std::span<const VertexId> ids,
                                              std::string& out) const {
  std::size_t offset = 0;
  char bytes[8];
  for (const std::uint8_t t : property_types_) {
    const auto type = ScalarType(t);
    double sum = 0;
    for (VertexId v : ids)
      sum += scalar_at(bytes_ + vertex_start_ + v * vertex_bytes_ + offset, type);
    const double mean = sum / double(ids.size());
    const double whole = std::round(mean);
    auto put = [&](auto value) {
      std::memcpy(bytes, &value, sizeof value);  // little-endian, as check_layout requires
      out.append(bytes, sizeof value);
    };
    switch (type) {
      case ScalarType::int8:
        put(std::int8_t(whole));
        break;
      case ScalarType::uint8:
        put(std::uint8_t(whole));
        break;
      case ScalarType::int16:
        put(std::int16_t(whole));
        break;
      case ScalarType::uint16:
        put(std::uint16_t(whole));
        break;
      case ScalarType::int32:
        put(std::int32_t(whole));
        break;
      case ScalarType::uint32:
        put(std::uint32_t(whole));
        break;
      case ScalarType::float32:
        put(float(mean));
        break;
      case ScalarType::float64:
        put(mean);
        break;
    }
    offset += ply::size_of(type);
  }
}

PlyTriangleStream::PlyTriangleStream(const std::string& path) : path_(path) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) io_detail::fail(path, "cannot open for reading", errno);
  struct stat status;
  if (::fstat(fd, &status) != 0 || !S_ISREG(status.st_mode) || status.st_size == 0) {
    ::close(fd);
    throw FileError(path, 0, "not a regular, non-empty file");
  }
  size_ = static_cast<std::size_t>(status.st_size);
  void* pages = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, fd, 0);
  ::close(fd);
  if (pages == MAP_FAILED) io_detail::fail(path, "cannot map", errno);
  bytes_ = static_cast<const char*>(pages);
  ::madvise(pages, size_, MADV_SEQUENTIAL);
  if (size_ >= 2 && std::uint8_t(bytes_[0]) == 0x1f && std::uint8_t(bytes_[1]) == 0x8b) {
    throw FileError(path, 0, "gzip-compressed: the out-of-core conversion reads plain files");
  }
  text::Lines lines{std::string_view(bytes_, size_)};
  std::vector<std::string> dropped;
  const ply::Header header = ply::read_header(lines, path, dropped);
  vertex_bytes_ = check_layout(header, path);
  vertex_count_ = header.elements[0].count;
  face_count_ = header.elements[1].count;
  count_bytes_ = ply::size_of(header.elements[1].properties[0].count_type);
  face_bytes_ = count_bytes_ + 12;
  vertex_start_ = lines.pos;
  face_start_ = vertex_start_ + vertex_count_ * vertex_bytes_;
  vertex_declaration_ = declaration_of(header.elements[0]);
  xyz_offset_.fill(SIZE_MAX);
  std::size_t offset = 0;
  for (const ply::Property& p : header.elements[0].properties) {
    property_types_.push_back(static_cast<std::uint8_t>(p.type));
    for (int k = 0; k < 3; ++k) {
      if (p.name == std::string(1, char('x' + k))) {
        xyz_offset_[k] = offset;
        xyz_type_[k] = static_cast<std::uint8_t>(p.type);
      }
    }
    offset += ply::size_of(p.type);
  }
  if (face_start_ + face_count_ * face_bytes_ > size_) {
    throw FileError(path, 0,
                    "shorter than its header says (" + std::to_string(size_) + " bytes; " +
                        std::to_string(vertex_count_) + " vertices and " +
                        std::to_string(face_count_) + " triangles need " +
                        std::to_string(face_start_ + face_count_ * face_bytes_) + ")");
  }
}

PlyTriangleStream::~PlyTriangleStream() {
  ::munmap(const_cast<char*>(bytes_), size_);
}

void PlyTriangleStream::read_faces(std::uint64_t first, std::uint64_t count,
                                   std::span<VertexId> corners) const {
  const char* record = bytes_ + face_start_ + first * face_bytes_;
  for (std::uint64_t i = 0; i < count; ++i, record += face_bytes_) {
    const std::uint64_t arity = read_little(record, count_bytes_);
    if (arity != 3) {
      throw FileError(path_, 0,
                      "face " + std::to_string(first + i) + " (byte " +
                          std::to_string(record - bytes_) + ") has " + std::to_string(arity) +
                          " corners: the out-of-core conversion takes triangles only");
    }
    for (int k = 0; k < 3; ++k) {
      const std::uint64_t v = read_little(record + count_bytes_ + 4 * k, 4);
      if (v >= vertex_count_) {
        throw FileError(path_, 0,
                        "face " + std::to_string(first + i) + " (byte " +
                            std::to_string(record - bytes_) + ") names vertex " +
                            std::to_string(std::int32_t(std::uint32_t(v))) + ", out of range (" +
                            std::to_string(vertex_count_) + " vertices)");
      }
      corners[3 * i + k] = static_cast<VertexId>(v);
    }
  }
}

void PlyTriangleStream::read_positions(std::span<const VertexId> ids,
                                       std::span<std::array<double, 3>> positions) const {
  for (int k = 0; k < 3; ++k) {
    if (xyz_offset_[k] == SIZE_MAX) {
      throw FileError(path_, 0, std::string("the vertex element has no property ") + char('x' + k));
    }
  }
  for (std::size_t i = 0; i < ids.size(); ++i) {
    const char* record = bytes_ + vertex_start_ + std::size_t{ids[i]} * vertex_bytes_;
    for (int k = 0; k < 3; ++k) {
      positions[i][k] = scalar_at(record + xyz_offset_[k], ScalarType(xyz_type_[k]));
    }
  }
}

std::string_view PlyTriangleStream::vertex_records(std::uint64_t first, std::uint64_t count) const {
  return {bytes_ + vertex_start_ + first * vertex_bytes_, count * vertex_bytes_};
}

void PlyTriangleStream::release_faces(std::uint64_t first, std::uint64_t count) const {
  release(face_start_ + first * face_bytes_, face_start_ + (first + count) * face_bytes_);
}

void PlyTriangleStream::release_vertices(std::uint64_t first, std::uint64_t count) const {
  release(vertex_start_ + first * vertex_bytes_, vertex_start_ + (first + count) * vertex_bytes_);
}

// The pages are the file's, unmodified: dropped from the process, read again if touched again.
void PlyTriangleStream::release(std::size_t begin, std::size_t end) const {
  begin = begin / kPage * kPage;
  end = std::min(size_, (end + kPage - 1) / kPage * kPage);
  if (end > begin) ::madvise(const_cast<char*>(bytes_) + begin, end - begin, MADV_DONTNEED);
}

struct PlyStreamWriter::File {
  io_detail::TemporaryFile file;
};

namespace {
// Whole buffers are written past the page cache (TemporaryFile::write): 64 MiB, aligned.
constexpr std::size_t kWriteBuffer = std::size_t{64} << 20;
}  // namespace

PlyStreamWriter::PlyStreamWriter(const std::string& path, const std::string& vertex_declaration,
                                 std::uint64_t face_count)
    : file_(new File{io_detail::TemporaryFile(path)}),
      path_(path),
      buffer_(make_raw_array<char>(kWriteBuffer)),
      faces_expected_(face_count) {
  put("ply\nformat binary_little_endian 1.0\ncomment petersen quads\n" + vertex_declaration +
      "element face " + std::to_string(face_count) +
      "\nproperty list uchar int vertex_indices\nend_header\n");
}

PlyStreamWriter::~PlyStreamWriter() = default;

void PlyStreamWriter::put(std::string_view bytes) {
  while (!bytes.empty()) {
    const std::size_t n = std::min(bytes.size(), kWriteBuffer - used_);
    std::memcpy(buffer_.get() + used_, bytes.data(), n);
    used_ += n;
    bytes.remove_prefix(n);
    if (used_ == kWriteBuffer) flush();
  }
}

void PlyStreamWriter::flush() {
  file_->file.write({buffer_.get(), used_});
  bytes_ += used_;
  used_ = 0;
}

template <std::size_t N>
void PlyStreamWriter::write_face(const VertexId (&corners)[N]) {
  char record[1 + 4 * N];
  record[0] = static_cast<char>(N);
  for (std::size_t k = 0; k < N; ++k) {
    for (int b = 0; b < 4; ++b) record[1 + 4 * k + b] = static_cast<char>(corners[k] >> (8 * b));
  }
  if (kWriteBuffer - used_ < sizeof record) flush();
  std::memcpy(buffer_.get() + used_, record, sizeof record);
  used_ += sizeof record;
  ++faces_;
}

void PlyStreamWriter::write_triangle(VertexId a, VertexId b, VertexId c) {
  const VertexId corners[3] = {a, b, c};
  write_face(corners);
}

void PlyStreamWriter::write_quad(VertexId a, VertexId b, VertexId c, VertexId d) {
  const VertexId corners[4] = {a, b, c, d};
  write_face(corners);
}

void PlyStreamWriter::commit() {
  if (faces_ != faces_expected_) {
    throw FileError(path_, 0,
                    "internal error: " + std::to_string(faces_) +
                        " faces written, the header says " + std::to_string(faces_expected_));
  }
  flush();
  file_->file.commit();
}

}  // namespace petersen
