#pragma once
// Output files written whole or not at all.

#include <string>
#include <string_view>

namespace petersen::cli {

/// Writes `bytes` to a new temporary file in `path`'s folder, then renames it onto `path`: a
/// failed or killed run leaves no partial file, and an existing `path` is replaced only by a
/// complete one. Throws std::runtime_error naming the path (the temporary file is removed).
void write_file_atomically(const std::string& path, std::string_view bytes);

}  // namespace petersen::cli
