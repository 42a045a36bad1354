#pragma once
// What a mesh carries besides positions and faces: texture coordinates and normals per corner,
// materials, groups, objects and smoothing groups per face, and any other scalar property per
// vertex or face (PLY properties, OFF colours). Readers fill it, writers write it back, and the
// front door carries it from the triangles to the quads made of them.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "petersen/graph/memory.hpp"

namespace petersen {

/// The index of a corner or face that has no value of an attribute the mesh has elsewhere (an OBJ
/// corner written without /vt in a file whose other corners have one; a face before the first
/// usemtl).
inline constexpr std::uint32_t kNoAttribute = 0xFFFFFFFFu;

/// A PLY scalar type; a property read from a file is written back with the type it had.
enum class ScalarType : std::uint8_t {
  int8,
  uint8,
  int16,
  uint16,
  int32,
  uint32,
  float32,
  float64
};

/// One scalar property of every vertex or of every face, in element order. Doubles hold every
/// PLY scalar type exactly, so one column type serves them all.
struct PropertyColumn {
  std::string name;
  ScalarType type = ScalarType::float32;
  std::pmr::vector<double> values;
};

/// Every array is empty when the mesh has none of that attribute; otherwise it has one entry per
/// corner (parallel to PolygonMesh::corners), per face or per vertex, as its name says.
/// check_attributes enforces that.
struct MeshAttributes {
  MeshAttributes() = default;
  /// No attributes, the arrays to come allocating from `memory`.
  explicit MeshAttributes(std::pmr::memory_resource* memory)
      : texcoords(memory),
        normals(memory),
        corner_texcoord(memory),
        corner_normal(memory),
        face_material(memory),
        face_group(memory),
        face_object(memory),
        face_smoothing(memory) {}

  /// OBJ `vt` and `vn`, in file order; corners refer to them by index.
  std::pmr::vector<std::array<double, 3>> texcoords;
  std::uint8_t texcoord_components = 2;  ///< 2 (u v) or 3 (u v w): the most any `vt` line had
  std::pmr::vector<std::array<double, 3>> normals;
  std::pmr::vector<std::uint32_t>
      corner_texcoord;  ///< per corner: index into texcoords, or kNoAttribute
  std::pmr::vector<std::uint32_t>
      corner_normal;  ///< per corner: index into normals, or kNoAttribute

  /// Per face, an index into the names (OBJ `usemtl`, `g`, `o`; a `g` line's whole argument is one
  /// name), or kNoAttribute for faces before the first such line.
  std::vector<std::string> material_names, group_names, object_names;
  std::pmr::vector<std::uint32_t> face_material, face_group, face_object;
  /// Per face, OBJ's smoothing group: 0 for `s off` or `s 0` (and before any `s` line).
  std::pmr::vector<std::uint32_t> face_smoothing;
  /// OBJ `mtllib` arguments, in order; written back at the top of an OBJ.
  std::vector<std::string> material_libraries;

  /// PLY vertex properties other than x, y, z (colours, normals, texture coordinates, anything
  /// scalar), and OFF vertex colours as red, green, blue[, alpha].
  std::vector<PropertyColumn> vertex_properties;
  /// PLY face scalar properties (the corner list is the face itself), and OFF face colours.
  std::vector<PropertyColumn> face_properties;
  /// The type a PLY declared for x, y and z, so that a float PLY is written back as float; other
  /// formats have no type and leave float64. Not an attribute: empty() ignores it.
  ScalarType position_type = ScalarType::float64;

  bool has_corner_attributes() const { return !corner_texcoord.empty() || !corner_normal.empty(); }
  bool has_face_attributes() const {
    return !face_material.empty() || !face_group.empty() || !face_object.empty() ||
           !face_smoothing.empty() || !face_properties.empty();
  }
  bool empty() const {
    return !has_corner_attributes() && !has_face_attributes() && vertex_properties.empty() &&
           material_libraries.empty();
  }
};

}  // namespace petersen
