#include "isolated_run.hpp"

#include <malloc.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <string>

#include "memory_pool.hpp"
#include "verification_error.hpp"

namespace petersen::bench {

namespace {

// A field of /proc/self/status in bytes (the file gives kB), or -1 when absent.
std::int64_t status_bytes(const char* field) {
  std::ifstream status("/proc/self/status");
  std::string line;
  const std::size_t length = std::strlen(field);
  while (std::getline(status, line)) {
    if (line.compare(0, length, field) == 0 && line.size() > length && line[length] == ':') {
      return std::stoll(line.substr(length + 1)) * 1024;
    }
  }
  return -1;
}

[[noreturn]] void child(const std::function<Measures()>& body, int out) {
  RunRecord record;
  // Free heap pages inherited from the parent would hide the run's allocations: give them back.
  malloc_trim(0);
  const std::int64_t rss_before = status_bytes("VmRSS");
  { std::ofstream("/proc/self/clear_refs") << "5"; }
  try {
    record.measures = body();
  } catch (const VerificationError& e) {
    record.status = RunRecord::Status::invalid_matching;
    set_message(record, e.what());
  } catch (const std::exception& e) {
    record.status = RunRecord::Status::error;
    set_message(record, e.what());
  }
  record.peak_extra_bytes = status_bytes("VmHWM") - rss_before;
  const char* bytes = reinterpret_cast<const char*>(&record);
  std::size_t written = 0;
  while (written < sizeof record) {
    const ssize_t n = write(out, bytes + written, sizeof record - written);
    if (n <= 0) _exit(2);
    written += static_cast<std::size_t>(n);
  }
  _exit(0);
}

}  // namespace

void set_message(RunRecord& record, const char* text) {
  std::snprintf(record.message, sizeof record.message, "%s", text);
}

RunRecord run_isolated(const std::function<Measures()>& body, double cap_seconds) {
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    close(fds[0]);
    bench::drop_inherited_pool();
    child(body, fds[1]);
  }
  close(fds[1]);

  RunRecord record;
  char* bytes = reinterpret_cast<char*>(&record);
  std::size_t received = 0;
  const auto deadline =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(cap_seconds);
  bool timed_out = false;
  while (received < sizeof record) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) {
      timed_out = true;
      break;
    }
    pollfd waiting{fds[0], POLLIN, 0};
    if (poll(&waiting, 1, static_cast<int>(left.count())) <= 0) continue;
    const ssize_t n = read(fds[0], bytes + received, sizeof record - received);
    if (n <= 0) break;  // the child closed the pipe without a full record
    received += static_cast<std::size_t>(n);
  }
  close(fds[0]);
  if (timed_out) kill(pid, SIGKILL);
  int wait_status = 0;
  waitpid(pid, &wait_status, 0);
  if (timed_out) {
    record = RunRecord{};
    record.status = RunRecord::Status::timeout;
  } else if (received < sizeof record) {
    record = RunRecord{};
    record.status = RunRecord::Status::crashed;
    const std::string what = WIFSIGNALED(wait_status)
                                 ? "killed by signal " + std::to_string(WTERMSIG(wait_status))
                                 : "exited with " + std::to_string(WEXITSTATUS(wait_status));
    set_message(record, what.c_str());
  }
  return record;
}

}  // namespace petersen::bench
