#pragma once
// Polygon meshes as flat arrays of positions and corner indices.

#include <array>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "petersen/graph/memory.hpp"
#include "petersen/mesh/mesh_attributes.hpp"

namespace petersen {

using VertexId = std::uint32_t;
using FaceId = std::uint32_t;
/// No face: a source that is no input face, a slot that names none.
inline constexpr FaceId kNoFace = 0xFFFFFFFFu;

/// Vertex positions; like every large array of the library, on the memory resource the caller
/// chose (petersen/graph/memory.hpp).
using Positions = std::pmr::vector<std::array<double, 3>>;

/// A mesh whose faces have any number of corners (three or more), as flat arrays: face f's
/// corners, in order, are corners[face_start[f]] up to corners[face_start[f + 1]]. While every
/// face is a triangle, face_start stays empty and face f is corners[3f], corners[3f + 1],
/// corners[3f + 2]: 4 bytes per face saved where it matters, on large all-triangle meshes.
/// add_face keeps that invariant; code that fills the arrays directly must keep it too.
/// Every array is on one memory resource, the one given at construction (the default resource
/// otherwise); a copy takes the default resource, a move keeps the source's.
struct PolygonMesh {
  PolygonMesh() = default;
  /// An empty mesh whose arrays allocate from `memory`.
  explicit PolygonMesh(std::pmr::memory_resource* memory)
      : positions(memory), corners(memory), face_start(memory), attributes(memory) {}

  Positions positions;
  std::pmr::vector<VertexId> corners;
  std::pmr::vector<std::uint32_t>
      face_start;  ///< empty (all triangles), or face_count() + 1 offsets
  /// Texture coordinates, normals, materials, groups and other properties, where the mesh has
  /// them (see MeshAttributes); add_face does not touch them.
  MeshAttributes attributes;

  bool all_triangles() const { return face_start.empty(); }
  std::size_t face_count() const {
    return all_triangles() ? corners.size() / 3 : face_start.size() - 1;
  }
  std::uint32_t arity(FaceId f) const {
    return all_triangles() ? 3 : face_start[f + 1] - face_start[f];
  }
  std::span<const VertexId> face(FaceId f) const {
    const std::size_t first = all_triangles() ? 3 * std::size_t{f} : face_start[f];
    return {corners.data() + first, arity(f)};
  }
  /// Appends a face (at least three corners; not checked here). Switches to explicit face starts
  /// at the first face that is not a triangle. Throws MeshError past 2^32 - 1 corners.
  void add_face(std::span<const VertexId> face_corners);
  /// The resource the arrays allocate from.
  std::pmr::memory_resource* memory() const { return corners.get_allocator().resource(); }
};

/// Throws MeshError naming the first attribute array whose size does not match the mesh (one
/// entry per corner, face or vertex) or whose index is out of range. O(corners + faces).
void check_attributes(const PolygonMesh& mesh);

/// Raised for bad mesh input or a mesh that is not a closed surface; the message names the file
/// and line, or the element index.
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace petersen
