#pragma once
// The byte buffer the writers fill before writing a file at once.

#include <algorithm>
#include <bit>
#include <charconv>
#include <cstring>
#include <string>
#include <string_view>
#include <vector>

#include "petersen/graph/memory.hpp"
#include "petersen/io/file_error.hpp"
#include "petersen/mesh/mesh.hpp"

namespace petersen {

// The file's bytes, built in memory and written at once. The plain writers size it from an upper
// bound of the output (every number at its longest), so it never grows and is never filled
// first; on the default memory resource, where a program's pool recycles the meshes' arrays
// (petersen/graph/memory.hpp).
class Buffer {
 public:
  explicit Buffer(std::size_t bound)
      : data_(make_raw_array<char>(bound)), end_(data_.get()), capacity_(bound) {}

  /// Makes room for `more` bytes, for writers that cannot bound their output up front (names of
  /// any length): doubles the buffer when it must grow.
  void ensure(std::size_t more) {
    const std::size_t used = static_cast<std::size_t>(end_ - data_.get());
    if (capacity_ - used >= more) return;
    const std::size_t capacity = std::max(2 * capacity_, used + more);
    RawArray<char> grown = make_raw_array<char>(capacity);
    std::memcpy(grown.get(), data_.get(), used);
    data_ = std::move(grown);
    end_ = data_.get() + used;
    capacity_ = capacity;
  }

  std::string_view view() const { return {data_.get(), std::size_t(end_ - data_.get())}; }
  void word(std::string_view s) {
    std::memcpy(end_, s.data(), s.size());
    end_ += s.size();
  }
  void put(char c) { *end_++ = c; }
  // std::to_chars: the shortest text that reads back as the same double, no locale.
  template <typename T>
  void number(T x) {
    end_ = std::to_chars(end_, end_ + kLongestNumber, x).ptr;
  }
  /// A number of a float property in text: never written as a whole number ("1" becomes "1.0"),
  /// so that a reader that tells integer colours from real ones reads the same type back.
  void real(double x) {
    char* const start = end_;
    number(x);
    if (std::string_view(start, std::size_t(end_ - start)).find_first_of(".en") ==
        std::string_view::npos) {
      word(".0");
    }
  }
  template <typename T>
  void binary(const T* values, std::size_t count) {
    static_assert(std::endian::native == std::endian::little,
                  "binary PLY writing assumes a little-endian host");
    std::memcpy(end_, values, count * sizeof(T));
    end_ += count * sizeof(T);
  }

  // "-2.2250738585072014e-308" is 24 characters; a 64-bit integer has at most 20 digits.
  static constexpr std::size_t kLongestNumber = 24;

 private:
  RawArray<char> data_;
  char* end_;
  std::size_t capacity_;
};

/// The writers of meshes with attributes (write_attributes.cpp): the file's bytes, and one line
/// per kind of thing the format has no place for appended to `dropped`. Each expects a mesh that
/// passed check_attributes, and throws FileError naming `path` for a value or name the format
/// cannot spell.
Buffer off_with_attributes(const PolygonMesh& mesh, const std::string& path,
                           std::vector<std::string>& dropped);
Buffer obj_with_attributes(const PolygonMesh& mesh, const std::string& path,
                           std::vector<std::string>& dropped);
Buffer ply_with_attributes(const PolygonMesh& mesh, const std::string& path,
                           std::vector<std::string>& dropped);

}  // namespace petersen
