#pragma once
// Whole-file reads and writes, through zlib when the name ends in .gz.

#include <string>
#include <string_view>

namespace petersen {

/// The decompressed bytes of the file (zlib reads plain files as they are). Throws MeshError
/// naming the path when it cannot be opened or the compressed stream is corrupt.
std::string read_file_bytes(const std::string& path);

/// Writes the bytes, gzip-compressed when the path ends in .gz. Throws MeshError on failure.
void write_file_bytes(const std::string& path, std::string_view bytes);

/// True when the path ends in `suffix`, ignoring ASCII case.
bool ends_with_nocase(std::string_view path, std::string_view suffix);

}  // namespace petersen
