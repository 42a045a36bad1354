#pragma once
// A part's global vertex ids renumbered densely, so that its pairable graph is built over its own
// vertices only.

#include <span>

#include "petersen/mesh/mesh.hpp"

namespace petersen::partition_detail {

/// corners[i] renumbered: the part's distinct vertices get ids 0..vertex_count-1 in ascending
/// order of their global ids.
struct LocalCorners {
  std::pmr::vector<VertexId> corners;
  std::uint32_t vertex_count = 0;
};

/// Renumbers `corners`. Where the ids span at most four times the corner count (a part of a
/// mesh stored in scan order) a table over the span does it in O(c + span); otherwise the ids are
/// sorted, O(c log c). Throws MeshError naming the global face (first_face + i / 3) of a corner
/// equal to kNoFace's value, which no vertex id may take.
LocalCorners local_corners(std::span<const VertexId> corners, FaceId first_face);

}  // namespace petersen::partition_detail
