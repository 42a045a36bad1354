#pragma once
// Whole-file reads and atomic whole-file writes, gzip through libdeflate.

#include <memory>
#include <string>
#include <string_view>

#include "petersen/graph/memory.hpp"
#include "petersen/io/file_error.hpp"

namespace petersen {

/// The pages of a file mapped read-only, unmapped with it.
struct Unmap {
  std::size_t size = 0;
  void operator()(const char* bytes) const;
};
using MappedBytes = std::unique_ptr<const char, Unmap>;

/// A file's bytes: a regular file's mapped from the page cache, read-only; a decompressed or
/// piped file's in an uninitialised buffer (a multi-gigabyte file is not zero-filled first).
struct FileBytes {
  RawArray<char> data;  // empty when mapped
  std::size_t size = 0;
  MappedBytes mapped;

  std::string_view view() const { return {mapped ? mapped.get() : data.get(), size}; }
};

/// The file's bytes, decompressed when they start with the gzip magic (any name; concatenated
/// gzip members are decompressed one after the other, trailing zero bytes ignored). Throws
/// FileError naming the path when the file cannot be opened or read, when the gzip data is
/// corrupt, or when it would decompress beyond deflate's largest ratio (1032:1) or the machine's
/// physical memory. A regular file is mapped, not copied: like any reader of a mapped file, the
/// process is killed (SIGBUS) if another truncates the file while it is being read.
/// O(decompressed size).
/// A buffer is allocated from `memory`.
FileBytes read_file_bytes(const std::string& path,
                          std::pmr::memory_resource* memory = std::pmr::get_default_resource());

/// Writes the bytes to `path` atomically, gzip-compressed when the path ends in .gz: into a new
/// temporary file in the same folder, flushed to disk, then renamed over `path`. On any failure
/// the temporary file is removed, an existing file at `path` is left untouched, and FileError
/// names the path. A new file gets the usual permissions (0666 less the umask), a replaced file
/// keeps its own.
void write_file_bytes(const std::string& path, std::string_view bytes);

/// True when the path ends in `suffix`, ignoring ASCII case.
bool ends_with_nocase(std::string_view path, std::string_view suffix);

}  // namespace petersen
