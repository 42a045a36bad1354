#pragma once
// JSON text for the --stats-json files, and their atomic write.

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>

#include "petersen/io/file_bytes.hpp"

namespace petersen::cli {

/// `s` as a JSON string literal, quotes and escapes included.
inline std::string json_string(const std::string& s) {
  std::string out = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof escaped, "\\u%04x", static_cast<unsigned>(c));
      out += escaped;
    } else {
      out += c;
    }
  }
  return out + "\"";
}

/// Writes to `path` what print(FILE*) prints, atomically (write_file_bytes): a run that fails
/// leaves no half-written file, and a file already there stays whole. Throws FileError naming
/// the path when it cannot be written.
template <class Print>
void write_printed(const std::string& path, Print print) {
  char* buffer = nullptr;
  std::size_t size = 0;
  {
    std::unique_ptr<std::FILE, int (*)(std::FILE*)> out(open_memstream(&buffer, &size),
                                                        &std::fclose);
    if (!out) throw std::runtime_error("cannot hold the text of " + path + " in memory");
    print(out.get());
  }  // closed: buffer and size are final
  const std::unique_ptr<char, void (*)(void*)> owned(buffer, &std::free);
  write_file_bytes(path, {buffer, size});
}

}  // namespace petersen::cli
