#pragma once
// The hand-written tokenizer the text readers share: lines, whitespace-separated tokens, numbers
// by std::from_chars, and errors located at "source:line".

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>

#include "petersen/io/file_error.hpp"

namespace petersen::text {

/// Walks a buffer line by line; `line` is the 1-based number of the line last returned.
struct Lines {
  std::string_view text;
  std::size_t pos = 0;
  std::size_t line = 0;

  /// The next line without its terminator ("\n", "\r\n" or a lone "\r", as old Mac files end
  /// lines), or false at the end. A UTF-8 byte-order mark opening the text is skipped.
  bool next(std::string_view& out) {
    if (pos == 0 && text.substr(0, 3) == "\xEF\xBB\xBF") pos = 3;
    if (pos >= text.size()) return false;
    const char* begin = text.data() + pos;
    const void* nl = std::memchr(begin, '\n', text.size() - pos);
    std::size_t len = nl ? static_cast<const char*>(nl) - begin : text.size() - pos;
    // A '\r' before the '\n' other than just before it ends the line there (the line is in
    // cache: the second scan is cheap).
    if (const void* cr = std::memchr(begin, '\r', len);
        cr && static_cast<const char*>(cr) - begin + 1 < static_cast<std::ptrdiff_t>(len + !nl)) {
      len = static_cast<const char*>(cr) - begin;
      nl = cr;
    }
    pos += len + (nl ? 1 : 0);
    ++line;
    out = std::string_view(begin, len);
    if (!out.empty() && out.back() == '\r') out.remove_suffix(1);
    return true;
  }
  std::size_t remaining() const { return text.size() - pos; }
};

inline bool is_space(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}

/// Whitespace-separated tokens of one line.
struct Tokens {
  std::string_view rest;

  bool next(std::string_view& out) {
    std::size_t i = 0;
    while (i < rest.size() && is_space(rest[i])) ++i;
    std::size_t j = i;
    while (j < rest.size() && !is_space(rest[j])) ++j;
    out = rest.substr(i, j - i);
    rest.remove_prefix(j);
    return !out.empty();
  }
};

/// The line with a '#' comment removed.
inline std::string_view strip_comment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

/// A whole token as a finite double (a leading '+' is allowed); false otherwise.
inline bool parse_real(std::string_view token, double& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size() && std::isfinite(value);
}

/// A whole token as a signed integer; false otherwise (including overflow).
inline bool parse_integer(std::string_view token, std::int64_t& value) {
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  const auto [end, ec] = std::from_chars(token.data(), token.data() + token.size(), value);
  return ec == std::errc() && end == token.data() + token.size() && !token.empty();
}

/// Builds "source:line: what" errors.
struct Located {
  const std::string& source;
  const Lines& lines;

  [[noreturn]] void fail(const std::string& what) const {
    throw FileError(source, lines.line, what);
  }
  /// Quotes a token for an error message, cut short if long.
  static std::string quote(std::string_view token) {
    // Built by appends: GCC 12 gives a false -Wrestrict on chains of operator+ here.
    std::string quoted(1, '\'');
    quoted.append(token.substr(0, 40));
    quoted.append(token.size() > 40 ? "...'" : "'");
    return quoted;
  }
};

/// How many records to reserve for a count read from a header: never more than the bytes left
/// could hold at `min_bytes` per record, so an absurd count allocates nothing absurd.
inline std::size_t safe_reserve(std::uint64_t count, std::size_t remaining, std::size_t min_bytes) {
  return static_cast<std::size_t>(std::min<std::uint64_t>(count, remaining / min_bytes + 1));
}

}  // namespace petersen::text
