#pragma once
// Where a PLY's record values come from: an ascii source (tokens of one line per record) or a
// binary one (bytes in the declared type and byte order). Both answer the same calls, so that one
// record decoder (parse_ply.cpp, a template over the source) serves every encoding; they differ
// in how a value is read and how an error is located: "source:line: what" in ascii, "source: what
// (byte N)" in binary. Every read is checked, so that truncation is always caught.

#include <bit>
#include <cmath>
#include <cstring>
#include <string>
#include <type_traits>

#include "ply_header.hpp"
#include "ply_types.hpp"

namespace petersen::ply {

/// "vertex 12": the record being read, for messages.
inline std::string record_name(const Element& element, std::uint64_t record) {
  return element.name + " " + std::to_string(record);
}

/// One record per line, blank lines between records skipped; values are tokens, whole numbers
/// for integer types and finite reals for float ones. A float property holds what a binary file
/// of the same header would (rounded to float); a coordinate keeps the digits written.
class AsciiSource {
 public:
  static constexpr bool kRecordPerLine = true;

  AsciiSource(text::Lines& lines, const std::string& source) : lines_(lines), at_{source, lines} {}

  void begin_record(const Element& element, std::uint64_t record) {
    element_ = &element;
    record_ = record;
    std::string_view line, token;
    do {
      if (!lines_.next(line)) {
        fail("truncated: expected " + std::to_string(element.count) + " " + element.name +
             " records, found " + std::to_string(record));
      }
      tokens_.rest = line;
    } while (!text::Tokens{line}.next(token));
  }

  double coordinate(const Property& property) { return scalar(property).real; }

  double column_value(const Property& property) {
    const Value value = scalar(property);
    if (is_integer(property.type) && !fits(property.type, value.whole)) {
      out_of_range(value.whole, property);
    }
    return property.type == ScalarType::float32 ? static_cast<float>(value.real) : value.real;
  }

  void skip(const Property& property) { scalar(property); }

  std::uint64_t list_length(const Property&) {
    const std::string_view token = next_token();
    std::int64_t items = 0;
    if (!text::parse_integer(token, items) || items < 0) bad("bad list length ", token, nullptr);
    return static_cast<std::uint64_t>(items);
  }

  std::int64_t list_index(const Property& property) { return item(property).whole; }

  double list_real(const Property& property) {
    const double value = item(property).real;
    return property.type == ScalarType::float32 ? static_cast<float>(value) : value;
  }

  void skip_list(const Property& property, std::uint64_t items) {
    for (std::uint64_t j = 0; j < items; ++j) item(property);
  }

  [[noreturn]] void fail(const std::string& what) const { at_.fail(what); }

 private:
  struct Value {
    double real = 0;
    std::int64_t whole = 0;  // for an integer type
  };

  static bool parse(std::string_view token, ScalarType type, Value& value) {
    if (!is_integer(type)) return text::parse_real(token, value.real);
    if (!text::parse_integer(token, value.whole)) return false;
    value.real = static_cast<double>(value.whole);
    return true;
  }

  Value scalar(const Property& property) {
    const std::string_view token = next_token();
    Value value;
    if (!parse(token, property.type, value)) bad("bad value ", token, &property);
    return value;
  }

  Value item(const Property& property) {
    const std::string_view token = next_token();
    Value value;
    if (!parse(token, property.type, value)) bad("bad list value ", token, nullptr);
    return value;
  }

  std::string_view next_token() {
    std::string_view token;
    if (!tokens_.next(token)) too_few_values();
    return token;
  }

  // The messages, out of line: the loop over tokens is the reader's hot path.
  [[noreturn, gnu::cold, gnu::noinline]] void bad(const char* what, std::string_view token,
                                                  const Property* property) const {
    std::string message = record() + ": " + what + text::Located::quote(token);
    if (property) message += " for property " + property->name;
    fail(message);
  }
  [[noreturn, gnu::cold, gnu::noinline]] void out_of_range(std::int64_t whole,
                                                           const Property& property) const {
    fail(record() + ": value " + std::to_string(whole) + " out of range for the type of property " +
         property.name);
  }
  [[noreturn, gnu::cold, gnu::noinline]] void too_few_values() const {
    fail(record() + ": too few values");
  }

  std::string record() const { return record_name(*element_, record_); }

