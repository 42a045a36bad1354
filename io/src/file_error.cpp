#include "petersen/io/file_error.hpp"

namespace petersen {

namespace {

// "file:line: what", or "file: what" without a line. Built by appends: GCC 12 gives a false
// -Wrestrict on chains of operator+ of strings.
std::string located(const std::string& file, std::size_t line, const std::string& what) {
  std::string message = file;
  if (line > 0) message.append(":").append(std::to_string(line));
  message.append(": ").append(what);
  return message;
}

}  // namespace

FileError::FileError(const std::string& file, std::size_t line, const std::string& what)
    : std::runtime_error(located(file, line, what)), file_size_(file.size()), line_(line) {}

}  // namespace petersen
