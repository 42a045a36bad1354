#pragma once
// The file layer's atomic writer: a temporary file beside the target, renamed over it on commit
// (write_file_bytes and the streamed PLY writer write through it).

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <string_view>
#include <system_error>

#include "petersen/io/file_error.hpp"

namespace petersen::io_detail {

[[noreturn]] inline void fail(const std::string& path, const std::string& what, int error) {
  throw FileError(path, 0, what + ": " + std::generic_category().message(error));
}

// A new file beside the target, renamed over it by commit(). Where the file system allows it
// (Linux's O_TMPFILE), the file has no name until commit() links it: a run killed while writing
// leaves nothing behind. Elsewhere it is created under a unique hidden name and removed unless
// committed.
class TemporaryFile {
 public:
  explicit TemporaryFile(const std::string& target) : target_(target) {
    const std::filesystem::path folder = std::filesystem::path(target).parent_path();
    // Mode 0666 in both cases, so that the umask applies as for any new file.
    fd_ = ::open(folder.empty() ? "." : folder.c_str(), O_TMPFILE | O_WRONLY | O_CLOEXEC, 0666);
    if (fd_ < 0 && errno != EOPNOTSUPP && errno != EISDIR && errno != EINVAL) {
      fail(target_, "cannot create a file in its folder", errno);
    }
    if (fd_ < 0) {
      create_named([&](const char* name) {
        fd_ = ::open(name, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        return fd_ >= 0;
      });
    }
    // A file that is replaced keeps its permissions.
    struct stat status;
    if (::stat(target.c_str(), &status) == 0 && S_ISREG(status.st_mode)) {
      ::fchmod(fd_, status.st_mode & 07777);
    }
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;
  ~TemporaryFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!committed_ && !path_.empty()) ::unlink(path_.c_str());
  }

  // A large write whose bytes start on a block boundary in memory and in the file goes past the
  // page cache (O_DIRECT), all but its last partial block: through the cache, each page of the
  // file is a fresh page of memory, which a host with free page reporting fills at 0.2-0.3 GB/s,
  // so that 2 GB written and flushed through the cache take about four times as long as direct.
  // Where the file system refuses direct writes, or the device wants larger blocks, the bytes go
  // through the cache.
  void write(std::string_view bytes) {
    if (bytes.size() >= kDirectMinBytes && offset_ % kDirectBlock == 0 &&
        reinterpret_cast<std::uintptr_t>(bytes.data()) % kDirectBlock == 0) {
      const int flags = ::fcntl(fd_, F_GETFL);
      if (flags >= 0 && ::fcntl(fd_, F_SETFL, flags | O_DIRECT) == 0) {
        bytes.remove_prefix(put(bytes.substr(0, bytes.size() / kDirectBlock * kDirectBlock), true));
        if (::fcntl(fd_, F_SETFL, flags) != 0) fail(target_, "write failed", errno);
      }
    }
    put(bytes, false);
  }

  // Flushed to disk before the rename, so a crash leaves the old file or the whole new one.
  void commit() {
    if (::fsync(fd_) != 0) fail(target_, "write failed", errno);
    if (path_.empty()) {
      // The unnamed file gets a name (through /proc: linking by descriptor needs privileges).
      const std::string self = "/proc/self/fd/" + std::to_string(fd_);
      create_named([&](const char* name) {
        return ::linkat(AT_FDCWD, self.c_str(), AT_FDCWD, name, AT_SYMLINK_FOLLOW) == 0;
      });
    }
    const int fd = fd_;
    fd_ = -1;
    if (::close(fd) != 0) fail(target_, "write failed", errno);
    if (::rename(path_.c_str(), target_.c_str()) != 0) fail(target_, "cannot replace", errno);
    committed_ = true;
  }

 private:
  // Makes path_ a new unique name beside the target, as mkstemp would, by create(name).
  template <class Create>
  void create_named(const Create& create) {
    const std::filesystem::path path(target_);
    std::random_device random;
    for (int attempt = 0;; ++attempt) {
      const std::uint64_t tag = std::uint64_t{random()} << 32 | random();
      char hex[17];
      std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(tag));
      // Built by appends: GCC 12 gives a false -Wrestrict on chains of operator+ here.
      std::string name(1, '.');
      name.append(path.filename().string()).append(".").append(hex).append(".tmp");
      const std::string candidate = (path.parent_path() / name).string();
      if (create(candidate.c_str())) {
        path_ = candidate;
        return;
      }
      if (errno != EEXIST || attempt == 100) {
        fail(target_, "cannot create a file in its folder", errno);
      }
    }
  }

  static constexpr std::size_t kDirectBlock = 4096;  // a multiple of every common logical block
  static constexpr std::size_t kDirectMinBytes = std::size_t{64} << 20;

  // Writes the bytes at the file's end; returns how many. `direct`: stops without failing at the
  // first refusal (EINVAL: alignment or support), leaving the rest to a write through the cache.
  std::size_t put(std::string_view bytes, bool direct) {
    std::size_t written = 0;
    while (written < bytes.size()) {
      const ssize_t put = ::write(fd_, bytes.data() + written,
                                  std::min<std::size_t>(bytes.size() - written, 1 << 30));
      if (put < 0 && errno == EINTR) continue;
      if (put < 0 && direct && errno == EINVAL) break;
      if (put < 0) fail(target_, "write failed", errno);
      written += static_cast<std::size_t>(put);
    }
    offset_ += written;
    return written;
  }

  std::string target_;
  std::string path_;  // empty while the file has no name
  int fd_ = -1;
  bool committed_ = false;
  std::size_t offset_ = 0;  // bytes written so far
};

}  // namespace petersen::io_detail
