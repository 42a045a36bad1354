#pragma once
// A PLY file's header: its encoding, its elements and their properties, and what the reader
// does with each property's values (ply_header.cpp reads it; parse_ply.cpp decodes the records).

#include <cstdint>
#include <string>
#include <vector>

#include "petersen/mesh/mesh_attributes.hpp"
#include "text_scan.hpp"

namespace petersen::ply {

enum class Encoding { ascii, little, big };

/// What the reader does with each value of a property.
enum class Use : std::uint8_t {
  coordinate,  ///< a vertex's x, y or z (slot: the axis)
  column,      ///< a kept scalar (slot: its column among the element's properties in the mesh)
  skip,        ///< a scalar read past
  corners,     ///< the face's (or the tristrips record's) vertex_indices list
  texcoords,   ///< the face's MeshLab texcoord list, u v per corner
  skip_list,   ///< any other list, read past
};

struct Property {
  std::string name;
  ScalarType type = ScalarType::float32;  ///< the items' type for a list
  bool is_list = false;
  ScalarType count_type = ScalarType::uint8;
  Use use = Use::skip;
  int slot = -1;
};

/// The vertex and face (or tristrips) elements make the mesh; any other is read past.
enum class Role : std::uint8_t { vertex, face, strips, other };

struct Element {
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
  std::size_t line = 0;  ///< where the header declared it
  Role role = Role::other;
};

struct Header {
  Encoding encoding = Encoding::ascii;
  std::vector<Element> elements;  ///< in file order, the order of their records
  std::uint64_t vertex_count = 0;
  /// The columns of the properties whose use is Use::column, named and typed, without values.
  std::vector<PropertyColumn> vertex_columns, face_columns;
  /// float32 when a binary file declares x, y and z float, so that it is written back as float;
  /// float64 otherwise (it holds every type exactly; ascii positions keep their digits).
  ScalarType position_type = ScalarType::float64;
};

/// Reads the header, from the "ply" line to "end_header", leaving `lines` on the first record.
/// Throws FileError "source:line: what" for an empty file, a first line other than "ply", an
/// unknown keyword, format or type, a property before any element, no format line, no end_header,
/// a missing or repeated vertex element, no face or tristrips element (or both, or either twice),
/// more than 2^32 - 1 vertices or faces, a vertex element without scalar x, y, z or a face or
/// tristrips element without an integer vertex_indices list.
/// Appends to `dropped` one line per property or element read past. O(header).
Header read_header(text::Lines& lines, const std::string& source,
                   std::vector<std::string>& dropped);

}  // namespace petersen::ply
