#pragma once
// Triangle and quad meshes as flat arrays of positions and corner indices.

#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "petersen/graph/huge_pages.hpp"

namespace petersen {

using VertexId = std::uint32_t;
using FaceId = std::uint32_t;

/// Vertex positions; like every large array of the library, on huge pages once large
/// (petersen/graph/huge_pages.hpp), so that meshes, graphs and scratch arrays recycle one
/// another's memory.
using Positions = HugeVector<std::array<double, 3>>;

/// A triangle mesh: positions and, per triangle, three corner indices in counter-clockwise order
/// seen from outside. Edge k of triangle t joins corners k and (k+1)%3.
struct TriangleMesh {
  Positions positions;
  HugeVector<std::array<VertexId, 3>> triangles;
};

/// A quad mesh over the same positions as the triangle mesh it came from.
struct QuadMesh {
  Positions positions;
  HugeVector<std::array<VertexId, 4>> quads;
};

/// Raised for bad mesh input or a mesh that is not a closed surface; the message names the file
/// and line, or the element index.
struct MeshError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace petersen
