#pragma once
// Temporary files beside the output, so that the out-of-core conversion holds on disk what it
// does not need in memory: the pairing (TempFaceArray, mapped, 4 bytes per triangle) and what a
// step leaves for a later one (TempRecords, appended, then read back whole).

#include <cstdint>
#include <memory_resource>
#include <span>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "petersen/mesh/mesh.hpp"

namespace petersen::partition_detail {

/// `size` face ids (zero until written), in an unnamed file in the folder of `beside` (removed by
/// the system when the array is destroyed, however the process ends; a file system without
/// unnamed files gets a named one, unlinked at once). Throws FileError naming `beside`.
class TempFaceArray {
 public:
  TempFaceArray(const std::string& beside, std::uint64_t size);
  ~TempFaceArray();
  TempFaceArray(const TempFaceArray&) = delete;
  TempFaceArray& operator=(const TempFaceArray&) = delete;

  FaceId& operator[](std::uint64_t i) { return data_[i]; }
  FaceId operator[](std::uint64_t i) const { return data_[i]; }
  std::uint64_t bytes() const { return size_ * sizeof(FaceId); }
  /// Writes entries first..first+count-1 back to the file and drops their pages from the process.
  void release(std::uint64_t first, std::uint64_t count);

 private:
  FaceId* data_ = nullptr;
  std::uint64_t size_ = 0;
  int fd_ = -1;
};

/// Bytes appended to an unnamed temporary file in the folder of `beside` (as TempFaceArray's) and
/// read back. They pass through the page cache, never the process's own memory. Throws FileError
/// naming `beside`.
class TempByteFile {
 public:
  explicit TempByteFile(const std::string& beside);
  ~TempByteFile();
  TempByteFile(TempByteFile&& other) noexcept
      : beside_(std::move(other.beside_)),
        fd_(std::exchange(other.fd_, -1)),
        bytes_(std::exchange(other.bytes_, 0)) {}
  TempByteFile& operator=(TempByteFile&&) = delete;

  void append(const void* bytes, std::uint64_t count);
  /// Copies bytes offset..offset+count-1 into `into`; drops them from the page cache.
  void read(std::uint64_t offset, std::uint64_t count, void* into) const;
  std::uint64_t bytes() const { return bytes_; }

 private:
  std::string beside_;
  int fd_ = -1;
  std::uint64_t bytes_ = 0;
};

/// Records of a trivially copyable type, appended and read back whole in the order appended.
template <class T>
class TempRecords {
  static_assert(std::is_trivially_copyable_v<T>);

 public:
  explicit TempRecords(const std::string& beside) : file_(beside) {}
  void append(std::span<const T> records) { file_.append(records.data(), records.size_bytes()); }
  std::uint64_t size() const { return file_.bytes() / sizeof(T); }
  std::uint64_t bytes() const { return file_.bytes(); }
  void read_all(std::pmr::vector<T>& into) const {
    into.resize(size());
    file_.read(0, file_.bytes(), into.data());
  }

 private:
  TempByteFile file_;
};

}  // namespace petersen::partition_detail