  text::Lines& lines_;
  text::Located at_;
  text::Tokens tokens_;
  const Element* element_ = nullptr;
  std::uint64_t record_ = 0;
};

/// Values in their declared type, byte-swapped when kSwap (the file's byte order is not the
/// host's). Every read is bounds-checked: a scalar by need(), a list's items all at once by
/// list_length().
template <bool kSwap>
class BinarySource {
 public:
  static constexpr bool kRecordPerLine = false;

  BinarySource(std::string_view bytes, std::size_t pos, const std::string& source)
      : bytes_(bytes), pos_(pos), source_(source) {}

  void begin_record(const Element& element, std::uint64_t record) {
    element_ = &element;
    record_ = record;
  }

  double coordinate(const Property& property) {
    need(size_of(property.type));
    const double value = real(property.type);
    if (!std::isfinite(value)) fail(record() + ": non-finite " + property.name);
    return value;
  }

  // Kept as read, NaN included: a property is not a coordinate.
  double column_value(const Property& property) {
    need(size_of(property.type));
    return real(property.type);
  }

  void skip(const Property& property) {
    need(size_of(property.type));
    pos_ += size_of(property.type);
  }

  std::uint64_t list_length(const Property& property) {
    need(size_of(property.count_type));
    const std::int64_t items = integer(property.count_type);
    if (items < 0) fail(record() + ": negative list length");
    // Compared by division: items * size may not fit in 64 bits.
    if (static_cast<std::uint64_t>(items) > (bytes_.size() - pos_) / size_of(property.type)) {
      fail("truncated in " + record() + " of " + std::to_string(element_->count) +
           ": its list of " + std::to_string(items) + " values runs past the end");
    }
    return static_cast<std::uint64_t>(items);
  }

  // The list's items are there: list_length checked.
  std::int64_t list_index(const Property& property) { return integer(property.type); }
  double list_real(const Property& property) { return real(property.type); }
  void skip_list(const Property& property, std::uint64_t items) {
    pos_ += static_cast<std::size_t>(items) * size_of(property.type);
  }

  /// Fails unless `n` more bytes are there.
  void need(std::size_t n) {
    if (bytes_.size() - pos_ < n) truncated();
  }

  [[noreturn]] void fail(const std::string& what) const {
    throw FileError(source_, 0, what + " (byte " + std::to_string(pos_) + ")");
  }

  /// The bytes and the position, for the fixed layouts parse_ply.cpp reads by whole records.
  std::string_view bytes() const { return bytes_; }
  std::size_t& pos() { return pos_; }

 private:
  [[noreturn, gnu::cold, gnu::noinline]] void truncated() const {
    fail("truncated in " + record() + " of " + std::to_string(element_->count));
  }

  std::string record() const { return record_name(*element_, record_); }

  template <typename T>
  T load() {
    using Raw = std::conditional_t<
        sizeof(T) == 1, std::uint8_t,
        std::conditional_t<sizeof(T) == 2, std::uint16_t,
                           std::conditional_t<sizeof(T) == 4, std::uint32_t, std::uint64_t>>>;
    Raw raw;
    std::memcpy(&raw, bytes_.data() + pos_, sizeof(T));
    if constexpr (kSwap && sizeof(T) > 1) raw = byteswap(raw);
    pos_ += sizeof(T);
    return std::bit_cast<T>(raw);
  }

  template <typename U>
  static U byteswap(U raw) {
    U out = 0;
    for (std::size_t i = 0; i < sizeof(U); ++i) out = U((out << 8) | ((raw >> (8 * i)) & 0xFF));
    return out;
  }

  double real(ScalarType type) {
    switch (type) {
      case ScalarType::float32:
        return load<float>();
      case ScalarType::float64:
        return load<double>();
      default:
        return static_cast<double>(integer(type));
    }
  }

  std::int64_t integer(ScalarType type) {
    switch (type) {
      case ScalarType::int8:
        return load<std::int8_t>();
      case ScalarType::uint8:
        return load<std::uint8_t>();
      case ScalarType::int16:
        return load<std::int16_t>();
      case ScalarType::uint16:
        return load<std::uint16_t>();
      case ScalarType::int32:
        return load<std::int32_t>();
      case ScalarType::uint32:
        return load<std::uint32_t>();
      default:
        return 0;  // float types are refused for counts and indices in the header
    }
  }

  std::string_view bytes_;
  std::size_t pos_;
  const std::string& source_;
  const Element* element_ = nullptr;
  std::uint64_t record_ = 0;
};

}  // namespace petersen::ply
