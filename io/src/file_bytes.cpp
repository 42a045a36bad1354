#include "petersen/io/file_bytes.hpp"

#include <fcntl.h>
#include <libdeflate.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <memory>
#include <random>
#include <system_error>

#include "petersen/io/file_error.hpp"
#include "temporary_file.hpp"

namespace petersen {

namespace {

using io_detail::fail;
using io_detail::TemporaryFile;

// Closes the descriptor on every way out.
struct Descriptor {
  int fd = -1;
  Descriptor(int fd) : fd(fd) {}  // NOLINT: wraps open()'s result
  Descriptor(const Descriptor&) = delete;
  Descriptor& operator=(const Descriptor&) = delete;
  ~Descriptor() {
    if (fd >= 0) ::close(fd);
  }
};

FileBytes allocate(const std::string& path, std::size_t size, std::pmr::memory_resource* memory) {
  try {
    return {make_raw_array<char>(size, memory), 0, {}};
  } catch (const std::bad_alloc&) {
    throw FileError(path, 0, "cannot allocate " + std::to_string(size) + " bytes to read it");
  }
}

// A copy of the first `bytes.size` bytes in a buffer of `capacity` bytes.
FileBytes grown(const std::string& path, const FileBytes& bytes, std::size_t capacity) {
  std::pmr::memory_resource* const memory = bytes.data.get_deleter().memory;
  FileBytes larger = allocate(path, capacity, memory);
  std::memcpy(larger.data.get(), bytes.data.get(), bytes.size);
  larger.size = bytes.size;
  return larger;
}

// The bytes as they are on disk. A regular file's pages are mapped from the page cache rather
// than read into a buffer: a fresh buffer costs a page fault per page, and where the host fills
// fresh memory slowly (a virtual machine with free page reporting: 0.2-0.3 GB/s) reading a
// 2.5 GB file into one takes several times as long as mapping and scanning it. Read ahead in
// full (MAP_POPULATE): the parsers read every byte once, in order.
FileBytes read_raw(const std::string& path, std::pmr::memory_resource* memory) {
  Descriptor file(::open(path.c_str(), O_RDONLY | O_CLOEXEC));
  if (file.fd < 0) fail(path, "cannot open for reading", errno);
  struct stat status;
  if (::fstat(file.fd, &status) != 0) fail(path, "cannot read", errno);
  if (S_ISREG(status.st_mode) && status.st_size > 0) {
    const auto size = static_cast<std::size_t>(status.st_size);
    void* pages = ::mmap(nullptr, size, PROT_READ, MAP_PRIVATE | MAP_POPULATE, file.fd, 0);
    // A file system that cannot map files is read as a pipe is.
    if (pages != MAP_FAILED)
      return {{}, size, MappedBytes(static_cast<const char*>(pages), {size})};
  }
  // A regular file's size is known; a pipe's is found by reading (one byte more lets the read
  // that sees the end need no growth).
  std::size_t capacity =
      (S_ISREG(status.st_mode) ? static_cast<std::size_t>(status.st_size) : 1 << 20) + 1;
  FileBytes bytes = allocate(path, capacity, memory);
  for (;;) {
    if (bytes.size == capacity) {
      capacity *= 2;
      bytes = grown(path, bytes, capacity);
    }
    const ssize_t got = ::read(file.fd, bytes.data.get() + bytes.size,
                               std::min<std::size_t>(capacity - bytes.size, 1 << 30));
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) fail(path, "cannot read", errno);
    if (got == 0) return bytes;
    bytes.size += static_cast<std::size_t>(got);
  }
}

bool is_gzip(std::string_view bytes) {
  return bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
         static_cast<unsigned char>(bytes[1]) == 0x8b;
}

std::size_t physical_memory() {
  const long pages = ::sysconf(_SC_PHYS_PAGES), page = ::sysconf(_SC_PAGESIZE);
  return pages > 0 && page > 0 ? static_cast<std::size_t>(pages) * static_cast<std::size_t>(page)
                               : SIZE_MAX;
}

struct DecompressorFree {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};
struct CompressorFree {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

// Deflate's largest ratio: a 258-byte match costs at least 2 bits, so 1032 output bytes per input
// byte; more output than that from a stream means a corrupt or hostile file.
constexpr std::size_t kDeflateMaxRatio = 1032;

// libdeflate decompresses whole members into a buffer of known size, in about half the time of
// zlib's gzread (armadillo-sub2: 20 MB gzip, 26 MB PLY).
FileBytes gunzip(const std::string& path, std::string_view in, std::pmr::memory_resource* memory) {
  const std::size_t limit = std::min(in.size() * kDeflateMaxRatio, physical_memory());
  // The last member's trailer holds its size mod 2^32 (exact for the usual single member); below
  // the compressed size it has wrapped, or the file has several members.
  std::size_t capacity = 0;
  if (in.size() >= 18) {  // the smallest gzip member
    const auto* trailer = reinterpret_cast<const unsigned char*>(in.data() + in.size() - 4);
    capacity = trailer[0] | trailer[1] << 8 | trailer[2] << 16 |
               static_cast<std::size_t>(trailer[3]) << 24;
  }
  while (capacity < in.size() && capacity + (std::size_t{1} << 32) <= limit) {
    capacity += std::size_t{1} << 32;
  }
  capacity = std::min(capacity, limit);
  FileBytes out = allocate(path, capacity, memory);
  std::unique_ptr<libdeflate_decompressor, DecompressorFree> decompressor(
      libdeflate_alloc_decompressor());
  if (!decompressor) throw FileError(path, 0, "cannot allocate a gzip decompressor");
  std::size_t pos = 0;
  while (pos < in.size()) {
    if (pos > 0 && !is_gzip(in.substr(pos))) {
      // gzip and zlib accept zero padding after the last member; anything else is damage.
      if (std::all_of(in.begin() + pos, in.end(), [](char c) { return c == 0; })) break;
      throw FileError(path, 0,
                      std::to_string(in.size() - pos) + " bytes after the gzip data, from byte " +
                          std::to_string(pos));
    }
    std::size_t used = 0, written = 0;
    const libdeflate_result result = libdeflate_gzip_decompress_ex(
        decompressor.get(), in.data() + pos, in.size() - pos, out.data.get() + out.size,
        capacity - out.size, &used, &written);
    if (result == LIBDEFLATE_INSUFFICIENT_SPACE) {
      // The member is decompressed again into a larger buffer: doubling bounds the waste.
      if (capacity == limit) {
        throw FileError(path, 0,
                        "decompresses to more than " + std::to_string(limit) + " bytes (" +
                            (limit == in.size() * kDeflateMaxRatio ? "deflate's largest ratio"
                                                                   : "the machine's memory") +
                            "): corrupt or not a mesh");
      }
      capacity = std::min(std::max<std::size_t>(2 * capacity, 1 << 16), limit);
      out = grown(path, out, capacity);
      continue;
    }
    if (result != LIBDEFLATE_SUCCESS) {
      throw FileError(path, 0,
                      "corrupt gzip data in the member starting at byte " + std::to_string(pos));
    }
    pos += used;
    out.size += written;
  }
  return out;
}

// Compressed in independent gzip members of this many input bytes: the output buffer stays
// small and the file stays one standard gzip stream for every reader (RFC 1952 members).
constexpr std::size_t kGzipMemberBytes = std::size_t{64} << 20;

// Level 6, zlib's default: libdeflate at 6 compresses a large PLY several times faster than zlib
// at 6, and smaller.
constexpr int kGzipLevel = 6;

void write_gzip(TemporaryFile& file, const std::string& path, std::string_view bytes) {
  std::unique_ptr<libdeflate_compressor, CompressorFree> compressor(
      libdeflate_alloc_compressor(kGzipLevel));
  if (!compressor) throw FileError(path, 0, "cannot allocate a gzip compressor");
  const std::size_t chunk = std::min(bytes.size(), kGzipMemberBytes);
  const std::size_t bound = libdeflate_gzip_compress_bound(compressor.get(), chunk);
  const RawArray<char> out = make_raw_array<char>(bound);
  do {
    const std::string_view member = bytes.substr(0, chunk);
    const std::size_t size =
        libdeflate_gzip_compress(compressor.get(), member.data(), member.size(), out.get(), bound);
    if (size == 0) throw FileError(path, 0, "gzip compression failed");
    file.write({out.get(), size});
    bytes.remove_prefix(member.size());
  } while (!bytes.empty());
}

}  // namespace

void Unmap::operator()(const char* bytes) const {
  ::munmap(const_cast<char*>(bytes), size);
}

bool ends_with_nocase(std::string_view path, std::string_view suffix) {
  if (path.size() < suffix.size()) return false;
  path.remove_prefix(path.size() - suffix.size());
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    const char c = path[i] >= 'A' && path[i] <= 'Z' ? char(path[i] - 'A' + 'a') : path[i];
    if (c != suffix[i]) return false;
  }
  return true;
}

FileBytes read_file_bytes(const std::string& path, std::pmr::memory_resource* memory) {
  FileBytes raw = read_raw(path, memory);
  if (!is_gzip(raw.view())) return raw;
  return gunzip(path, raw.view(), memory);
}

void write_file_bytes(const std::string& path, std::string_view bytes) {
  TemporaryFile file(path);
  if (ends_with_nocase(path, ".gz")) {
    write_gzip(file, path, bytes);
  } else {
    file.write(bytes);
  }
  file.commit();
}

}  // namespace petersen
