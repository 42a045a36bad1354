#pragma once
// An array of face ids in a temporary file beside the output, mapped: the out-of-core
// conversion's pairing, 4 bytes per triangle, held on disk rather than in memory.

#include <cstdint>
#include <string>

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

}  // namespace petersen::partition_detail
