#pragma once
// Triangle and quad meshes as flat arrays of positions and corner indices.

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace petersen {

using VertexId = std::uint32_t;
using FaceId = std::uint32_t;

/// A triangle mesh: positions and, per triangle, three corner indices in counter-clockwise order
/// seen from outside. Edge k of triangle t joins corners k and (k+1)%3.
struct TriangleMesh {
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<VertexId, 3>> triangles;
};

/// A quad mesh over the same positions as the triangle mesh it came from.
struct QuadMesh {
  std::vector<std::array<double, 3>> positions;
  std::vector<std::array<VertexId, 4>> quads;
};

/// Raised for bad mesh input or a mesh that is not a closed surface; the message names the file
/// and line, or the element index.
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace petersen
