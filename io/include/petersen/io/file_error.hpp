#pragma once
// The one exception petersen::io raises for a problem in a file, with the file and the line.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace petersen {

/// Raised by every reader and writer of petersen::io and by its file layer for a problem in a
/// file: one that cannot be opened, read, decompressed or written; a name whose format is
/// unknown; a header, line or record that does not parse or names what the file does not hold; a
/// value or name the format being written cannot spell. what() is "file:line: what" for a line of
/// a text file, "file: what" when there is no line (line() is 0: a binary PLY's records, whose
/// message names the element and the byte instead, or the file as a whole).
class FileError : public std::runtime_error {
 public:
  FileError(const std::string& file, std::size_t line, const std::string& what);

  /// The file as the caller named it (a path, or parse_mesh's and parse_graph's `source`); valid
  /// while the exception is.
  std::string_view file() const noexcept { return std::string_view(what(), file_size_); }
  /// The 1-based line of a text file the problem is on, 0 when there is none.
  std::size_t line() const noexcept { return line_; }

 private:
  std::size_t file_size_;
  std::size_t line_;
};

}  // namespace petersen
