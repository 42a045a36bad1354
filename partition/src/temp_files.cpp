#include "temp_files.hpp"

#include <fcntl.h>
#include <sys/mman.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "petersen/io/file_error.hpp"

namespace petersen::partition_detail {

namespace {

[[noreturn]] void fail(const std::string& beside, const std::string& what) {
  throw FileError(beside, 0, what + ": " + std::generic_category().message(errno));
}

int open_unnamed(const std::string& beside) {
  const std::filesystem::path folder = std::filesystem::path(beside).parent_path();
  const std::string dir = folder.empty() ? "." : folder.string();
  int fd = ::open(dir.c_str(), O_TMPFILE | O_RDWR | O_CLOEXEC, 0600);
  if (fd >= 0) return fd;
  std::string name = dir + "/.petersen-temporary-XXXXXX";
  fd = ::mkostemp(name.data(), O_CLOEXEC);
  if (fd < 0) fail(beside, "cannot create a temporary file in its folder");
  ::unlink(name.c_str());
  return fd;
}

}  // namespace

TempFaceArray::TempFaceArray(const std::string& beside, std::uint64_t size) : size_(size) {
  fd_ = open_unnamed(beside);
  const std::size_t bytes = std::max<std::size_t>(size * sizeof(FaceId), 1);
  if (::ftruncate(fd_, static_cast<off_t>(bytes)) != 0) {
    ::close(fd_);
    fail(beside, "cannot size a temporary file of " + std::to_string(bytes) + " bytes");
  }
  void* pages = ::mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, 0);
  if (pages == MAP_FAILED) {
    ::close(fd_);
    fail(beside, "cannot map a temporary file");
  }
  data_ = static_cast<FaceId*>(pages);
}

TempFaceArray::~TempFaceArray() {
  ::munmap(data_, std::max<std::size_t>(size_ * sizeof(FaceId), 1));
  ::close(fd_);
}

void TempFaceArray::release(std::uint64_t first, std::uint64_t count) {
  constexpr std::uint64_t kPage = 4096;
  std::uint64_t begin = first * sizeof(FaceId), end = (first + count) * sizeof(FaceId);
  // Only whole pages: a page shared with a neighbouring range stays mapped.
  begin = (begin + kPage - 1) / kPage * kPage;
  end = end / kPage * kPage;
  if (end <= begin) return;
  char* base = reinterpret_cast<char*>(data_);
  ::msync(base + begin, end - begin, MS_ASYNC);
  ::madvise(base + begin, end - begin, MADV_DONTNEED);
}

TempByteFile::TempByteFile(const std::string& beside) : beside_(beside) {
  fd_ = open_unnamed(beside);
}

TempByteFile::~TempByteFile() {
  if (fd_ >= 0) ::close(fd_);
}

void TempByteFile::append(const void* bytes, std::uint64_t count) {
  const char* from = static_cast<const char*>(bytes);
  while (count > 0) {
    const ssize_t written = ::pwrite(fd_, from, count, static_cast<off_t>(bytes_));
    if (written < 0 && errno == EINTR) continue;
    if (written == 0) errno = ENOSPC;
    if (written <= 0) fail(beside_, "cannot write a temporary file");
    from += written;
    bytes_ += static_cast<std::uint64_t>(written);
    count -= static_cast<std::uint64_t>(written);
  }
}

void TempByteFile::read(std::uint64_t offset, std::uint64_t count, void* into) const {
  char* to = static_cast<char*>(into);
  const std::uint64_t first = offset;
  while (count > 0) {
    const ssize_t got = ::pread(fd_, to, count, static_cast<off_t>(offset));
    if (got < 0 && errno == EINTR) continue;
    if (got == 0) errno = EIO;
    if (got <= 0) fail(beside_, "cannot read back a temporary file");
    to += got;
    offset += static_cast<std::uint64_t>(got);
    count -= static_cast<std::uint64_t>(got);
  }
  ::posix_fadvise(fd_, static_cast<off_t>(first), static_cast<off_t>(offset - first),
                  POSIX_FADV_DONTNEED);
}

}  // namespace petersen::partition_detail
