#include "file_bytes.hpp"

#include <zlib.h>

#include <cstdio>
#include <memory>

#include "petersen/dualize/mesh.hpp"

namespace petersen {

namespace {

struct GzCloser {
  void operator()(gzFile file) const { gzclose(file); }
};
using GzHandle = std::unique_ptr<gzFile_s, GzCloser>;

std::string gz_error(gzFile file) {
  int code = 0;
  const char* message = gzerror(file, &code);
  return message ? message : "unknown zlib error";
}

// The size the file will likely decompress to: the gzip trailer's ISIZE (the size mod 2^32),
// capped by deflate's best ratio so a forged trailer cannot make us allocate absurdly; the plain
// size for other files. Only a hint: the read loop grows the buffer when it is wrong.
std::size_t expected_size(const std::string& path) {
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "rb"),
                                                       &std::fclose);
  if (!file || std::fseek(file.get(), 0, SEEK_END) != 0) return 0;
  const long size = std::ftell(file.get());
  unsigned char magic[2] = {0, 0}, trailer[4] = {0, 0, 0, 0};
  if (size < 18 || std::fseek(file.get(), 0, SEEK_SET) != 0 ||
      std::fread(magic, 1, 2, file.get()) != 2 || magic[0] != 0x1f || magic[1] != 0x8b) {
    return size > 0 ? static_cast<std::size_t>(size) : 0;
  }
  if (std::fseek(file.get(), size - 4, SEEK_SET) != 0 ||
      std::fread(trailer, 1, 4, file.get()) != 4) {
    return 0;
  }
  const std::size_t isize =
      trailer[0] | trailer[1] << 8 | trailer[2] << 16 | static_cast<std::size_t>(trailer[3]) << 24;
  return std::min(isize, static_cast<std::size_t>(size) * 1032);
}

}  // namespace

bool ends_with_nocase(std::string_view path, std::string_view suffix) {
  if (path.size() < suffix.size()) return false;
  path.remove_prefix(path.size() - suffix.size());
  for (std::size_t i = 0; i < suffix.size(); ++i) {
    const char c = path[i] >= 'A' && path[i] <= 'Z' ? char(path[i] - 'A' + 'a') : path[i];
    if (c != suffix[i]) return false;
  }
  return true;
}

std::string read_file_bytes(const std::string& path) {
  GzHandle file(gzopen(path.c_str(), "rb"));
  if (!file) throw MeshError(path + ": cannot open for reading");
  gzbuffer(file.get(), 1 << 18);
  // One byte past the expected size lets the read that sees the end need no growth.
  std::string bytes(expected_size(path) + 1, '\0');
  std::size_t size = 0;
  for (;;) {
    if (size == bytes.size()) bytes.resize(bytes.size() * 2);
    const std::size_t want = std::min<std::size_t>(bytes.size() - size, 1u << 30);
    const int got = gzread(file.get(), bytes.data() + size, static_cast<unsigned>(want));
    if (got < 0) throw MeshError(path + ": read failed: " + gz_error(file.get()));
    if (got == 0) break;
    size += static_cast<std::size_t>(got);
  }
  bytes.resize(size);
  return bytes;
}

void write_file_bytes(const std::string& path, std::string_view bytes) {
  if (ends_with_nocase(path, ".gz")) {
    GzHandle file(gzopen(path.c_str(), "wb6"));
    if (!file) throw MeshError(path + ": cannot open for writing");
    while (!bytes.empty()) {
      const std::size_t chunk = std::min<std::size_t>(bytes.size(), 1u << 30);
      if (gzwrite(file.get(), bytes.data(), static_cast<unsigned>(chunk)) <= 0) {
        throw MeshError(path + ": write failed: " + gz_error(file.get()));
      }
      bytes.remove_prefix(chunk);
    }
    if (gzclose(file.release()) != Z_OK) throw MeshError(path + ": write failed on close");
    return;
  }
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path.c_str(), "wb"),
                                                       &std::fclose);
  if (!file) throw MeshError(path + ": cannot open for writing");
  if (std::fwrite(bytes.data(), 1, bytes.size(), file.get()) != bytes.size() ||
      std::fclose(file.release()) != 0) {
    throw MeshError(path + ": write failed");
  }
}

}  // namespace petersen
