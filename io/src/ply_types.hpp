#pragma once
// PLY's scalar types as a header spells them, with their sizes and ranges: the one table the
// reader and the writer share.

#include <cstddef>
#include <cstdint>
#include <string_view>
#include <utility>

#include "petersen/mesh/mesh_attributes.hpp"

namespace petersen::ply {

/// The type a header names ("uchar" or its alias "uint8", ...); false for any other name.
inline bool parse_type(std::string_view name, ScalarType& type) {
  static constexpr std::pair<std::string_view, ScalarType> names[] = {
      {"char", ScalarType::int8},      {"int8", ScalarType::int8},
      {"uchar", ScalarType::uint8},    {"uint8", ScalarType::uint8},
      {"short", ScalarType::int16},    {"int16", ScalarType::int16},
      {"ushort", ScalarType::uint16},  {"uint16", ScalarType::uint16},
      {"int", ScalarType::int32},      {"int32", ScalarType::int32},
      {"uint", ScalarType::uint32},    {"uint32", ScalarType::uint32},
      {"float", ScalarType::float32},  {"float32", ScalarType::float32},
      {"double", ScalarType::float64}, {"float64", ScalarType::float64},
  };
  for (const auto& [n, t] : names) {
    if (n == name) {
      type = t;
      return true;
    }
  }
  return false;
}

/// The name the writer gives the type: the original PLY spelling every reader knows.
inline const char* type_name(ScalarType type) {
  static constexpr const char* names[] = {"char", "uchar", "short", "ushort",
                                          "int",  "uint",  "float", "double"};
  return names[static_cast<int>(type)];
}

/// Bytes per value in a binary file.
inline std::size_t size_of(ScalarType type) {
  static constexpr std::size_t sizes[] = {1, 1, 2, 2, 4, 4, 4, 8};
  return sizes[static_cast<int>(type)];
}

inline bool is_integer(ScalarType type) {
  return type != ScalarType::float32 && type != ScalarType::float64;
}

/// Whether a whole number read from ascii fits the integer type; every number fits a float type.
inline bool fits(ScalarType type, std::int64_t value) {
  switch (type) {
    case ScalarType::int8:
      return value >= -128 && value <= 127;
    case ScalarType::uint8:
      return value >= 0 && value <= 255;
    case ScalarType::int16:
      return value >= -32768 && value <= 32767;
    case ScalarType::uint16:
      return value >= 0 && value <= 65535;
    case ScalarType::int32:
      return value >= -2147483648ll && value <= 2147483647ll;
    case ScalarType::uint32:
      return value >= 0 && value <= 4294967295ll;
    default:
      return true;
  }
}

}  // namespace petersen::ply
