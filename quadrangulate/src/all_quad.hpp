#pragma once
// --all-quad: the triangles a maximum pairing leaves, turned into quads by splitting edges.

#include <cstdint>
#include <vector>

#include "petersen/quadrangulate/quadrangulate.hpp"

namespace petersen::quad_detail {

/// What each output face of a QuadResult is, for the splits.
enum class FaceKind : std::uint8_t { kept, left, pair };

/// Joins every left triangle of `result` to another left triangle, or to a boundary edge, by a
/// shortest path of pair quads across edges of exactly two faces, and splits along it: each edge
/// crossed gets a midpoint, a left triangle with one midpoint is a quad, and a crossed quad
/// becomes two quads (the path goes straight through) or three around a new centre vertex (it
/// turns). Updates the mesh, the sources and the stats (added_vertices, split_quads,
/// triangles_left stays the pairing's). Throws MeshError naming the face when a left triangle
/// repeats a vertex or has nothing to reach. O(k·r) for k left triangles, r the region a search
/// explores.
void split_leftovers(QuadResult& result, const std::vector<FaceKind>& kinds);

}  // namespace petersen::quad_detail
